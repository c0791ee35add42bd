// glTF 2.0 import (.gltf with external or embedded buffers, .glb) into a Scene.
//
// Supported: the node hierarchy (matrix or TRS), every primitive of every mesh; TRIANGLES,
// TRIANGLE_STRIP and TRIANGLE_FAN (strips and fans converted to lists; POINTS and LINES are
// validated, then skipped with a warning); 8/16/32-bit indices and non-indexed primitives;
// POSITION, NORMAL (flat normals generated when missing), TANGENT (generated, tangents.hpp, when
// missing), TEXCOORD_0/1 (float or normalized integer); metal/rough materials with all five
// textures, texCoord sets, samplers, factors, doubleSided, alphaMode MASK + alphaCutoff. BLEND is
// imported as opaque with one warning per material. KHR_materials_pbrSpecularGlossiness is
// approximated (diffuse -> base color, roughness = 1 - glossiness, metallic = 0, with a warning);
// KHR_mesh_quantization is supported by the generic accessor reader. Any other extension in
// extensionsRequired is an error.
//
// Validation is strict and atomic: on any error a SceneError naming the file and the element is
// thrown and `scene` is left unchanged.
#pragma once

#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "halfvec/scene/scene.hpp"
#include "halfvec/scene/scene_error.hpp"

namespace hv {

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
  // Camera nodes go here, in the order they are visited (depth first from the scene's roots).
  std::vector<GltfCamera>* cameras = nullptr;
};

// Appends the meshes, materials, images and objects (one per node with a mesh, transform =
// `transform` * node's world matrix) of the glTF file at `path` to `scene`.
void loadGltf(const std::string& path, const glm::mat4& transform, Scene& scene,
              const GltfOptions& options = {});

}  // namespace hv
