// C++ mirror of the GLSL GpuLight (shaders/common/lights.glsl): one light as the GPU reads it
// from a std430 buffer, and the packing from the scene's hv::Light. Field meaning and units:
// docs/lights.md.
#pragma once

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "halfvec/scene/scene.hpp"
#include "halfvec/shading/shading.hpp"

namespace hv {

// std430 layout: four vec4, 64 bytes, 16-byte aligned (identical in std140).
struct alignas(16) GpuLight {
  glm::vec4 position_radius;  // xyz world position (tube: segment center), w radius (m)
  glm::vec4 color_inv_range;  // rgb color * intensity (W/sr), w 1/R (Karis eq. 9 window)
  glm::vec4 axis_length;      // xyz unit tube axis, w tube length (m); 0 for point/sphere
  glm::vec4 params;           // x range R, y type as float (hv::LightType), z culling radius, w 0
};
static_assert(sizeof(GpuLight) == 64, "GpuLight must match the std430 GLSL struct (64 bytes)");
static_assert(alignof(GpuLight) == 16, "GpuLight array stride must be 16-byte aligned");
static_assert(offsetof(GpuLight, position_radius) == 0);
static_assert(offsetof(GpuLight, color_inv_range) == 16);
static_assert(offsetof(GpuLight, axis_length) == 32);
static_assert(offsetof(GpuLight, params) == 48);
static_assert(sizeof(glsl::GpuLight) == sizeof(GpuLight), "GLSL struct compiled as C++ differs");

// Packs a scene light. Sanitizes what the shader assumes: radius, length >= 0 (radius 0 for
// point lights, length 0 unless tube), unit axis (x if degenerate), range > 0 (1e-4 m minimum
// so 1/R is finite), color = color * intensity.
GpuLight packLight(const Light& light);

// The same record as the shader-side struct, for calling hv::glsl::evaluateLight from C++. Inline
// in the header: glsl::GpuLight sits in the headers' anonymous namespace (internal linkage).
inline glsl::GpuLight toGlsl(const GpuLight& g) {
  glsl::GpuLight r;
  r.position_radius = g.position_radius;
  r.color_inv_range = g.color_inv_range;
  r.axis_length = g.axis_length;
  r.params = g.params;
  return r;
}

// Defines HV_HAS_POINT_LIGHTS / HV_HAS_SPHERE_LIGHTS / HV_HAS_TUBE_LIGHTS ("0"/"1") for the
// light types present, so a scene without tubes compiles no tube code.
std::vector<std::pair<std::string, std::string>> lightTypeDefines(const std::vector<Light>& lights);

}  // namespace hv
