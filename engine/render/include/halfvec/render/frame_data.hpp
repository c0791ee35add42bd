// FrameBlock (std140), declared from shaders/common/frame_block.glsl, the member list frame.glsl
// declares the block from, and the packing of materials into hv::GpuMaterial
// (shaders/common/gpu_records.glsl).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include <glm/glm.hpp>

#include "halfvec/scene/scene.hpp"
#include "halfvec/shading/gpu_records.hpp"
#include "halfvec/shaders/common/bindings.glsl"

namespace hv::render {

constexpr int kTileSize = HV_TILE_SIZE;      // culling tile width (shaders/common/bindings.glsl)
constexpr int kTileHeight = HV_TILE_HEIGHT;  // culling tile height
// Tiles per workgroup (a column) of the light pass.
constexpr int kLightGroupTiles = HV_LIGHT_GROUP_TILES;

// FrameBlock::frame_flags bits (HV_FRAME_* in bindings.glsl), set for the per-term debug views.
enum FrameFlag : uint32_t {
  kFrameNoBackground = HV_FRAME_NO_BACKGROUND,  // the ambient pass writes 0 on background pixels
  kFrameNoEmissive = HV_FRAME_NO_EMISSIVE,      // the G-buffer pass leaves the HDR target at 0
};

// The members of shaders/common/frame_block.glsl, the list frame.glsl declares the block from.
struct alignas(16) FrameBlock {
#define HV_BLOCK_MEMBER(type, name) glm::type name;
#include "halfvec/shaders/common/frame_block.glsl"
#undef HV_BLOCK_MEMBER
};
static_assert(sizeof(FrameBlock) == 4 * 64 + 6 * 16, "FrameBlock must match std140 layout");
static_assert(offsetof(FrameBlock, viewport) == 4 * 64 + 16);
static_assert(offsetof(FrameBlock, light_count) == 4 * 64 + 32);
static_assert(offsetof(FrameBlock, frame_flags) == 4 * 64 + 44);
static_assert(offsetof(FrameBlock, output) == 4 * 64 + 48);
static_assert(offsetof(FrameBlock, frame_params) == 4 * 64 + 64);
static_assert(offsetof(FrameBlock, directional_lights) == 4 * 64 + 80);
static_assert(kMaxDirectionalLights == glm::uvec4::length(),
              "FrameBlock::directional_lights holds kMaxDirectionalLights indices");

// The material record: hv::GpuMaterial, declared once for C++ and GLSL (gpu_records.glsl, its
// layout checked in halfvec/shading/gpu_records.hpp). Filled from the scene's material here.
GpuMaterial packMaterial(const Material& m);
// A material's textures in the order of the slots (HV_MAT_SLOT_*, gpu_records.glsl), which are
// also its texture units after HV_UNIT_MATERIAL_TEXTURES (GpuScene binds them so).
std::array<const TextureRef*, HV_MAT_SLOTS> materialTextureSlots(const Material& m);

// Reversed-Z infinite perspective: depth = near / view distance; 1 at the near plane, 0 at
// infinity. Paired with glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE) and GL_GREATER.
glm::mat4 reversedInfinitePerspective(float fov_y_rad, float aspect, float near_plane);

FrameBlock makeFrameBlock(const Scene& scene, int width, int height);

}  // namespace hv::render
