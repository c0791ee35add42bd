// glTF import on top of tinygltf (Debian libtinygltf-dev). tinygltf parses JSON, loads buffers
// and decodes images (stb_image from Debian's libstb); everything else (accessor bounds, index
// validation, primitive conversion, materials) is checked and done here.
#define TINYGLTF_IMPLEMENTATION
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_INCLUDE_JSON  // nlohmann/json is already included below, outside the
                                  // hidden-visibility pragma tinygltf wraps around it
#include <nlohmann/json.hpp>
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-parameter"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#include <tiny_gltf.h>
#pragma GCC diagnostic pop

#include "halfvec/scene/gltf_loader.hpp"

#include "halfvec/core/input_file.hpp"
#include "halfvec/core/png_bound.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <set>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "tangents.hpp"

namespace hv {
namespace {

namespace fs = std::filesystem;

// offset + length <= size, without overflow.
bool fitsIn(uint64_t offset, uint64_t length, uint64_t size) {
  return offset <= size && length <= size - offset;
}

std::string idx(const char* array, size_t i) {
  return std::string(array) + "[" + std::to_string(i) + "]";
}

// Scene coordinates and sizes (metres) stay within +-1e6, as in scene files (kBig there).
constexpr float kMaxWorldExtent = 1e6f;

std::string fmtFloat(float x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", double(x));
  return buf;
}

bool allFinite(const glm::mat3& m) {
  for (int c = 0; c < 3; ++c) {
    for (int r = 0; r < 3; ++r) {
      if (!std::isfinite(m[c][r])) return false;
    }
  }
  return true;
}

// ---- checks on the raw bytes, before tinygltf parses them -------------------------------------

struct GlbChunks {
  const uint8_t* json = nullptr;
  size_t json_size = 0;
};

uint32_t le32(const uint8_t* p) {
  return uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16 | uint32_t(p[3]) << 24;
}

// The GLB container (glTF 2.0 spec, 4.4 "Binary glTF Layout"): a 12-byte header whose length is
// the file size, a JSON chunk, an optional BIN chunk, each chunk inside the file and 4-byte
// aligned. tinygltf 2.7 lets a BIN chunk end up to 8 bytes past the data it was given; checked
// here so it never sees such a file.
GlbChunks checkGlb(const std::string& name, const uint8_t* b, size_t size) {
  auto fail = [&](const std::string& element, const std::string& msg) {
    throw SceneError(name + ": GLB " + element + ": " + msg);
  };
  if (size < 20) fail("header", "file too short (" + std::to_string(size) + " bytes)");
  if (std::memcmp(b, "glTF", 4) != 0) fail("header", "bad magic (not a binary glTF file)");
  if (le32(b + 4) != 2) fail("header.version", "expected 2, got " + std::to_string(le32(b + 4)));
  if (le32(b + 8) != size) {
    fail("header.length",
         std::to_string(le32(b + 8)) + " differs from the file size " + std::to_string(size));
  }
  GlbChunks out;
  size_t at = 12;
  for (int chunk = 0; at < size; ++chunk) {
    const std::string el = "chunks[" + std::to_string(chunk) + "]";
    if (size - at < 8) fail(el, "truncated chunk header");
    const uint32_t length = le32(b + at), type = le32(b + at + 4);
    if (!fitsIn(at + 8, length, size)) {
      fail(el + ".chunkLength", std::to_string(length) + " bytes at offset " +
                                    std::to_string(at + 8) + " exceed the file size " +
                                    std::to_string(size));
    }
    if (length % 4 != 0) fail(el + ".chunkLength", "not a multiple of 4");
    if (chunk == 0) {
      if (type != 0x4E4F534Au) fail(el + ".chunkType", "the first chunk must be JSON");
      if (length == 0) fail(el + ".chunkLength", "empty JSON chunk");
      out.json = b + at + 8;
      out.json_size = length;
    } else if (chunk == 1) {
      if (type != 0x004E4942u) fail(el + ".chunkType", "the second chunk must be BIN");
      if (length == 0) fail(el + ".chunkLength", "empty BIN chunk");
    }
    at += 8 + size_t(length);
  }
  return out;
}

// tinygltf converts "extras" and "extensions" recursively: JSON nesting is bounded before it
// parses anything (strings and escapes skipped).
void checkJsonDepth(const std::string& name, const uint8_t* text, size_t size, int max_depth) {
  const size_t at =
      jsonNestingBeyond(std::string_view(reinterpret_cast<const char*>(text), size), max_depth);
  if (at != std::string_view::npos) {
    throw SceneError(name + ": JSON nesting deeper than " + std::to_string(max_depth) +
                     " levels at byte " + std::to_string(at) + " (GltfLimits::max_json_depth)");
  }
}

// tinygltf 2.7 decodes an image stored in a bufferView without checking the view against its
// buffer: that range is checked here on the JSON (a buffer's data always has its declared
// byteLength once tinygltf has loaded it, or loading fails).
void checkImageViews(const std::string& name, const uint8_t* text, size_t size) {
  const std::string_view view(reinterpret_cast<const char*>(text), size);
  if (view.find("\"images\"") == std::string_view::npos) return;  // no second parse needed
  const nlohmann::json j = nlohmann::json::parse(text, text + size, nullptr, false);
  if (j.is_discarded() || !j.is_object() || !j.contains("images")) return;  // tinygltf reports
  auto fail = [&](const std::string& element, const std::string& msg) {
    throw SceneError(name + ": " + element + ": " + msg);
  };
  auto array = [&](const char* key) -> const nlohmann::json* {
    const auto it = j.find(key);
    return it != j.end() && it->is_array() ? &*it : nullptr;
  };
  auto unsignedAt = [&](const nlohmann::json& o, const char* key, uint64_t def,
                        const std::string& el) -> uint64_t {
    if (!o.is_object() || !o.contains(key)) return def;
    const nlohmann::json& v = o[key];
    if (!v.is_number_unsigned()) fail(el + "." + key, "expected an unsigned integer");
    return v.get<uint64_t>();
  };
  const nlohmann::json* images = array("images");
  if (!images) return;
  const nlohmann::json *views = array("bufferViews"), *buffers = array("buffers");
  for (size_t i = 0; i < images->size(); ++i) {
    const nlohmann::json& im = (*images)[i];
    if (!im.is_object() || !im.contains("bufferView")) continue;
    const std::string el = idx("images", i);
    const uint64_t vi = unsignedAt(im, "bufferView", 0, el);
    if (!views || vi >= views->size()) fail(el + ".bufferView", "index out of range");
    const nlohmann::json& v = (*views)[size_t(vi)];
    const std::string vel = idx("bufferViews", size_t(vi));
    const uint64_t bi = unsignedAt(v, "buffer", uint64_t(-1), vel);
    if (!buffers || bi >= buffers->size()) fail(vel + ".buffer", "index out of range");
    const std::string bel = idx("buffers", size_t(bi));
    const uint64_t buffer_len = unsignedAt((*buffers)[size_t(bi)], "byteLength", 0, bel);
    const uint64_t off = unsignedAt(v, "byteOffset", 0, vel);
    const uint64_t len = unsignedAt(v, "byteLength", 0, vel);
    if (!fitsIn(off, len, buffer_len)) {
      fail(vel + ".byteLength", "byteOffset " + std::to_string(off) + " + byteLength " +
                                    std::to_string(len) + " exceeds " + bel + ".byteLength " +
                                    std::to_string(buffer_len));
    }
    if (len == 0 || len > uint64_t(std::numeric_limits<int>::max())) {
      fail(vel + ".byteLength", "image data of " + std::to_string(len) + " bytes");
    }
  }
}

// ---- file access and image decoding, as tinygltf callbacks ------------------------------------

struct LoadContext {
  const GltfLimits* limits = nullptr;
  bool decode_images = true;
  uint64_t image_pixels = 0;  // decoded so far
};

bool fileExists(const std::string& path, void*) {
  std::error_code ec;
  return fs::is_regular_file(path, ec);
}

std::string expandNothing(const std::string& path, void*) {
  return path;  // glTF URIs are plain relative paths: no ~ or variables
}

bool readWholeFile(std::vector<unsigned char>* out, std::string* err, const std::string& path,
                   void* user) {
  const auto* ctx = static_cast<const LoadContext*>(user);
  // A buffer or image URI may name a FIFO, a device or a directory: the same checks as the file.
  try {
    const std::string bytes =
        readInputFile(path, ctx->limits->max_file_bytes, "GltfLimits::max_file_bytes");
    out->assign(bytes.begin(), bytes.end());
  } catch (const InputError& e) {
    *err += e.reason;  // tinygltf names the file itself
    return false;
  }
  return true;
}

bool writeNothing(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
  *err += "writing is not supported";
  return false;
}

// Decodes every image to 8-bit RGBA after checking its dimensions (from the header only) against
// the budget, so a small compressed file cannot decode into gigabytes.
bool decodeImage(tinygltf::Image* image, const int index, std::string* err, std::string*, int, int,
                 const unsigned char* bytes, int size, void* user) {
  auto* ctx = static_cast<LoadContext*>(user);
  const GltfLimits& lim = *ctx->limits;
  const std::string el = idx("images", size_t(index));
  if (!ctx->decode_images) return true;  // material_override: images are not imported
  int w = 0, h = 0, comp = 0;
  if (size <= 0 || !stbi_info_from_memory(bytes, size, &w, &h, &comp)) {
    const char* why = stbi_failure_reason();
    *err += el + ": unknown or corrupt image data (" + (why ? why : "unknown") + ")";
    return false;
  }
  if (w <= 0 || h <= 0 || w > lim.max_image_side || h > lim.max_image_side) {
    *err += el + ": " + std::to_string(w) + "x" + std::to_string(h) + " exceeds the limit of " +
            std::to_string(lim.max_image_side) + " per side (GltfLimits::max_image_side)";
    return false;
  }
  ctx->image_pixels += uint64_t(w) * uint64_t(h);
  if (ctx->image_pixels > lim.max_image_pixels) {
    *err += el + ": the file's images exceed the budget of " +
            std::to_string(lim.max_image_pixels) + " pixels (GltfLimits::max_image_pixels)";
    return false;
  }
  // A PNG's compressed data must be able to inflate to its declared pixels before stb_image
  // allocates them (halfvec/core/png_bound.hpp).
  if (const std::string why = pngDataShortfall(bytes, size_t(size)); !why.empty()) {
    *err += el + ": " + why;
    return false;
  }
  int dw = 0, dh = 0;
  stbi_uc* data = stbi_load_from_memory(bytes, size, &dw, &dh, &comp, 4);
  if (!data || dw != w || dh != h) {
    if (data) stbi_image_free(data);
    const char* why = stbi_failure_reason();
    *err += el + ": image data cannot be decoded (" + (why ? why : "unknown") + ")";
    return false;
  }
  image->width = w;
  image->height = h;
  image->component = 4;
  image->bits = 8;
  image->pixel_type = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
  image->image.assign(data, data + size_t(w) * size_t(h) * 4);
  stbi_image_free(data);
  return true;
}

// ---- the import, on tinygltf's model -----------------------------------------------------------

// An accessor's elements, checked against the buffer: `count` elements of `comps` components of
// type `ctype`, element i at base + i * stride.
struct ElementRange {
  const uint8_t* base = nullptr;
  size_t count = 0, stride = 0;
  int comps = 1, ctype = 0;
  bool normalized = false;
};

class Importer {
 public:
  Importer(std::string path, tinygltf::Model& model, const Scene& scene, const GltfOptions& opt)
      : path_(std::move(path)), m_(model), opt_(opt), lim_(opt.limits) {
    image_base_ = int(scene.images.size());
    material_base_ = int(scene.materials.size());
    mesh_base_ = int(scene.meshes.size());
  }

  [[noreturn]] void fail(const std::string& element, const std::string& msg) const {
    throw SceneError(path_ + ": " + element + ": " + msg);
  }
  void warn(const std::string& msg) const { sceneWarning(path_ + ": " + msg, opt_.warnings); }

  void run(const glm::mat4& transform) {
    for (size_t i = 0; i < m_.extensionsRequired.size(); ++i) {
      const std::string& ext = m_.extensionsRequired[i];
      if (!honoured(ext)) {
        fail(idx("extensionsRequired", i), "the required extension " + ext +
                                               " is not supported (supported: " + honouredList() +
                                               ")");
      }
    }
    for (size_t i = 0; i < m_.extensionsUsed.size(); ++i) {
      noteExtension(m_.extensionsUsed[i], idx("extensionsUsed", i));
    }
    checkUnsupportedStructure();
    if (opt_.material_override < 0) {
      for (size_t i = 0; i < m_.images.size(); ++i) importImage(int(i));
      for (size_t i = 0; i < m_.materials.size(); ++i) importMaterial(int(i));
    }
    mesh_map_.assign(m_.meshes.size(), {});
    mesh_triangles_.assign(m_.meshes.size(), 0);
    // Every mesh is validated even if no node uses it.
    for (size_t i = 0; i < m_.meshes.size(); ++i) importMesh(int(i));
    std::vector<int> roots;
    std::string roots_el;
    if (!m_.scenes.empty()) {
      const int s = m_.defaultScene >= 0 ? m_.defaultScene : 0;
      if (s >= int(m_.scenes.size())) fail("scene", "index " + std::to_string(s) + " out of range");
      roots = m_.scenes[size_t(s)].nodes;
      roots_el = idx("scenes", size_t(s)) + ".nodes";
    } else {  // no scenes: every node that is nobody's child is a root
      std::vector<bool> child(m_.nodes.size(), false);
      for (const auto& n : m_.nodes)
        for (int c : n.children)
          if (c >= 0 && c < int(child.size())) child[size_t(c)] = true;
      for (size_t i = 0; i < m_.nodes.size(); ++i)
        if (!child[i]) roots.push_back(int(i));
      roots_el = "nodes";
    }
    checkExpansion(roots);
    for (int r : roots) visit(r, transform, roots_el);
  }

  // Extensions the importer reads. KHR_materials_pbrSpecularGlossiness is approximated (with a
  // warning of its own), the others are honoured in full.
  static bool honoured(const std::string& ext) {
    for (const char* h : kHonouredExtensions)
      if (ext == h) return true;
    return false;
  }
  static std::string honouredList() {
    std::string t;
    for (const char* h : kHonouredExtensions) {
      if (!t.empty()) t += ", ";
      t += h;
    }
    return t;
  }

  std::vector<ImageData> images;
  std::vector<Material> materials;
  std::vector<Mesh> meshes;
  std::vector<Object> objects;
  std::vector<GltfCamera> cameras;

 private:
  static constexpr const char* kHonouredExtensions[] = {
      "KHR_materials_emissive_strength", "KHR_materials_pbrSpecularGlossiness",
      "KHR_mesh_quantization", "KHR_texture_transform"};

  // ---- what is not imported: one warning per extension, attribute or feature -----------------
  // An extension the importer does not read, used at `el`: one warning per name per file, where
  // it is first seen (extensionsUsed, or the object of a file that forgot to declare it).
  void noteExtension(const std::string& ext, const std::string& el) {
    if (honoured(ext) || !warned_.insert("extension " + ext).second) return;
    warn(el + ": extension " + ext + " is not supported; ignored (the model renders without it)");
  }
  void noteExtensions(const tinygltf::ExtensionMap& exts, const std::string& el) {
    for (const auto& [name, value] : exts) noteExtension(name, el + ".extensions");
  }
  void warnOnce(const std::string& key, const std::string& msg) {
    if (warned_.insert(key).second) warn(msg);
  }
  // Skins, animations and morph targets are not applied: the rest pose is drawn.
  void checkUnsupportedStructure() {
    if (!m_.skins.empty()) {
      warnOnce("skins", "skins: " + std::to_string(m_.skins.size()) +
                            " skin(s) not applied (skinning is not supported); the bind pose is "
                            "drawn");
    }
    if (!m_.animations.empty()) {
      warnOnce("animations", "animations: " + std::to_string(m_.animations.size()) +
                                 " animation(s) not played (not supported); the static pose is "
                                 "drawn");
    }
    for (size_t i = 0; i < m_.nodes.size(); ++i)
      noteExtensions(m_.nodes[i].extensions, idx("nodes", i));
    for (size_t i = 0; i < m_.textures.size(); ++i) {
      noteExtensions(m_.textures[i].extensions, idx("textures", i));
    }
    for (size_t i = 0; i < m_.images.size(); ++i)
      noteExtensions(m_.images[i].extensions, idx("images", i));
    for (size_t i = 0; i < m_.samplers.size(); ++i) {
      noteExtensions(m_.samplers[i].extensions, idx("samplers", i));
    }
    for (size_t i = 0; i < m_.cameras.size(); ++i) {
      noteExtensions(m_.cameras[i].extensions, idx("cameras", i));
    }
    for (size_t i = 0; i < m_.scenes.size(); ++i)
      noteExtensions(m_.scenes[i].extensions, idx("scenes", i));
    for (size_t i = 0; i < m_.meshes.size(); ++i) {
      const tinygltf::Mesh& gm = m_.meshes[i];
      noteExtensions(gm.extensions, idx("meshes", i));
      for (size_t pi = 0; pi < gm.primitives.size(); ++pi) {
        const tinygltf::Primitive& p = gm.primitives[pi];
        const std::string el = idx("meshes", i) + ".primitives[" + std::to_string(pi) + "]";
        noteExtensions(p.extensions, el);
        if (!p.targets.empty()) {
          warnOnce("targets", el + ".targets: morph targets are not applied (not supported); "
                                   "the base shape is drawn");
        }
        for (const auto& [name, acc] : p.attributes) {
          if (name == "POSITION" || name == "NORMAL" || name == "TANGENT" || name == "TEXCOORD_0" ||
              name == "TEXCOORD_1" || name == "COLOR_0") {
            continue;
          }
          warnOnce("attribute " + name,
                   el + ".attributes." + name + ": attribute not supported; ignored" +
                       (name.rfind("JOINTS_", 0) == 0 || name.rfind("WEIGHTS_", 0) == 0
                            ? " (skinning is not supported)"
                            : ""));
        }
      }
    }
  }

  // ---- accessors ---------------------------------------------------------------------------
  // The bytes of bufferView `view_index`, checked against its buffer; `ref` names the reference.
  std::pair<const uint8_t*, size_t> viewBytes(int view_index, const std::string& ref) const {
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
  ElementRange elements(int view_index, uint64_t byte_offset, uint64_t count, int comps, int ctype,
                        bool normalized, const std::string& el) const {
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

  static float component(const ElementRange& r, size_t i, int c) {
    const unsigned char* q =
        r.base + i * r.stride +
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

  static uint32_t unsignedComponent(const ElementRange& r, size_t i) {
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

  const tinygltf::Accessor& accessor(int index, const std::string& ref) const {
    if (index < 0 || size_t(index) >= m_.accessors.size()) {
      fail(ref, "accessor index " + std::to_string(index) + " out of range (" +
                    std::to_string(m_.accessors.size()) + " accessors)");
    }
    return m_.accessors[size_t(index)];
  }

  void checkCount(uint64_t count, uint64_t budget, const std::string& el, const char* limit) const {
    if (count > budget) {
      fail(el + ".count", std::to_string(count) + " exceeds the budget of " +
                              std::to_string(budget) + " (GltfLimits::" + limit + ")");
    }
  }

  // Reads accessor `index` (referenced as `ref`) as count x comps floats (normalized integers
  // mapped to [0,1] or [-1,1], plain integers converted), after checking type, every byte range
  // and that each value is finite.
  std::vector<float> readFloats(int index, const std::string& ref, std::initializer_list<int> types,
                                std::initializer_list<int> ctypes, bool require_normalized_ints) {
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
    if (a.sparse.isSparse) {
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
          elements(a.sparse.indices.bufferView, uint64_t(a.sparse.indices.byteOffset), n, 1, ict,
                   false, sel + ".indices");
      const ElementRange rv =
          elements(a.sparse.values.bufferView, uint64_t(a.sparse.values.byteOffset), n, comps,
                   a.componentType, a.normalized, sel + ".values");
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
    for (float f : out)
      if (!std::isfinite(f)) fail(el, "non-finite value" + use);
    return out;
  }

  std::vector<uint32_t> readIndices(int index, size_t vertex_count, const std::string& ref) {
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

  // ---- images, materials ---------------------------------------------------------------------
  void importImage(int i) {
    tinygltf::Image& im = m_.images[size_t(i)];
    const std::string el = idx("images", size_t(i));
    ImageData out;
    out.name = im.name.empty() ? (im.uri.empty() || im.uri.size() > 256 ? el : im.uri) : im.name;
    // decodeImage produced every decoded image as 8-bit RGBA within the budgets.
    if (im.image.empty() || im.width <= 0 || im.height <= 0 || im.component != 4 || im.bits != 8 ||
        im.image.size() != size_t(im.width) * size_t(im.height) * 4) {
      fail(el, "image could not be loaded or decoded" +
                   (im.uri.empty() || im.uri.size() > 256 ? "" : " (" + im.uri + ")"));
    }
    out.width = im.width;
    out.height = im.height;
    out.rgba = std::move(im.image);
    images.push_back(std::move(out));
  }

  // A glTF number as a finite float, else an error naming `el`.
  float finite(double x, const std::string& el) const {
    if (!std::isfinite(x) || std::abs(x) > double(std::numeric_limits<float>::max())) {
      fail(el, "expected a finite number, got " + std::to_string(x));
    }
    return float(x);
  }

  // A number of an extension's object (`v` has `key`), finite, else an error naming `el.key`.
  float extNumber(const tinygltf::Value& v, const char* key, const std::string& el) const {
    const tinygltf::Value& x = v.Get(key);
    if (!x.IsNumber()) fail(el + "." + key, "expected a number");
    return finite(x.GetNumberAsDouble(), el + "." + key);
  }
  glm::vec2 extVec2(const tinygltf::Value& v, const char* key, const std::string& el) const {
    const tinygltf::Value& x = v.Get(key);
    if (!x.IsArray() || x.ArrayLen() != 2 || !x.Get(0).IsNumber() || !x.Get(1).IsNumber()) {
      fail(el + "." + key, "expected an array of 2 numbers");
    }
    return {finite(x.Get(0).GetNumberAsDouble(), el + "." + key),
            finite(x.Get(1).GetNumberAsDouble(), el + "." + key)};
  }

  // KHR_texture_transform on a textureInfo (`exts` its extensions): offset, rotation, scale and
  // the texCoord that replaces the textureInfo's own.
  void textureTransform(const tinygltf::ExtensionMap& exts, TextureRef& r, int& texcoord,
                        const std::string& el) {
    noteExtensions(exts, el);
    const auto it = exts.find("KHR_texture_transform");
    if (it == exts.end()) return;
    const tinygltf::Value& v = it->second;
    const std::string xel = el + ".extensions.KHR_texture_transform";
    if (!v.IsObject()) fail(xel, "expected an object");
    if (v.Has("offset")) r.uv_offset = extVec2(v, "offset", xel);
    if (v.Has("rotation")) r.uv_rotation = extNumber(v, "rotation", xel);
    if (v.Has("scale")) r.uv_scale = extVec2(v, "scale", xel);
    if (v.Has("texCoord")) {
      const tinygltf::Value& tc = v.Get("texCoord");
      if (!tc.IsInt()) fail(xel + ".texCoord", "expected an integer");
      texcoord = tc.GetNumberAsInt();
    }
  }

  TextureRef texture(int tex_index, int texcoord, const tinygltf::ExtensionMap& exts,
                     const std::string& el) {
    TextureRef r;
    if (tex_index < 0) return r;
    if (tex_index >= int(m_.textures.size())) fail(el, "texture index out of range");
    const tinygltf::Texture& t = m_.textures[size_t(tex_index)];
    textureTransform(exts, r, texcoord, el);
    if (texcoord < 0 || texcoord > 1)
      fail(el, "texCoord " + std::to_string(texcoord) + " not supported (0 or 1)");
    r.texcoord = texcoord;
    if (t.source < 0) {
      warn(el + ": texture has no source image (extension-only source?); ignored");
      return r;
    }
    if (t.source >= int(m_.images.size())) fail(el, "texture source out of range");
    r.image = image_base_ + t.source;
    if (t.sampler >= 0) {
      if (t.sampler >= int(m_.samplers.size())) fail(el, "sampler index out of range");
      const tinygltf::Sampler& s = m_.samplers[size_t(t.sampler)];
      auto wrap = [&](int w) {
        switch (w) {
          case TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE:
            return Wrap::ClampToEdge;
          case TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT:
            return Wrap::MirroredRepeat;
          case TINYGLTF_TEXTURE_WRAP_REPEAT:
            return Wrap::Repeat;
          default:
            fail(el, "bad sampler wrap mode " + std::to_string(w));
        }
      };
      r.sampler.wrap_s = wrap(s.wrapS);
      r.sampler.wrap_t = wrap(s.wrapT);
      r.sampler.mag =
          s.magFilter == TINYGLTF_TEXTURE_FILTER_NEAREST ? Filter::Nearest : Filter::Linear;
      switch (s.minFilter) {
        case TINYGLTF_TEXTURE_FILTER_NEAREST:
          r.sampler.min = Filter::Nearest, r.sampler.mipmaps = false;
          break;
        case TINYGLTF_TEXTURE_FILTER_LINEAR:
          r.sampler.min = Filter::Linear, r.sampler.mipmaps = false;
          break;
        case TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_NEAREST:
        case TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_LINEAR:
          r.sampler.min = Filter::Nearest;
          break;
        default:
          r.sampler.min = Filter::Linear;
          break;  // LINEAR_MIPMAP_* or unset
      }
    }
    return r;
  }

  void importMaterial(int i) {
    const tinygltf::Material& g = m_.materials[size_t(i)];
    const std::string el = "materials[" + std::to_string(i) + "]";
    Material m;
    m.name = g.name.empty() ? el : g.name;
    const auto& pbr = g.pbrMetallicRoughness;
    if (pbr.baseColorFactor.size() == 4) {
      const std::string f = el + ".pbrMetallicRoughness.baseColorFactor";
      m.base_color = glm::vec3(finite(pbr.baseColorFactor[0], f), finite(pbr.baseColorFactor[1], f),
                               finite(pbr.baseColorFactor[2], f));
      m.base_alpha = finite(pbr.baseColorFactor[3], f);
    }
    m.metallic = finite(pbr.metallicFactor, el + ".pbrMetallicRoughness.metallicFactor");
    m.roughness = finite(pbr.roughnessFactor, el + ".pbrMetallicRoughness.roughnessFactor");
    for (const auto& [name, value] : g.extensions) {
      if (name != "KHR_materials_pbrSpecularGlossiness") noteExtension(name, el + ".extensions");
    }
    noteExtensions(pbr.extensions, el + ".pbrMetallicRoughness");
    m.base_color_tex = texture(pbr.baseColorTexture.index, pbr.baseColorTexture.texCoord,
                               pbr.baseColorTexture.extensions, el + ".baseColorTexture");
    m.metallic_roughness_tex =
        texture(pbr.metallicRoughnessTexture.index, pbr.metallicRoughnessTexture.texCoord,
                pbr.metallicRoughnessTexture.extensions, el + ".metallicRoughnessTexture");
    m.normal_tex = texture(g.normalTexture.index, g.normalTexture.texCoord,
                           g.normalTexture.extensions, el + ".normalTexture");
    m.normal_tex.scale = finite(g.normalTexture.scale, el + ".normalTexture.scale");
    m.occlusion_tex = texture(g.occlusionTexture.index, g.occlusionTexture.texCoord,
                              g.occlusionTexture.extensions, el + ".occlusionTexture");
    m.occlusion_tex.scale = finite(g.occlusionTexture.strength, el + ".occlusionTexture.strength");
    m.emissive_tex = texture(g.emissiveTexture.index, g.emissiveTexture.texCoord,
                             g.emissiveTexture.extensions, el + ".emissiveTexture");
    if (g.emissiveFactor.size() == 3) {
      const std::string f = el + ".emissiveFactor";
      // glTF 2.0: each in [0, 1]; KHR_materials_emissive_strength scales it past 1.
      m.emissive =
          glm::clamp(glm::vec3(finite(g.emissiveFactor[0], f), finite(g.emissiveFactor[1], f),
                               finite(g.emissiveFactor[2], f)),
                     0.0f, 1.0f);
    }
    if (auto es = g.extensions.find("KHR_materials_emissive_strength"); es != g.extensions.end()) {
      const std::string xel = el + ".extensions.KHR_materials_emissive_strength";
      if (!es->second.IsObject()) fail(xel, "expected an object");
      if (es->second.Has("emissiveStrength")) {
        const float k = extNumber(es->second, "emissiveStrength", xel);
        if (k < 0.0f) fail(xel + ".emissiveStrength", "expected >= 0, got " + fmtFloat(k));
        m.emissive *= k;
        // The product stays a radiance the HDR target holds (frame.glsl clamps at HV_HDR_MAX).
        if (!std::isfinite(m.emissive.x + m.emissive.y + m.emissive.z)) {
          fail(xel + ".emissiveStrength", "emissive radiance overflows");
        }
      }
    }
    m.double_sided = g.doubleSided;
    if (g.alphaMode == "MASK") {
      m.alpha_mode = AlphaMode::Mask;
      m.alpha_cutoff = finite(g.alphaCutoff, el + ".alphaCutoff");
    } else if (g.alphaMode == "BLEND") {
      m.alpha_mode = AlphaMode::Opaque;
      warn(el + " \"" + m.name + "\": alphaMode BLEND is not supported; rendered opaque");
    } else if (g.alphaMode != "OPAQUE" && !g.alphaMode.empty()) {
      fail(el + ".alphaMode", "unknown value \"" + g.alphaMode + "\"");
    }
    auto sg = g.extensions.find("KHR_materials_pbrSpecularGlossiness");
    if (sg != g.extensions.end() && sg->second.IsObject()) {
      // Approximation: diffuse as base colour of a dielectric, roughness = 1 - glossiness; the
      // specular colour and specularGlossinessTexture are not representable and dropped.
      const tinygltf::Value& v = sg->second;
      m.metallic = 0.0f;
      m.metallic_roughness_tex = {};
      m.base_color = glm::vec3(1.0f);
      m.base_alpha = 1.0f;
      m.base_color_tex = {};
      if (v.Has("diffuseFactor") && v.Get("diffuseFactor").ArrayLen() == 4) {
        const auto& f = v.Get("diffuseFactor");
        const std::string fe = el + ".diffuseFactor";
        m.base_color = glm::vec3(finite(f.Get(0).GetNumberAsDouble(), fe),
                                 finite(f.Get(1).GetNumberAsDouble(), fe),
                                 finite(f.Get(2).GetNumberAsDouble(), fe));
        m.base_alpha = finite(f.Get(3).GetNumberAsDouble(), fe);
      }
      m.roughness =
          1.0f - (v.Has("glossinessFactor") ? finite(v.Get("glossinessFactor").GetNumberAsDouble(),
                                                     el + ".glossinessFactor")
                                            : 1.0f);
      if (v.Has("diffuseTexture")) {
        const auto& t = v.Get("diffuseTexture");
        const int index = t.Has("index") ? t.Get("index").GetNumberAsInt() : -1;
        int tc = t.Has("texCoord") ? t.Get("texCoord").GetNumberAsInt() : 0;
        tinygltf::ExtensionMap exts;
        if (t.Has("extensions") && t.Get("extensions").IsObject()) {
          const tinygltf::Value& e = t.Get("extensions");
          for (const std::string& key : e.Keys()) exts[key] = e.Get(key);
        }
        m.base_color_tex = texture(index, tc, exts, el + ".diffuseTexture");
      }
      if (!warned_specgloss_) {
        warn(
            "KHR_materials_pbrSpecularGlossiness approximated as metal/rough (specular colour "
            "dropped)");
        warned_specgloss_ = true;
      }
    }
    m.base_color = glm::clamp(m.base_color, 0.0f, 1.0f);
    m.metallic = glm::clamp(m.metallic, 0.0f, 1.0f);
    m.roughness = glm::clamp(m.roughness, 0.0f, 1.0f);
    materials.push_back(m);
  }

  int defaultMaterial() {
    if (opt_.material_override >= 0) return opt_.material_override;
    if (default_material_ < 0) {
      // glTF 2.0, 3.9.6: a primitive without a material uses every default of a material:
      // baseColorFactor 1, metallicFactor 1, roughnessFactor 1.
      Material m;
      m.name = "gltf default";
      m.base_color = glm::vec3(1.0f);
      m.metallic = 1.0f;
      m.roughness = 1.0f;
      materials.push_back(m);
      default_material_ = int(materials.size()) - 1;
    }
    return material_base_ + default_material_;
  }

  // ---- meshes --------------------------------------------------------------------------------
  void importMesh(int mi) {
    const tinygltf::Mesh& gm = m_.meshes[size_t(mi)];
    for (size_t pi = 0; pi < gm.primitives.size(); ++pi) {
      const std::string el =
          "meshes[" + std::to_string(mi) + "].primitives[" + std::to_string(pi) + "]";
      std::optional<Mesh> mesh = importPrimitive(gm.primitives[pi], el);
      if (!mesh) continue;
      mesh_triangles_[size_t(mi)] += mesh->indices.size() / 3;
      mesh->name =
          (gm.name.empty() ? "mesh" + std::to_string(mi) : gm.name) + "/" + std::to_string(pi);
      meshes.push_back(std::move(*mesh));
      mesh_map_[size_t(mi)].push_back(mesh_base_ + int(meshes.size()) - 1);
    }
  }

  std::optional<Mesh> importPrimitive(const tinygltf::Primitive& p, const std::string& el) {
    auto attr = [&](const char* name) {
      auto it = p.attributes.find(name);
      return it == p.attributes.end() ? -1 : it->second;
    };
    const int pos_acc = attr("POSITION");
    // glTF 2.0 (3.7.2.1): without positions a client "SHOULD skip primitive's rendering" (the
    // Khronos validator accepts such a file, with a warning).
    if (pos_acc < 0) {
      warn(el + ": no POSITION attribute (nothing to draw); skipped");
      return std::nullopt;
    }
    // The vertex budget before any attribute is read (they may have no bufferView: zeros).
    const uint64_t pos_count = accessor(pos_acc, el + ".POSITION").count;
    if (pos_count > lim_.max_vertices - std::min(total_vertices_, lim_.max_vertices)) {
      fail(idx("accessors", size_t(pos_acc)) + ".count",
           std::to_string(pos_count) + " vertices (" + el +
               ".POSITION) exceed the file's budget of " + std::to_string(lim_.max_vertices) +
               " (GltfLimits::max_vertices)");
    }
    using std::initializer_list;
    constexpr int kF = TINYGLTF_COMPONENT_TYPE_FLOAT, kUB = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,
                  kB = TINYGLTF_COMPONENT_TYPE_BYTE, kUS = TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                  kS = TINYGLTF_COMPONENT_TYPE_SHORT;
    const std::vector<float> pos =
        readFloats(pos_acc, el + ".POSITION", {TINYGLTF_TYPE_VEC3}, {kF, kB, kUB, kS, kUS}, false);
    const size_t n = pos.size() / 3;
    std::vector<float> nrm, tan, uv[2];
    const bool has_normal = attr("NORMAL") >= 0;
    if (has_normal)
      nrm = readFloats(attr("NORMAL"), el + ".NORMAL", {TINYGLTF_TYPE_VEC3}, {kF, kB, kS}, true);
    if (has_normal && attr("TANGENT") >= 0) {
      tan = readFloats(attr("TANGENT"), el + ".TANGENT", {TINYGLTF_TYPE_VEC4}, {kF, kB, kS}, true);
    }
    for (int s = 0; s < 2; ++s) {
      const std::string name = "TEXCOORD_" + std::to_string(s);
      if (attr(name.c_str()) >= 0) {
        uv[s] = readFloats(attr(name.c_str()), el + "." + name, {TINYGLTF_TYPE_VEC2},
                           {kF, kUB, kUS, kB, kS}, true);
      }
    }
    // glTF 2.0 3.7.2.1: COLOR_0 is VEC3 or VEC4 of float, or normalized unsigned byte/short;
    // linear RGB(A), multiplying the base colour (and alpha).
    std::vector<float> col;
    size_t col_comps = 0;
    if (attr("COLOR_0") >= 0) {
      col = readFloats(attr("COLOR_0"), el + ".COLOR_0", {TINYGLTF_TYPE_VEC3, TINYGLTF_TYPE_VEC4},
                       {kF, kUB, kUS}, true);
      col_comps = accessor(attr("COLOR_0"), el + ".COLOR_0").type == TINYGLTF_TYPE_VEC3 ? 3 : 4;
    }
    auto sizeCheck = [&](const std::vector<float>& v, size_t comps, const char* what) {
      if (!v.empty() && v.size() != n * comps) {
        fail(el + "." + what, "count differs from POSITION count " + std::to_string(n));
      }
    };
    sizeCheck(nrm, 3, "NORMAL");
    sizeCheck(tan, 4, "TANGENT");
    sizeCheck(uv[0], 2, "TEXCOORD_0");
    sizeCheck(uv[1], 2, "TEXCOORD_1");
    sizeCheck(col, col_comps, "COLOR_0");

    std::vector<uint32_t> ind;
    if (p.indices >= 0) {
      ind = readIndices(p.indices, n, el + ".indices");
    } else {
      ind.resize(n);
      for (size_t i = 0; i < n; ++i) ind[i] = uint32_t(i);
    }
    size_t triangles = 0;
    switch (p.mode) {
      case TINYGLTF_MODE_TRIANGLES:
        if (ind.size() % 3 != 0) fail(el, "TRIANGLES index count is not a multiple of 3");
        triangles = ind.size() / 3;
        break;
      case TINYGLTF_MODE_TRIANGLE_STRIP:
      case TINYGLTF_MODE_TRIANGLE_FAN:
        triangles = ind.size() >= 3 ? ind.size() - 2 : 0;
        break;
      case TINYGLTF_MODE_POINTS:
      case TINYGLTF_MODE_LINE:
      case TINYGLTF_MODE_LINE_LOOP:
      case TINYGLTF_MODE_LINE_STRIP:
        warn(el + ": mode " + std::to_string(p.mode) + " (points/lines) is not rendered; skipped");
        return std::nullopt;
      default:
        fail(el + ".mode", "unknown value " + std::to_string(p.mode));
    }
    // Budgets, before the triangle list and the vertices are built.
    total_triangles_ += triangles;
    total_vertices_ += has_normal ? n : 3 * triangles;  // without normals: 3 per triangle
    if (total_triangles_ > lim_.max_triangles) {
      fail(el, "the file's triangles exceed the budget of " + std::to_string(lim_.max_triangles) +
                   " (GltfLimits::max_triangles)");
    }
    if (total_vertices_ > lim_.max_vertices) {
      fail(el, "the file's vertices exceed the budget of " + std::to_string(lim_.max_vertices) +
                   " (GltfLimits::max_vertices)");
    }
    std::vector<uint32_t> tris;
    if (p.mode == TINYGLTF_MODE_TRIANGLES) {
      tris = std::move(ind);
    } else {
      tris.reserve(3 * triangles);
      for (size_t i = 0; i < triangles; ++i) {
        if (p.mode == TINYGLTF_MODE_TRIANGLE_STRIP) {  // glTF spec 3.7.2.1 ordering
          tris.insert(tris.end(), {ind[i], ind[i + 1 + i % 2], ind[i + 2 - i % 2]});
        } else {
          tris.insert(tris.end(), {ind[i + 1], ind[i + 2], ind[0]});
        }
      }
    }

    int material;
    if (p.material >= 0) {
      if (p.material >= int(m_.materials.size())) {
        fail(el + ".material", "index " + std::to_string(p.material) + " out of range");
      }
      material = opt_.material_override >= 0 ? opt_.material_override : material_base_ + p.material;
    } else {
      material = defaultMaterial();
    }
    int normal_set = 0;
    if (opt_.material_override < 0 && p.material >= 0) {
      normal_set = materials[size_t(p.material)].normal_tex.texcoord;
    }
    Mesh mesh;
    mesh.material = material;
    mesh.has_colors = !col.empty();
    auto vertex = [&](size_t i) {
      Vertex v;
      v.position = glm::make_vec3(&pos[i * 3]);
      if (has_normal) {
        v.normal = glm::make_vec3(&nrm[i * 3]);
        const float l = glm::length(v.normal);
        v.normal = l > 1e-12f ? v.normal / l : glm::vec3(0, 1, 0);
      }
      if (!tan.empty()) {
        v.tangent = glm::make_vec4(&tan[i * 4]);
        v.tangent.w = v.tangent.w < 0.0f ? -1.0f : 1.0f;
      }
      if (!uv[0].empty()) v.uv0 = glm::make_vec2(&uv[0][i * 2]);
      if (!uv[1].empty()) v.uv1 = glm::make_vec2(&uv[1][i * 2]);
      if (!col.empty()) {
        const float* c = &col[i * col_comps];
        // Float colours outside [0, 1] are invalid glTF: clamped, as a base colour is.
        v.color = glm::clamp(glm::vec4(c[0], c[1], c[2], col_comps == 4 ? c[3] : 1.0f), 0.0f, 1.0f);
      }
      return v;
    };
    if (has_normal) {
      mesh.vertices.reserve(n);
      for (size_t i = 0; i < n; ++i) mesh.vertices.push_back(vertex(i));
      mesh.indices = std::move(tris);
    } else {  // flat normals: every triangle gets its own three vertices
      mesh.vertices.reserve(tris.size());
      mesh.indices.reserve(tris.size());
      for (size_t t = 0; t + 2 < tris.size(); t += 3) {
        Vertex v[3] = {vertex(tris[t]), vertex(tris[t + 1]), vertex(tris[t + 2])};
        glm::vec3 fn = glm::cross(v[1].position - v[0].position, v[2].position - v[0].position);
        const float l = glm::length(fn);
        fn = l > 0.0f ? fn / l : glm::vec3(0, 1, 0);
        for (Vertex& x : v) {
          x.normal = fn;
          mesh.indices.push_back(uint32_t(mesh.vertices.size()));
          mesh.vertices.push_back(x);
        }
      }
    }
    // Provided tangents are ignored when normals were missing (glTF 2.0, 3.7.2.1).
    if (tan.empty() || !has_normal) generateTangents(mesh, normal_set);
    return mesh;
  }

  // ---- nodes ---------------------------------------------------------------------------------
  glm::mat4 localMatrix(const tinygltf::Node& n, const std::string& el) const {
    glm::mat4 local(1.0f);
    if (n.matrix.size() == 16) {
      for (int k = 0; k < 16; ++k) {
        glm::value_ptr(local)[k] = finite(n.matrix[size_t(k)], el + ".matrix");
      }
      return local;
    }
    glm::mat4 t(1.0f), r(1.0f), s(1.0f);
    if (n.translation.size() == 3) {
      const std::string f = el + ".translation";
      t = glm::translate(glm::mat4(1.0f),
                         glm::vec3(finite(n.translation[0], f), finite(n.translation[1], f),
                                   finite(n.translation[2], f)));
    }
    if (n.rotation.size() == 4) {
      const std::string f = el + ".rotation";
      const glm::quat q(finite(n.rotation[3], f), finite(n.rotation[0], f),
                        finite(n.rotation[1], f), finite(n.rotation[2], f));
      if (!(glm::length(q) > 1e-6f)) fail(f, "expected a non-zero quaternion");
      r = glm::mat4_cast(glm::normalize(q));
    }
    if (n.scale.size() == 3) {
      const std::string f = el + ".scale";
      s = glm::scale(glm::mat4(1.0f), glm::vec3(finite(n.scale[0], f), finite(n.scale[1], f),
                                                finite(n.scale[2], f)));
    }
    return t * r * s;
  }

  // The budgets of node instances and instanced triangles, checked before anything is instanced:
  // per node, the instances and triangles of its subtree, counted once per node over the graph
  // (O(nodes + children) however often a node is reused) and saturating at the budgets. A few KB
  // whose 64 nodes each list the next one 4 times (4^63 instances) are rejected at once instead
  // of after a million instances have been built (9 s). A child that is out of range or closes a
  // cycle counts 0 here and is left to visit(), which names it (before it has instanced more than
  // these totals); with neither, visit() instances exactly these totals, so it checks no budget of
  // its own.
  void checkExpansion(const std::vector<int>& roots) {
    const size_t n = m_.nodes.size();
    auto capOf = [](uint64_t limit) { return std::max(limit, limit + 1); };  // limit + 1, no wrap
    const uint64_t cap_i = capOf(lim_.max_node_instances);
    const uint64_t cap_t = capOf(lim_.max_instanced_triangles);
    auto add = [](uint64_t a, uint64_t b, uint64_t cap) { return b > cap - a ? cap : a + b; };
    std::vector<uint64_t> inst(n, 0), tris(n, 0);
    std::vector<uint8_t> state(n, 0);              // 0 not seen, 1 on the current path, 2 counted
    std::vector<std::pair<size_t, size_t>> stack;  // node, next child
    uint64_t total_i = 0, total_t = 0;
    for (int r : roots) {
      if (r < 0 || size_t(r) >= n) continue;
      if (state[size_t(r)] == 0) {
        state[size_t(r)] = 1;
        stack.push_back({size_t(r), 0});
      }
      while (!stack.empty()) {
        const size_t ni = stack.back().first;
        const tinygltf::Node& node = m_.nodes[ni];
        if (stack.back().second < node.children.size()) {
          const int c = node.children[stack.back().second++];
          if (c >= 0 && size_t(c) < n && state[size_t(c)] == 0) {
            state[size_t(c)] = 1;
            stack.push_back({size_t(c), 0});
          }
          continue;
        }
        uint64_t i = 1, t = 0;
        if (node.mesh >= 0 && size_t(node.mesh) < mesh_triangles_.size()) {
          t = std::min(cap_t, mesh_triangles_[size_t(node.mesh)]);
        }
        for (int c : node.children) {
          if (c < 0 || size_t(c) >= n || state[size_t(c)] != 2) continue;
          i = add(i, inst[size_t(c)], cap_i);
          t = add(t, tris[size_t(c)], cap_t);
        }
        inst[ni] = i;
        tris[ni] = t;
        state[ni] = 2;
        stack.pop_back();
      }
      total_i = add(total_i, inst[size_t(r)], cap_i);
      total_t = add(total_t, tris[size_t(r)], cap_t);
      const std::string el = idx("nodes", size_t(r));
      if (total_i > lim_.max_node_instances) {
        fail(el, "the node graph expands into more than " +
                     std::to_string(lim_.max_node_instances) +
                     " node instances (GltfLimits::max_node_instances; nodes reused by several "
                     "parents count once per use)");
      }
      if (total_t > lim_.max_instanced_triangles) {
        fail(el, "the instanced meshes exceed the budget of " +
                     std::to_string(lim_.max_instanced_triangles) +
                     " triangles (GltfLimits::max_instanced_triangles; nodes reused by several "
                     "parents count once per use)");
      }
    }
  }

  // Depth-first over the node graph from root `root` with an explicit stack (a file controls
  // the depth), rejecting cycles; nodes reused by several parents are instanced (checkExpansion
  // has checked the budgets of node instances and instanced triangles).
  void visit(int root, const glm::mat4& parent, const std::string& from) {
    struct Frame {
      int node;
      glm::mat4 world;
      size_t next_child;
    };
    std::vector<bool> on_path(m_.nodes.size(), false);
    std::vector<Frame> stack;
    auto enter = [&](int ni, const glm::mat4& parent_world, const std::string& ref) {
      if (ni < 0 || size_t(ni) >= m_.nodes.size()) {
        fail(ref, "node index " + std::to_string(ni) + " out of range (" +
                      std::to_string(m_.nodes.size()) + " nodes)");
      }
      const std::string el = idx("nodes", size_t(ni));
      if (on_path[size_t(ni)]) fail(ref, "node hierarchy contains a cycle through " + el);
      if (int(stack.size()) >= lim_.max_node_depth) {
        fail(ref, "node hierarchy deeper than " + std::to_string(lim_.max_node_depth) +
                      " levels (GltfLimits::max_node_depth)");
      }
      const tinygltf::Node& n = m_.nodes[size_t(ni)];
      // Messages name the node by index and, when it has one, by name.
      const std::string label = n.name.empty() ? el : el + " (\"" + n.name + "\")";
      const glm::mat4 world = parent_world * localMatrix(n, el);
      for (int k = 0; k < 16; ++k) {
        if (!std::isfinite(glm::value_ptr(world)[k])) {
          fail(label, "world transform overflows (non-finite)");
        }
      }
      // Scene coordinates stay within +-1e6 m (docs/scene-format.md "Bounded"): a node placed or
      // scaled past that (a translation of 1e38) is reported here, not later by the camera
      // framed around it.
      for (int c = 0; c < 4; ++c) {
        const glm::vec3 t = glm::abs(glm::vec3(world[3]));
        const float extent = c < 3 ? glm::length(glm::vec3(world[c])) : std::max({t.x, t.y, t.z});
        if (!(extent <= kMaxWorldExtent)) {
          fail(label, std::string(c < 3 ? "world scale " : "world translation ") +
                          "beyond the scene's range of +-1e6 m (" + (c < 3 ? "axis length " : "") +
                          fmtFloat(extent) + ")");
        }
      }
      // A singular transform (a scale of 0, an all-zero matrix: valid glTF, used to hide a node)
      // draws nothing, and its normals have no inverse transpose: its meshes and cameras are
      // skipped, the node and its children are still checked.
      const bool singular = !(std::abs(glm::determinant(glm::mat3(world))) > 0.0f) ||
                            !allFinite(glm::inverse(glm::mat3(world)));
      if (singular && n.mesh >= 0 && !warned_singular_) {
        warn(label + ": a singular transform (scale 0) hides its mesh; not drawn" +
             std::string(" (nor any other mesh under a singular transform)"));
        warned_singular_ = true;
      }
      if (n.mesh >= 0 && !singular) {
        if (size_t(n.mesh) >= m_.meshes.size()) {
          fail(el + ".mesh", "index " + std::to_string(n.mesh) + " out of range");
        }
        if (!mesh_map_[size_t(n.mesh)].empty()) {
          Object o;
          o.name = (opt_.name_prefix.empty() ? fs::path(path_).stem().string() : opt_.name_prefix) +
                   "/" + (n.name.empty() ? el : n.name);
          o.transform = world;
          o.meshes = mesh_map_[size_t(n.mesh)];
          objects.push_back(std::move(o));
        }
      }
      if (n.camera >= 0 && size_t(n.camera) < m_.cameras.size() && !singular) {
        addCamera(m_.cameras[size_t(n.camera)], world);
      }
      on_path[size_t(ni)] = true;
      stack.push_back({ni, world, 0});
    };
    enter(root, parent, from);
    while (!stack.empty()) {
      Frame& f = stack.back();
      const tinygltf::Node& n = m_.nodes[size_t(f.node)];
      if (f.next_child < n.children.size()) {
        const int child = n.children[f.next_child];
        const std::string ref =
            idx("nodes", size_t(f.node)) + ".children[" + std::to_string(f.next_child) + "]";
        ++f.next_child;
        const glm::mat4 world = f.world;  // `f` may move when the stack grows
        enter(child, world, ref);
      } else {
        on_path[size_t(f.node)] = false;
        stack.pop_back();
      }
    }
  }

  void addCamera(const tinygltf::Camera& c, const glm::mat4& world) {
    GltfCamera cam;
    cam.name = c.name;
    cam.world = world;
    cam.perspective = c.type != "orthographic";
    if (cam.perspective) {
      if (c.perspective.yfov > 0.0) cam.yfov_rad = float(c.perspective.yfov);
      if (c.perspective.znear > 0.0) cam.znear = float(c.perspective.znear);
      cam.zfar = float(std::max(c.perspective.zfar, 0.0));
    } else {
      cam.znear = float(std::max(c.orthographic.znear, 1e-4));
      cam.zfar = float(std::max(c.orthographic.zfar, 0.0));
    }
    cameras.push_back(cam);
  }

  std::string path_;
  tinygltf::Model& m_;  // images are moved out of it
  const GltfOptions& opt_;
  const GltfLimits& lim_;
  int image_base_ = 0, material_base_ = 0, mesh_base_ = 0;
  bool warned_singular_ = false;  // one warning per file
  uint64_t total_vertices_ = 0, total_triangles_ = 0;
  std::vector<uint64_t> mesh_triangles_;  // per glTF mesh, all imported primitives
  int default_material_ = -1;
  bool warned_specgloss_ = false;
  std::set<std::string> warned_;  // what was warned about (checkUnsupportedStructure)
  std::vector<std::vector<int>> mesh_map_;
};

}  // namespace

void loadGltfFromMemory(const uint8_t* bytes, size_t size, bool binary, const std::string& name,
                        const glm::mat4& transform, Scene& scene, const GltfOptions& options) {
  const GltfLimits& lim = options.limits;
  if (size > lim.max_file_bytes || size > std::numeric_limits<unsigned int>::max()) {
    throw SceneError(name + ": " + std::to_string(size) + " bytes exceed the limit of " +
                     std::to_string(lim.max_file_bytes) + " (GltfLimits::max_file_bytes)");
  }
  const uint8_t* json = bytes;
  size_t json_size = size;
  if (binary) {
    const GlbChunks c = checkGlb(name, bytes, size);
    json = c.json, json_size = c.json_size;
  }
  checkJsonDepth(name, json, json_size, lim.max_json_depth);
  checkImageViews(name, json, json_size);

  tinygltf::TinyGLTF loader;
  LoadContext ctx;
  ctx.limits = &lim;
  ctx.decode_images = options.material_override < 0;
  loader.SetFsCallbacks({&fileExists, &expandNothing, &readWholeFile, &writeNothing, &ctx});
  loader.SetImageLoader(&decodeImage, &ctx);
  tinygltf::Model model;
  std::string err, warn;
  const std::string base_dir = fs::path(name).parent_path().string();
  bool ok = false;
  try {
    if (binary) {
      ok = loader.LoadBinaryFromMemory(&model, &err, &warn, bytes, unsigned(size), base_dir);
    } else {
      ok = loader.LoadASCIIFromString(&model, &err, &warn, reinterpret_cast<const char*>(bytes),
                                      unsigned(size), base_dir);
    }
  } catch (const std::bad_alloc&) {
    throw SceneError(name + ": cannot load glTF: out of memory");
  } catch (const std::out_of_range& e) {  // tinygltf 2.7 indexes by .at() on some bad sizes
    err = std::string("a size or index out of range (") + e.what() +
          "), e.g. a buffer of byteLength 0";
    ok = false;
  } catch (const std::exception& e) {
    err = e.what();
    ok = false;
  }
  if (!ok || !err.empty()) {
    while (!err.empty() && (err.back() == '\n' || err.back() == ' ')) err.pop_back();
    throw SceneError(name +
                     ": cannot load glTF: " + (err.empty() ? std::string("unknown error") : err));
  }
  Importer imp(name, model, scene, options);
  try {
    imp.run(transform);
  } catch (const std::bad_alloc&) {
    throw SceneError(name + ": out of memory while importing");
  }
  // Success: append everything at once (indices were computed against the final offsets).
  for (auto& x : imp.images) scene.images.push_back(std::move(x));
  for (auto& x : imp.materials) scene.materials.push_back(std::move(x));
  for (auto& x : imp.meshes) scene.meshes.push_back(std::move(x));
  for (auto& x : imp.objects) scene.objects.push_back(std::move(x));
  if (options.cameras) {
    for (auto& c : imp.cameras) options.cameras->push_back(std::move(c));
  }
}

void loadGltf(const std::string& path, const glm::mat4& transform, Scene& scene,
              const GltfOptions& options) {
  std::string text;
  try {
    text = readInputFile(path, options.limits.max_file_bytes, "GltfLimits::max_file_bytes");
  } catch (const InputError& e) {
    throw SceneError(e.what());
  }
  const auto* bytes = reinterpret_cast<const uint8_t*>(text.data());
  const size_t size = text.size();
  // A GLB is recognised by its magic, whatever the extension.
  const bool binary = size >= 4 && std::memcmp(bytes, "glTF", 4) == 0;
  loadGltfFromMemory(bytes, size, binary, path, transform, scene, options);
}

}  // namespace hv
