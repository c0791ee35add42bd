// The glTF importer's internals, shared by its source files (private to the scene module; the
// public interface is halfvec/scene/gltf_loader.hpp). One file per responsibility:
//   gltf_loader.cpp     tinygltf (its one implementation), file access and image decoding
//                       callbacks, the entry points loadGltf and loadGltfFromMemory
//   gltf_container.cpp  checks on the raw bytes before tinygltf parses them (GLB, JSON nesting,
//                       images in bufferViews)
//   gltf_import.cpp     the import's order, extensions and what is not imported (warnings)
//   gltf_accessors.cpp  bufferViews and accessors (dense, sparse, indices), checked and read
//   gltf_textures.cpp   images, textures, samplers, KHR_texture_transform
//   gltf_materials.cpp  materials and their extensions, the default material
//   gltf_meshes.cpp     primitives: attributes, indices, triangle lists, vertices, tangents
//   gltf_nodes.cpp      the node walk (transforms, expansion budgets, objects) and cameras
//   gltf_lights.cpp     KHR_lights_punctual: the nodes' point and spot lights
//
// tinygltf's implementation is compiled in gltf_loader.cpp alone: that file defines
// TINYGLTF_IMPLEMENTATION (and TINYGLTF_NO_INCLUDE_JSON, having included nlohmann/json itself)
// before including this header, every other file sees the declarations only. The configuration
// macros below change tinygltf's classes, so they are set here, once, for every file.
#pragma once

#ifndef TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#endif
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-parameter"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#include <tiny_gltf.h>
#pragma GCC diagnostic pop

#include <cstdint>
#include <cstdio>
#include <initializer_list>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "halfvec/scene/gltf_loader.hpp"

namespace hv::gltf {

// offset + length <= size, without overflow.
inline bool fitsIn(uint64_t offset, uint64_t length, uint64_t size) {
  return offset <= size && length <= size - offset;
}

// `array[i]`, the name of an element in messages.
inline std::string idx(const char* array, size_t i) {
  return std::string(array) + "[" + std::to_string(i) + "]";
}

inline std::string fmtFloat(float x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", double(x));
  return buf;
}

// ---- gltf_container.cpp: checks on the raw bytes, before tinygltf parses them ----------------

struct GlbChunks {
  const uint8_t* json = nullptr;
  size_t json_size = 0;
};

// The GLB container's header and chunks; returns the JSON chunk. `name` is the file, for messages.
GlbChunks checkGlb(const std::string& name, const uint8_t* b, size_t size);
// JSON nesting of `text` at most `max_depth` levels.
void checkJsonDepth(const std::string& name, const uint8_t* text, size_t size, int max_depth);
// Every image stored in a bufferView: the view inside its buffer.
void checkImageViews(const std::string& name, const uint8_t* text, size_t size);

// ---- the import, on tinygltf's model -----------------------------------------------------------

// An accessor's elements, checked against the buffer: `count` elements of `comps` components of
// type `ctype`, element i at base + i * stride.
struct ElementRange {
  const uint8_t* base = nullptr;
  size_t count = 0, stride = 0;
  int comps = 1, ctype = 0;
  bool normalized = false;
};

// The vertex attributes of one primitive as floats, `n` vertices (POSITION's count); the others
// are empty when absent. COLOR_0 has `col_comps` (3 or 4) components per vertex.
struct PrimitiveAttributes {
  std::vector<float> pos, nrm, tan, uv[2], col;
  size_t n = 0, col_comps = 0;
  bool has_normal = false;
};

// Imports tinygltf's model of one file into new images, materials, meshes, objects and cameras,
// indexed as if appended to `scene` (loadGltfFromMemory appends them when everything succeeded).
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

  void run(const glm::mat4& transform);

  // Extensions the importer reads. KHR_materials_pbrSpecularGlossiness is approximated (with a
  // warning of its own), the others are honoured in full.
  static bool honoured(const std::string& ext);
  static std::string honouredList();

  std::vector<ImageData> images;
  std::vector<Material> materials;
  std::vector<Mesh> meshes;
  std::vector<Object> objects;
  std::vector<GltfCamera> cameras;
  std::vector<Light> lights;  // KHR_lights_punctual instances, in node-visit order

 private:
  static constexpr const char* kHonouredExtensions[] = {"KHR_lights_punctual",
                                                        "KHR_materials_clearcoat",
                                                        "KHR_materials_emissive_strength",
                                                        "KHR_materials_pbrSpecularGlossiness",
                                                        "KHR_mesh_quantization",
                                                        "KHR_texture_transform"};

  // ---- gltf_import.cpp: what is not imported, numbers of extension objects ------------------
  void noteExtension(const std::string& ext, const std::string& el);
  void noteExtensions(const tinygltf::ExtensionMap& exts, const std::string& el);
  void warnOnce(const std::string& key, const std::string& msg);
  void checkUnsupportedStructure();
  void checkUnsupportedPrimitives();
  float finite(double x, const std::string& el) const;
  float extNumber(const tinygltf::Value& v, const char* key, const std::string& el) const;
  glm::vec2 extVec2(const tinygltf::Value& v, const char* key, const std::string& el) const;

  // ---- gltf_accessors.cpp ---------------------------------------------------------------------
  std::pair<const uint8_t*, size_t> viewBytes(int view_index, const std::string& ref) const;
  ElementRange elements(int view_index, uint64_t byte_offset, uint64_t count, int comps, int ctype,
                        bool normalized, const std::string& el) const;
  const tinygltf::Accessor& accessor(int index, const std::string& ref) const;
  void checkCount(uint64_t count, uint64_t budget, const std::string& el, const char* limit) const;
  std::vector<float> readFloats(int index, const std::string& ref, std::initializer_list<int> types,
                                std::initializer_list<int> ctypes, bool require_normalized_ints);
  void readSparse(const tinygltf::Accessor& a, int comps, const std::string& el,
                  std::vector<float>& out) const;
  std::vector<uint32_t> readIndices(int index, size_t vertex_count, const std::string& ref);

  // ---- gltf_textures.cpp ----------------------------------------------------------------------
  void importImage(int i);
  void textureTransform(const tinygltf::ExtensionMap& exts, TextureRef& r, int& texcoord,
                        const std::string& el);
  TextureRef texture(int tex_index, int texcoord, const tinygltf::ExtensionMap& exts,
                     const std::string& el);
  TextureRef textureInfo(const tinygltf::Value& t, const std::string& el);
  Sampler samplerOf(const tinygltf::Sampler& s, const std::string& el) const;

  // ---- gltf_materials.cpp ---------------------------------------------------------------------
  void importMaterial(int i);
  void metalRoughFactors(const tinygltf::Material& g, const std::string& el, Material& m) const;
  void materialTextures(const tinygltf::Material& g, const std::string& el, Material& m);
  void emission(const tinygltf::Material& g, const std::string& el, Material& m) const;
  void alphaMode(const tinygltf::Material& g, const std::string& el, Material& m) const;
  void clearCoat(const tinygltf::Material& g, const std::string& el, Material& m);
  void specularGlossiness(const tinygltf::Value& v, const std::string& el, Material& m);
  int defaultMaterial();

  // ---- gltf_meshes.cpp ------------------------------------------------------------------------
  void importMesh(int mi);
  std::optional<Mesh> importPrimitive(const tinygltf::Primitive& p, const std::string& el);
  PrimitiveAttributes readAttributes(const tinygltf::Primitive& p, int pos_acc,
                                     const std::string& el);
  std::optional<size_t> triangleCount(const tinygltf::Primitive& p, size_t index_count,
                                      const std::string& el) const;
  void countBudgets(size_t triangles, const PrimitiveAttributes& a, const std::string& el);
  int primitiveMaterial(const tinygltf::Primitive& p, const std::string& el);

  // ---- gltf_nodes.cpp -------------------------------------------------------------------------
  std::vector<int> sceneRoots(std::string& roots_el) const;
  glm::mat4 localMatrix(const tinygltf::Node& n, const std::string& el) const;
  void checkExpansion(const std::vector<int>& roots);
  void visit(int root, const glm::mat4& parent, const std::string& from);
  glm::mat4 nodeWorld(const tinygltf::Node& n, const glm::mat4& parent_world, const std::string& el,
                      const std::string& label) const;
  void instanceNode(const tinygltf::Node& n, const glm::mat4& world, const std::string& el,
                    const std::string& label);
  void addCamera(const tinygltf::Camera& c, const glm::mat4& world);

  // ---- gltf_lights.cpp ------------------------------------------------------------------------
  void importNodeLight(const tinygltf::Node& n, const glm::mat4& world, const std::string& el);

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

}  // namespace hv::gltf
