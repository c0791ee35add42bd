// bufferViews and accessors: every byte range checked against the buffer it indexes with
// overflow-safe arithmetic, then read as floats (dense and sparse) or as triangle indices.
#include "gltf_import.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace hv::gltf {
namespace {

// Component `c` of element `i` as a float: normalized integers mapped to [0, 1] or [-1, 1] by
// the glTF 2.0 spec's conversions (e.g. max(c / 127, -1) for BYTE), plain integers converted.
float component(const ElementRange& r, size_t i, int c) {
  const unsigned char* q = r.base + i * r.stride +
                           size_t(c) * size_t(tinygltf::GetComponentSizeInBytes(uint32_t(r.ctype)));
  const bool n = r.normalized;
  switch (r.ctype) {
    case TINYGLTF_COMPONENT_TYPE_FLOAT: {
      float f;
      std::memcpy(&f, q, 4);
      return f;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return n ? *q / 255.0f : *q;
    case TINYGLTF_COMPONENT_TYPE_BYTE: {
      const int8_t x = int8_t(*q);
      return n ? std::max(x / 127.0f, -1.0f) : x;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
      uint16_t x;
      std::memcpy(&x, q, 2);
      return n ? x / 65535.0f : x;
    }
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
      int16_t x;
      std::memcpy(&x, q, 2);
      return n ? std::max(x / 32767.0f, -1.0f) : x;
    }
    default: {  // UNSIGNED_INT (elements() rejects the rest)
      uint32_t x;
      std::memcpy(&x, q, 4);
      return float(x);
    }
  }
}

// Element `i` of an unsigned integer range (indices).
uint32_t unsignedComponent(const ElementRange& r, size_t i) {
  const unsigned char* q = r.base + i * r.stride;
  switch (r.ctype) {
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return *q;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
      uint16_t x;
      std::memcpy(&x, q, 2);
      return x;
    }
    default: {
      uint32_t x;
      std::memcpy(&x, q, 4);
      return x;
    }
  }
}

}  // namespace

// The bytes of bufferView `view_index`, checked against its buffer; `ref` names the reference.
std::pair<const uint8_t*, size_t> Importer::viewBytes(int view_index,
                                                      const std::string& ref) const {
  if (view_index < 0 || size_t(view_index) >= m_.bufferViews.size()) {
    fail(ref, "bufferView index " + std::to_string(view_index) + " out of range (" +
                  std::to_string(m_.bufferViews.size()) + " bufferViews)");
  }
  const tinygltf::BufferView& v = m_.bufferViews[size_t(view_index)];
  const std::string vel = idx("bufferViews", size_t(view_index));
  if (v.buffer < 0 || size_t(v.buffer) >= m_.buffers.size()) {
    fail(vel + ".buffer", "index " + std::to_string(v.buffer) + " out of range");
  }
  const std::vector<unsigned char>& data = m_.buffers[size_t(v.buffer)].data;
  if (!fitsIn(v.byteOffset, v.byteLength, data.size())) {
    fail(vel + (v.byteOffset > data.size() ? ".byteOffset" : ".byteLength"),
         "byteOffset " + std::to_string(v.byteOffset) + " + byteLength " +
             std::to_string(v.byteLength) + " exceeds " + idx("buffers", size_t(v.buffer)) +
             " size " + std::to_string(data.size()));
  }
  return {data.data() + v.byteOffset, v.byteLength};
}

// `count` elements of `comps` x `ctype` at `byte_offset` in bufferView `view_index`, each
// checked to lie inside the view (overflow-safe). `el` is the accessor, for messages.
ElementRange Importer::elements(int view_index, uint64_t byte_offset, uint64_t count, int comps,
                                int ctype, bool normalized, const std::string& el) const {
  const auto [bytes, size] = viewBytes(view_index, el + ".bufferView");
  const std::string vel = idx("bufferViews", size_t(view_index));
  const int csize = tinygltf::GetComponentSizeInBytes(uint32_t(ctype));
  if (csize <= 0 || ctype == TINYGLTF_COMPONENT_TYPE_DOUBLE ||
      ctype == TINYGLTF_COMPONENT_TYPE_INT) {
    fail(el + ".componentType", "unsupported value " + std::to_string(ctype));
  }
  const size_t elem = size_t(csize) * size_t(comps);
  const size_t declared = m_.bufferViews[size_t(view_index)].byteStride;
  const size_t stride = declared ? declared : elem;
  if (stride < elem) {
    fail(vel + ".byteStride", std::to_string(stride) + " is smaller than the element size " +
                                  std::to_string(elem) + " of " + el);
  }
  if (byte_offset > size) {
    fail(el + ".byteOffset",
         std::to_string(byte_offset) + " exceeds " + vel + ".byteLength " + std::to_string(size));
  }
  const uint64_t avail = size - byte_offset;
  if (count == 0) fail(el + ".count", "must be at least 1");
  if (elem > avail || count - 1 > (avail - elem) / stride) {
    fail(el + ".count", std::to_string(count) + " elements of " + std::to_string(elem) +
                            " bytes at stride " + std::to_string(stride) + " from byteOffset " +
                            std::to_string(byte_offset) + " exceed " + vel + ".byteLength " +
                            std::to_string(size));
  }
  return {bytes + byte_offset, size_t(count), stride, comps, ctype, normalized};
}

const tinygltf::Accessor& Importer::accessor(int index, const std::string& ref) const {
  if (index < 0 || size_t(index) >= m_.accessors.size()) {
    fail(ref, "accessor index " + std::to_string(index) + " out of range (" +
                  std::to_string(m_.accessors.size()) + " accessors)");
  }
  return m_.accessors[size_t(index)];
}

void Importer::checkCount(uint64_t count, uint64_t budget, const std::string& el,
                          const char* limit) const {
  if (count > budget) {
    fail(el + ".count", std::to_string(count) + " exceeds the budget of " + std::to_string(budget) +
                            " (GltfLimits::" + limit + ")");
  }
}

// Reads accessor `index` (referenced as `ref`) as count x comps floats (normalized integers
// mapped to [0,1] or [-1,1], plain integers converted), after checking type, every byte range
// and that each value is finite.
std::vector<float> Importer::readFloats(int index, const std::string& ref,
                                        std::initializer_list<int> types,
                                        std::initializer_list<int> ctypes,
                                        bool require_normalized_ints) {
  const tinygltf::Accessor& a = accessor(index, ref);
  const std::string el = idx("accessors", size_t(index));
  const std::string use = " (" + ref + ")";
  if (std::find(types.begin(), types.end(), a.type) == types.end()) {
    fail(el + ".type", "unexpected type for" + use);
  }
  if (std::find(ctypes.begin(), ctypes.end(), a.componentType) == ctypes.end()) {
    fail(el + ".componentType", "unsupported value " + std::to_string(a.componentType) + use);
  }
  const bool is_float = a.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT;
  if (!is_float && require_normalized_ints && !a.normalized) {
    fail(el + ".normalized", "integer components must be normalized for" + use);
  }
  checkCount(a.count, lim_.max_vertices, el, "max_vertices");
  const int comps = tinygltf::GetNumComponentsInType(uint32_t(a.type));
  if (a.count == 0) fail(el + ".count", "must be at least 1");
  std::vector<float> out(a.count * size_t(comps), 0.0f);
  if (a.bufferView >= 0) {
    const ElementRange r =
        elements(a.bufferView, a.byteOffset, a.count, comps, a.componentType, a.normalized, el);
    for (size_t i = 0; i < r.count; ++i)
      for (int c = 0; c < comps; ++c) out[i * size_t(comps) + size_t(c)] = component(r, i, c);
  }
  if (a.sparse.isSparse) readSparse(a, comps, el, out);
  for (float f : out)
    if (!std::isfinite(f)) fail(el, "non-finite value" + use);
  return out;
}

// The sparse substitution of accessor `a` (`el`, `comps` components) applied to `out`.
void Importer::readSparse(const tinygltf::Accessor& a, int comps, const std::string& el,
                          std::vector<float>& out) const {
  const std::string sel = el + ".sparse";
  if (a.sparse.count < 1 || uint64_t(a.sparse.count) > a.count) {
    fail(sel + ".count",
         std::to_string(a.sparse.count) + " is not in [1, " + std::to_string(a.count) + "]");
  }
  const int ict = a.sparse.indices.componentType;
  if (ict != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
      ict != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
      ict != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT) {
    fail(sel + ".indices.componentType", "unsupported value " + std::to_string(ict));
  }
  if (a.sparse.indices.byteOffset < 0) fail(sel + ".indices.byteOffset", "negative");
  if (a.sparse.values.byteOffset < 0) fail(sel + ".values.byteOffset", "negative");
  const size_t n = size_t(a.sparse.count);
  const ElementRange ri =
      elements(a.sparse.indices.bufferView, uint64_t(a.sparse.indices.byteOffset), n, 1, ict, false,
               sel + ".indices");
  const ElementRange rv = elements(a.sparse.values.bufferView, uint64_t(a.sparse.values.byteOffset),
                                   n, comps, a.componentType, a.normalized, sel + ".values");
  for (size_t i = 0; i < n; ++i) {
    const uint32_t k = unsignedComponent(ri, i);
    if (k >= a.count) {
      fail(sel + ".indices", "index " + std::to_string(i) + " = " + std::to_string(k) +
                                 " >= count " + std::to_string(a.count));
    }
    for (int c = 0; c < comps; ++c)
      out[size_t(k) * size_t(comps) + size_t(c)] = component(rv, i, c);
  }
}

std::vector<uint32_t> Importer::readIndices(int index, size_t vertex_count,
                                            const std::string& ref) {
  const tinygltf::Accessor& a = accessor(index, ref);
  const std::string el = idx("accessors", size_t(index));
  const std::string use = " (" + ref + ")";
  if (a.type != TINYGLTF_TYPE_SCALAR) fail(el + ".type", "expected SCALAR" + use);
  uint32_t restart = 0;
  switch (a.componentType) {
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      restart = 0xFFu;
      break;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      restart = 0xFFFFu;
      break;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
      restart = 0xFFFFFFFFu;
      break;
    default:
      fail(el + ".componentType", std::to_string(a.componentType) +
                                      " is not UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT" +
                                      use);
  }
  if (a.normalized) fail(el + ".normalized", "indices must not be normalized" + use);
  if (a.bufferView < 0) fail(el + ".bufferView", "indices need a bufferView" + use);
  if (a.sparse.isSparse) fail(el + ".sparse", "sparse indices are not supported" + use);
  checkCount(a.count, 3 * lim_.max_triangles + 2, el, "max_triangles");
  const ElementRange r =
      elements(a.bufferView, a.byteOffset, a.count, 1, a.componentType, false, el);
  std::vector<uint32_t> out(r.count);
  for (size_t i = 0; i < r.count; ++i) {
    const uint32_t x = unsignedComponent(r, i);
    if (x == restart) {
      fail(el, "index " + std::to_string(i) + " is the primitive-restart value " +
                   std::to_string(restart) + ", which glTF forbids" + use);
    }
    if (x >= vertex_count) {
      fail(el, "index " + std::to_string(i) + " = " + std::to_string(x) + " >= vertex count " +
                   std::to_string(vertex_count) + use);
    }
    out[i] = x;
  }
  return out;
}

}  // namespace hv::gltf
