// The G-buffer as data: what the G-buffer pass stored, read back and decoded per pixel. A plain
// CPU type (no OpenGL), so the reference renderer and the evaluation code take it without knowing
// the renderer (render::Renderer::readGBuffer fills it).
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace hv {

// G-buffer contents read back and decoded, per pixel (row 0 = top).
struct GBufferReadback {
  int width = 0, height = 0;
  std::vector<glm::vec3> base_color;  // linear
  std::vector<float> metallic, roughness, cavity, depth;
  std::vector<glm::vec3> normal;
  std::vector<uint32_t> model;
  // The clear coat (gbuffer.glsl's coat target), filled where the scene has one (else empty):
  // layer weight, perceptual roughness and the coat's own normal, 0 and N off clear_coat pixels.
  std::vector<float> clearcoat, clearcoat_roughness;
  std::vector<glm::vec3> coat_normal;
  bool hasCoat() const { return !clearcoat.empty(); }
};

}  // namespace hv
