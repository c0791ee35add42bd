// glTF import on top of tinygltf (Debian libtinygltf-dev). tinygltf parses JSON, loads buffers
// and decodes images (stb_image from Debian's libstb); everything else (accessor bounds, index
// validation, primitive conversion, materials) is checked and done by the importer
// (gltf_import.hpp lists its files). This file holds tinygltf's implementation, its file and
// image callbacks, and the entry points.
#define TINYGLTF_IMPLEMENTATION
#define TINYGLTF_NO_INCLUDE_JSON  // nlohmann/json is already included below, outside the
                                  // hidden-visibility pragma tinygltf wraps around it
#include <nlohmann/json.hpp>

#include "gltf_import.hpp"

#include "halfvec/core/input_file.hpp"
#include "halfvec/core/png_bound.hpp"

#include <cstring>
#include <filesystem>
#include <limits>

namespace hv {
namespace {

namespace fs = std::filesystem;
using gltf::idx;

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
    const gltf::GlbChunks c = gltf::checkGlb(name, bytes, size);
    json = c.json, json_size = c.json_size;
  }
  gltf::checkJsonDepth(name, json, json_size, lim.max_json_depth);
  gltf::checkImageViews(name, json, json_size);

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
  gltf::Importer imp(name, model, scene, options);
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
  std::vector<Light>& lights = options.lights ? *options.lights : scene.lights;
  lights.insert(lights.end(), imp.lights.begin(), imp.lights.end());
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
