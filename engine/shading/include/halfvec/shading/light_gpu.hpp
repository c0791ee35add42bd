// The packing of the scene's hv::Light into GpuLight, the record the shaders read from a std430
// buffer (declared once for C++ and GLSL: shaders/common/gpu_records.glsl). Field meaning and
// units: docs/lights.md.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "halfvec/scene/scene.hpp"
#include "halfvec/shading/gpu_records.hpp"
#include "halfvec/shading/shading.hpp"

namespace hv {

// Packs a scene light. Sanitizes what the shader assumes: radius, length >= 0 (radius 0 for
// point lights and point spots, length 0 unless tube), unit axis (x if degenerate), range > 0
// (1e-4 m minimum so 1/R is finite), color = color * intensity. A spot is packed as its shape
// (lightShape) with HV_LIGHT_SPOT_FLAG and its cone (spotCone: unit direction, -y if degenerate;
// angles clamped to 0 <= inner <= outer <= pi/2) in axis_length.
GpuLight packLight(const Light& light);

// The record the shaders read, for calling hv::glsl::evaluateLight: the same type since
// GpuLight is declared once (gpu_records.glsl); kept for the callers written before.
inline const GpuLight& toGlsl(const GpuLight& g) {
  return g;
}

// Defines HV_HAS_POINT_LIGHTS / HV_HAS_SPHERE_LIGHTS / HV_HAS_TUBE_LIGHTS / HV_HAS_SPOT_LIGHTS /
// HV_HAS_DIRECTIONAL_LIGHTS ("0"/"1") for the light shapes present (a spot counts as its shape
// and as a spot), so a scene without tubes compiles no tube code and one without spots no cone.
std::vector<std::pair<std::string, std::string>> lightTypeDefines(const std::vector<Light>& lights);

}  // namespace hv
