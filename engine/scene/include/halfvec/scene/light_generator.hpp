// Random lights: the one generator behind scene files' "light_generators"
// (docs/scene-format.md) and the viewer's "Generate random lights", so the same parameters give
// the same lights in both, on every platform (no std distribution, whose output the standard
// leaves to the implementation).
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "halfvec/scene/scene.hpp"

namespace hv {

enum class LightColorMode : uint8_t { White, RandomHue, Fixed };

// Parameters as a scene file's generator states them (defaults are the file format's). Ranges are
// [lo, hi]; each light draws its own value from each. The caller validates them (the loader with
// path-precise errors): weights >= 0 with a positive sum, volume_min <= volume_max.
struct LightGeneratorParams {
  int count = 64;
  uint64_t seed = 1;
  glm::vec3 weights{1.0f};  // point, sphere, tube
  glm::vec3 volume_min{-5.0f, 0.2f, -5.0f}, volume_max{5.0f, 3.0f, 5.0f};
  glm::vec2 intensity{1.0f, 5.0f};
  glm::vec2 radius{0.02f, 0.1f};  // sphere and tube
  glm::vec2 length{0.2f, 1.0f};   // tube
  glm::vec2 range{1.0f, 3.0f};
  LightColorMode color_mode = LightColorMode::RandomHue;
  glm::vec3 color{1.0f};    // Fixed
  float saturation = 0.7f;  // RandomHue: mix of white and a fully saturated hue
};

// `p.count` lights, appended to `out`.
void generateLights(const LightGeneratorParams& p, std::vector<Light>& out);

}  // namespace hv
