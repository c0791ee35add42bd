// The GPU records of shaders/common/gpu_records.glsl as C++ types: hv::GpuLight (std430 light
// buffer) and hv::GpuMaterial (std140 material block), the very structs the shaders declare. The
// upload code fills them (hv::packLight, hv::render::packMaterial); the static_asserts below hold
// the C++ layout to the std140/std430 offsets the header states, so a field added on one side only
// does not compile.
#pragma once

#include <cstddef>

#include "halfvec/shading/glsl.hpp"

namespace hv::gpu_records {
using namespace glm;
using uint = unsigned int;
#include "halfvec/shaders/common/gpu_records.glsl"
}  // namespace hv::gpu_records

namespace hv {
using gpu_records::GpuLight;
using gpu_records::GpuMaterial;
using gpu_records::GpuSunShadow;
}  // namespace hv
// The shading headers compiled as C++ (shading.hpp, and the variants compiled again in their own
// namespaces) skip gpu_records.glsl by its include guard and find these through the enclosing
// namespace hv; qualified names such as hv::glsl::GpuLight are the same type.
namespace hv::glsl {
using hv::GpuLight;
using hv::GpuMaterial;
using hv::GpuSunShadow;
}  // namespace hv::glsl

namespace hv::gpu_records {
// std430 (and std140): three vec4, then four scalars filling the fourth 16 bytes (the fourth
// texel of the buffer-texture path). The shadow pass writes shadow_cube alone, at its offset
// (engine/render/src/shadow_pass.cpp).
static_assert(sizeof(GpuSunShadow) == 64);
static_assert(offsetof(GpuSunShadow, right_inv_extent) == 16);
static_assert(offsetof(GpuSunShadow, up_texel) == 32);
static_assert(offsetof(GpuSunShadow, forward_tan) == 48);
static_assert(sizeof(GpuLight) == 64);
static_assert(offsetof(GpuLight, position_radius) == 0);
static_assert(offsetof(GpuLight, color_inv_range) == 16);
static_assert(offsetof(GpuLight, axis_length) == 32);
static_assert(offsetof(GpuLight, range) == 48);
static_assert(offsetof(GpuLight, type) == 52);
static_assert(offsetof(GpuLight, cull_radius) == 56);
static_assert(offsetof(GpuLight, shadow_cube) == 60);
static_assert(sizeof(GpuLight::type) == 4 && sizeof(GpuLight::shadow_cube) == 4);

// std140, the offsets written in gpu_records.glsl.
static_assert(sizeof(GpuMaterial) == 368);
static_assert(offsetof(GpuMaterial, base_color) == 0);
static_assert(offsetof(GpuMaterial, metallic) == 16);
static_assert(offsetof(GpuMaterial, roughness) == 20);
static_assert(offsetof(GpuMaterial, cavity) == 24);
static_assert(offsetof(GpuMaterial, alpha_cutoff) == 28);
static_assert(offsetof(GpuMaterial, emissive) == 32);  // vec3: 16-byte aligned in std140
static_assert(offsetof(GpuMaterial, normal_scale) == 44);
static_assert(offsetof(GpuMaterial, occlusion_strength) == 48);
static_assert(offsetof(GpuMaterial, texture_bits) == 52);
static_assert(offsetof(GpuMaterial, alpha_mode) == 56);
static_assert(offsetof(GpuMaterial, shading_model) == 60);
static_assert(offsetof(GpuMaterial, texcoord_base_color) == 64);
static_assert(offsetof(GpuMaterial, texcoord_metal_rough) == 68);
static_assert(offsetof(GpuMaterial, texcoord_normal) == 72);
static_assert(offsetof(GpuMaterial, texcoord_occlusion) == 76);
static_assert(offsetof(GpuMaterial, texcoord_emissive) == 80);
static_assert(offsetof(GpuMaterial, clearcoat) == 84);
static_assert(offsetof(GpuMaterial, clearcoat_roughness) == 88);
static_assert(offsetof(GpuMaterial, uv_linear) == 96);  // arrays: 16-byte aligned, stride 16
static_assert(offsetof(GpuMaterial, uv_offset) == 96 + 16 * HV_MAT_SLOTS);
static_assert(offsetof(GpuMaterial, texcoord_coat) == 92);
static_assert(offsetof(GpuMaterial, clearcoat_normal_scale) == 96 + 32 * HV_MAT_SLOTS);
}  // namespace hv::gpu_records
