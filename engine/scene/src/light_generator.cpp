#include "halfvec/scene/light_generator.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace hv {

namespace {

// splitmix64 (Steele, Lea & Flood 2014): tiny and platform-independent.
struct Rng {
  uint64_t s;
  uint64_t next() {
    uint64_t z = (s += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  float uniform() { return float(next() >> 40) * (1.0f / 16777216.0f); }  // [0, 1)
  float in(glm::vec2 r) { return r.x + (r.y - r.x) * uniform(); }
};

glm::vec3 hueToRgb(float h) {  // fully saturated HSV hue in [0, 1) -> linear RGB, value 1
  const float r = std::abs(h * 6.0f - 3.0f) - 1.0f;
  const float g = 2.0f - std::abs(h * 6.0f - 2.0f);
  const float b = 2.0f - std::abs(h * 6.0f - 4.0f);
  return glm::clamp(glm::vec3(r, g, b), 0.0f, 1.0f);
}

}  // namespace

void generateLights(const LightGeneratorParams& p, std::vector<Light>& out) {
  Rng rng{p.seed * 0x2545F4914F6CDD1Dull + 1};
  const glm::vec3 w = p.weights;
  const float wsum = w.x + w.y + w.z;
  for (int i = 0; i < p.count; ++i) {
    Light l;
    // Every light draws the same numbers whatever its type, so changing the mix keeps positions.
    const float pick = rng.uniform() * wsum;
    l.type = pick < w.x ? LightType::Point : pick < w.x + w.y ? LightType::Sphere : LightType::Tube;
    l.position = glm::vec3(rng.in({p.volume_min.x, p.volume_max.x}),
                           rng.in({p.volume_min.y, p.volume_max.y}),
                           rng.in({p.volume_min.z, p.volume_max.z}));
    l.intensity = rng.in(p.intensity);
    l.range = rng.in(p.range);
    const float r = rng.in(p.radius);
    const float len = rng.in(p.length);
    // Uniform on the sphere: z uniform in [-1, 1], phi uniform (Archimedes' hat-box theorem).
    const float z = rng.uniform() * 2.0f - 1.0f,
                phi = rng.uniform() * 2.0f * std::numbers::pi_v<float>;
    const float s = std::sqrt(std::max(0.0f, 1.0f - z * z));
    const glm::vec3 axis(s * std::cos(phi), z, s * std::sin(phi));
    const float hue = rng.uniform();
    if (l.type != LightType::Point) l.radius = r;
    if (l.type == LightType::Tube) {
      l.length = len;
      l.axis = axis;
    }
    switch (p.color_mode) {
      case LightColorMode::White:
        l.color = glm::vec3(1.0f);
        break;
      case LightColorMode::Fixed:
        l.color = p.color;
        break;
      case LightColorMode::RandomHue:
        l.color = glm::mix(glm::vec3(1.0f), hueToRgb(hue), p.saturation);
        break;
    }
    out.push_back(l);
  }
}

}  // namespace hv
