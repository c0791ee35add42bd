// Checks on the raw bytes of a glTF file, before tinygltf parses them: the GLB container, the
// JSON nesting and the images stored in bufferViews, which tinygltf 2.7 does not check itself.
#include <nlohmann/json.hpp>

#include "gltf_import.hpp"

#include <cstring>
#include <limits>
#include <string_view>

#include "halfvec/core/input_file.hpp"

namespace hv::gltf {
namespace {

uint32_t le32(const uint8_t* p) {
  return uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16 | uint32_t(p[3]) << 24;
}

}  // namespace

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

}  // namespace hv::gltf
