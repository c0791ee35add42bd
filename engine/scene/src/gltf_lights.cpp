// KHR_lights_punctual: the point, spot and directional lights of the nodes (docs/gltf.md,
// "Lights"). The engine's units and the conversion: docs/lights.md, "Spot lights" and "glTF
// lights".
#include <algorithm>
#include <cmath>

#include "gltf_import.hpp"
#include "halfvec/scene/enums.hpp"
#include "halfvec/scene/scene_loader.hpp"

namespace hv {

namespace {

// An undefined range is infinite in glTF; the engine's window needs a finite R. The rule: the
// distance at which the brightest channel's inverse-square irradiance I / d^2 falls to
// kGltfRangeIrradiance (W/m^2 per unit color in the engine's units: a white Lambertian surface
// lit by it shows radiance 0.01 / pi), within [0.01 m, 1e4 m].
constexpr float kGltfRangeIrradiance = 0.01f;

}  // namespace

float gltfInfiniteRange(const glm::vec3& color, float intensity) {
  const float peak = intensity * std::max({color.x, color.y, color.z});
  return std::clamp(std::sqrt(std::max(peak, 0.0f) / kGltfRangeIrradiance), 0.01f, 1e4f);
}

}  // namespace hv

namespace hv::gltf {

namespace {
constexpr double kHalfPi = 1.5707963267948966;
}  // namespace

// The light a node holds (its extensions.KHR_lights_punctual.light), placed by the node's world
// transform: position its origin, a spot's or a directional light's direction its local -Z
// (KHR_lights_punctual, "Adding Light Instances to Nodes").
void Importer::importNodeLight(const tinygltf::Node& n, const glm::mat4& world,
                               const std::string& el) {
  const auto ext = n.extensions.find("KHR_lights_punctual");
  if (ext == n.extensions.end()) return;
  const std::string lel = el + ".extensions.KHR_lights_punctual";
  const tinygltf::Value& v = ext->second;
  if (!v.IsObject() || !v.Get("light").IsInt()) fail(lel + ".light", "expected a light index");
  const int index = v.Get("light").GetNumberAsInt();
  if (index < 0 || size_t(index) >= m_.lights.size()) {
    fail(lel + ".light", "index " + std::to_string(index) + " out of range (" +
                             std::to_string(m_.lights.size()) + " lights)");
  }
  const tinygltf::Light& g = m_.lights[size_t(index)];
  const std::string gel = "extensions.KHR_lights_punctual.lights[" + std::to_string(index) + "]";
  if (g.type != "point" && g.type != "spot" && g.type != "directional") {
    fail(gel + ".type", "expected \"point\", \"spot\" or \"directional\", got \"" + g.type + "\"");
  }
  if (lights.size() >= kMaxSceneLights) {
    fail(lel,
         "more than " + std::to_string(kMaxSceneLights) + " light instances (kMaxSceneLights)");
  }
  Light l;
  l.type = g.type == "spot"          ? LightType::Spot
           : g.type == "directional" ? LightType::Directional
                                     : LightType::Point;
  l.position = glm::vec3(world[3]);
  if (!g.color.empty()) {
    if (g.color.size() != 3) fail(gel + ".color", "expected 3 numbers");
    for (int k = 0; k < 3; ++k) {
      l.color[k] = finite(g.color[size_t(k)], gel + ".color");
      if (l.color[k] < 0.0f) fail(gel + ".color", "expected values >= 0");
    }
  }
  // Candela (lm/sr) to the engine's I, and lux (lm/m^2) of a directional light to its E, one to
  // one (docs/lights.md, "glTF lights").
  l.intensity = finite(g.intensity, gel + ".intensity");
  if (l.intensity < 0.0f) fail(gel + ".intensity", "expected a value >= 0");
  if (l.type != LightType::Point) {
    // A spot's or a directional light's direction: the node's local -Z, normalized (the node's
    // scale does not change it).
    const glm::vec3 d = glm::mat3(world) * glm::vec3(0.0f, 0.0f, -1.0f);
    if (!(glm::length(d) > 1e-20f)) {
      const std::string type(toString(l.type));
      warnOnce(type + " singular", lel + ": a singular transform gives the " + type +
                                       " light no direction; not imported (nor any other such " +
                                       "light)");
      return;
    }
    l.direction = glm::normalize(d);
  }
  if (l.type == LightType::Directional) {
    // The extension's directional light is a single direction (range does not apply to it):
    // angular diameter 0, as the glTF viewers shade it; at most kMaxDirectionalLights of them.
    const auto directional = [](const Light& x) { return x.type == LightType::Directional; };
    if (size_t(std::count_if(lights.begin(), lights.end(), directional)) >= kMaxDirectionalLights) {
      warnOnce("directional budget", lel + ": more than " + std::to_string(kMaxDirectionalLights) +
                                         " directional light instances (kMaxDirectionalLights); "
                                         "this one and any further ones not imported");
      return;
    }
    l.angular_diameter = 0.0f;
    lights.push_back(l);
    return;
  }
  const float range = finite(g.range, gel + ".range");
  if (range < 0.0f) fail(gel + ".range", "expected a value > 0 (or none: infinite)");
  l.range = range > 0.0f ? std::max(range, 1e-4f) : gltfInfiniteRange(l.color, l.intensity);
  if (l.type == LightType::Spot) {
    const double inner = g.spot.innerConeAngle, outer = g.spot.outerConeAngle;
    if (!(inner >= 0.0 && inner < outer && outer <= kHalfPi)) {
      fail(gel + ".spot", "expected 0 <= innerConeAngle < outerConeAngle <= pi/2, got " +
                              fmtFloat(float(inner)) + " and " + fmtFloat(float(outer)));
    }
    l.inner_cone_angle = float(inner);
    l.outer_cone_angle = float(outer);
  }
  lights.push_back(l);
}

}  // namespace hv::gltf
