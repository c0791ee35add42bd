// glTF 2.0 import (.gltf with external or embedded buffers, .glb) into a Scene.
//
// Supported: the node hierarchy (matrix or TRS), every primitive of every mesh; TRIANGLES,
// TRIANGLE_STRIP and TRIANGLE_FAN (strips and fans converted to lists; POINTS and LINES are
// validated, then skipped with a warning); 8/16/32-bit indices and non-indexed primitives;
// POSITION, NORMAL (flat normals generated when missing), TANGENT (generated, tangents.hpp, when
// missing), TEXCOORD_0/1 (float or normalized integer), COLOR_0 (VEC3/VEC4 of float or normalized
// unsigned byte/short; Vertex::color); metal/rough materials with all five textures, texCoord
// sets, samplers, factors, doubleSided, alphaMode MASK + alphaCutoff; KHR_texture_transform
// (TextureRef::uv_*), KHR_materials_emissive_strength. BLEND is imported as opaque with one
// warning per material. KHR_materials_pbrSpecularGlossiness is approximated (diffuse -> base
// color, roughness = 1 - glossiness, metallic = 0, with a warning); KHR_mesh_quantization is
// supported by the generic accessor reader. Everything else is skipped with one warning per file
// naming it (every other extension, wherever it is used; other attributes; morph targets, skins,
// animations: docs/gltf.md); an extension the loader cannot honour in extensionsRequired is an
// error naming it.
//
// Validation is strict and atomic: on any error a SceneError naming the file and the element
// (`accessors[3].byteOffset`, `nodes[7].children`) is thrown and `scene` is left unchanged.
// Hostile files are expected: the GLB container, every offset, length, count and stride are
// checked against the buffer they index with overflow-safe arithmetic (by this loader, whatever
// tinygltf checks), the node graph is walked without recursion, and the budgets of GltfLimits
// bound the memory and time a file can ask for (docs/scene-format.md, "glTF budgets").
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "halfvec/scene/scene.hpp"
#include "halfvec/scene/scene_error.hpp"

namespace hv {

// Budgets per glTF file. A file that exceeds one is rejected with an error naming the element
// where it went over and the limit. The defaults allow models far larger than the samples (the
// 1.04M-triangle dense_geometry scene, 4K textures) while keeping a hostile file to a few GB of
// memory and a few seconds: about 1.2 GB of vertices (72 bytes each), 2 GB of RGBA8 images (twice,
// while decoding), node instances bounded so that a small file reusing nodes cannot expand into
// billions of objects.
struct GltfLimits {
  uint64_t max_file_bytes = uint64_t(1) << 31;    // the .gltf/.glb and each external buffer, image
  int max_json_depth = 64;                        // nesting of JSON arrays and objects
  int max_node_depth = 1024;                      // longest root-to-leaf node chain
  uint64_t max_node_instances = 1u << 20;         // nodes visited, counting every reuse
  uint64_t max_vertices = 1u << 24;               // all primitives, after flat-normal expansion
  uint64_t max_triangles = 1u << 24;              // all primitives, each counted once
  uint64_t max_instanced_triangles = 1u << 28;    // triangles of every object, instances included
  int max_image_side = 16384;                     // width and height of one image
  uint64_t max_image_pixels = uint64_t(1) << 28;  // all images of the file together
};

// A camera node of a glTF file (glTF 2.0 section 3.10): it looks down its local -Z with +Y up.
struct GltfCamera {
  std::string name;
  glm::mat4 world{1.0f};  // `transform` * the node's world matrix
  bool perspective = true;
  float yfov_rad = 0.7853982f;  // perspective only
  float znear = 0.05f;
  float zfar = 0.0f;  // 0 = infinite
};

struct GltfOptions {
  // >= 0: every imported primitive uses scene.materials[material_override] and no glTF
  // materials or images are imported.
  int material_override = -1;
  // Prefix for the names of created objects (defaults to the file's stem).
  std::string name_prefix;
  // Warnings go here if set, else to stderr.
  std::vector<std::string>* warnings = nullptr;
  GltfLimits limits;
  // Camera nodes go here, in the order they are visited (depth first from the scene's roots).
  std::vector<GltfCamera>* cameras = nullptr;
  // KHR_lights_punctual point and spot lights go here if set, else to scene.lights
  // (docs/gltf.md, "Lights").
  std::vector<Light>* lights = nullptr;
};

// The range R given to a KHR_lights_punctual light without one (glTF: infinite): where the
// brightest channel's I / d^2 falls to 0.01, within [0.01 m, 1e4 m] (docs/gltf.md, "Lights").
float gltfInfiniteRange(const glm::vec3& color, float intensity);

// Appends the meshes, materials, images and objects (one per node with a mesh, transform =
// `transform` * node's world matrix) of the glTF file at `path` to `scene`.
void loadGltf(const std::string& path, const glm::mat4& transform, Scene& scene,
              const GltfOptions& options = {});

// The same from the file's bytes (`binary`: GLB, else JSON glTF); `name` is used in messages and
// its folder resolves relative URIs. For fuzzers and tests.
void loadGltfFromMemory(const uint8_t* bytes, size_t size, bool binary, const std::string& name,
                        const glm::mat4& transform, Scene& scene, const GltfOptions& options = {});

}  // namespace hv
