// libFuzzer harness: glTF (JSON) and GLB files (GLB when the input starts with "glTF"). The
// budgets are lowered 16-fold so one input stays small under the sanitizers; the code that
// enforces them is the same.
#include <cstdint>
#include <cstring>

#include "halfvec/scene/gltf_loader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  hv::GltfOptions opt;
  std::vector<std::string> warnings;
  opt.warnings = &warnings;
  opt.limits.max_vertices >>= 4;
  opt.limits.max_triangles >>= 4;
  opt.limits.max_instanced_triangles >>= 4;
  opt.limits.max_node_instances >>= 4;
  opt.limits.max_image_pixels >>= 4;
  opt.limits.max_image_side = 4096;
  const bool binary = size >= 4 && std::memcmp(data, "glTF", 4) == 0;
  hv::Scene scene;
  try {
    hv::loadGltfFromMemory(data, size, binary, "/nonexistent-hv-fuzz/model.gltf", glm::mat4(1.0f),
                           scene, opt);
  } catch (const hv::SceneError&) {
  }
  return 0;
}
