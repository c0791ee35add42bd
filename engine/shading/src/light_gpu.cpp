#include "halfvec/shading/light_gpu.hpp"

#include <algorithm>
#include <cmath>

namespace hv {

static_assert(int(LightType::Point) == HV_LIGHT_POINT &&
                  int(LightType::Sphere) == HV_LIGHT_SPHERE &&
                  int(LightType::Tube) == HV_LIGHT_TUBE,
              "GpuLight.type holds hv::LightType (gpu_records.glsl)");

// A directional light (HV_LIGHT_DIRECTIONAL, gpu_records.glsl): the unit direction toward it, the
// sine of the disk's angular radius, the color times the illuminance. No range: the window and the
// culling radius are 0 (the culling does not bin it).
GpuLight packDirectional(const Light& light) {
  GpuLight g{};
  glm::vec3 dir = light.direction;
  const float dir_len = glm::length(dir);
  dir = (std::isfinite(dir_len) && dir_len > 1e-20f) ? dir / dir_len : glm::vec3(0, -1, 0);
  const float half_angle = 0.5f * std::clamp(light.angular_diameter, 0.0f, kMaxAngularDiameter);
  g.position_radius = glm::vec4(-dir, std::sin(half_angle));
  g.color_inv_range = glm::vec4(light.color * light.intensity, 0.0f);
  g.axis_length = glm::vec4(0.0f);
  g.range = 0.0f;
  g.type = HV_LIGHT_DIRECTIONAL;
  g.cull_radius = 0.0f;
  g.shadow_cube = 0;
  return g;
}

GpuLight packLight(const Light& light) {
  if (light.type == LightType::Directional) return packDirectional(light);
  GpuLight g{};
  const LightType shape = lightShape(light);  // a spot: its point or sphere
  float radius = shape == LightType::Point ? 0.0f : std::max(light.radius, 0.0f);
  float len = light.type == LightType::Tube ? std::max(light.length, 0.0f) : 0.0f;
  glm::vec3 axis = light.axis;
  float axis_len = glm::length(axis);
  axis = (std::isfinite(axis_len) && axis_len > 1e-20f) ? axis / axis_len : glm::vec3(1, 0, 0);
  // 1e-4 m: a smaller (or zero/negative) range would make 1/R infinite; such a light is dark.
  float range = std::max(light.range, 1e-4f);
  g.position_radius = glm::vec4(light.position, radius);
  // 1/R shares the color's texel: what a point or sphere light reads is 2 of the 4 texels.
  g.color_inv_range = glm::vec4(light.color * light.intensity, 1.0f / range);
  g.axis_length = glm::vec4(axis, len);
  // The eq. 9 window is 0 at distance R from the nearest point of the segment (tubes) or from
  // the center (points, spheres); a tube's segment reaches len/2 from its center.
  g.range = range;
  g.type = static_cast<unsigned>(shape);
  g.cull_radius = range + 0.5f * len;
  if (light.type == LightType::Spot) {
    // The cone replaces the axis (spot.glsl); angles clamped to what the loader accepts.
    glm::vec3 dir = light.direction;
    const float dir_len = glm::length(dir);
    dir = (std::isfinite(dir_len) && dir_len > 1e-20f) ? dir / dir_len : glm::vec3(0, -1, 0);
    const float outer = std::clamp(light.outer_cone_angle, 0.0f, 1.5707963f);
    const float inner = std::clamp(light.inner_cone_angle, 0.0f, outer);
    g.axis_length = glsl::spotCone(dir, std::cos(inner), std::cos(outer));
    g.type |= HV_LIGHT_SPOT_FLAG;
  }
  g.shadow_cube = 0;  // written by the shadow pass
  return g;
}

std::vector<std::pair<std::string, std::string>> lightTypeDefines(
    const std::vector<Light>& lights) {
  bool has[5] = {false, false, false, false, false};
  for (const Light& l : lights) {
    has[static_cast<int>(lightShape(l))] = true;  // Directional: index 4
    has[3] = has[3] || l.type == LightType::Spot;
  }
  auto flag = [](bool b) { return std::string(b ? "1" : "0"); };
  return {{"HV_HAS_POINT_LIGHTS", flag(has[0])},
          {"HV_HAS_SPHERE_LIGHTS", flag(has[1])},
          {"HV_HAS_TUBE_LIGHTS", flag(has[2])},
          {"HV_HAS_SPOT_LIGHTS", flag(has[3])},
          {"HV_HAS_DIRECTIONAL_LIGHTS", flag(has[4])}};
}

}  // namespace hv
