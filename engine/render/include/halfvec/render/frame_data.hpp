// C++ mirror of shaders/common/frame.glsl's FrameBlock (std140), and the packing of materials
// into hv::GpuMaterial (shaders/common/gpu_records.glsl).
#pragma once

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

struct alignas(16) FrameBlock {
  glm::mat4 view;
  glm::mat4 proj;
  glm::mat4 view_proj;
  glm::mat4 inv_view_proj;
  glm::vec4 camera_pos;
  glm::uvec4 viewport;  // width, height, tiles x, tiles y
  uint32_t light_count;
  uint32_t tile_capacity;  // entries the tile index list holds after its header
  uint32_t debug_view;     // DebugView
  uint32_t frame_flags;    // FrameFlag bits
  glm::vec4 output;        // exposure, dither, environment intensity, environment rotation (rad)
  glm::vec4 near_params;   // near plane
};
static_assert(sizeof(FrameBlock) == 4 * 64 + 5 * 16, "FrameBlock must match std140 layout");
static_assert(offsetof(FrameBlock, viewport) == 4 * 64 + 16);
static_assert(offsetof(FrameBlock, light_count) == 4 * 64 + 32);
static_assert(offsetof(FrameBlock, frame_flags) == 4 * 64 + 44);
static_assert(offsetof(FrameBlock, output) == 4 * 64 + 48);
static_assert(offsetof(FrameBlock, near_params) == 4 * 64 + 64);

// The material record: hv::GpuMaterial, declared once for C++ and GLSL (gpu_records.glsl, its
// layout checked in halfvec/shading/gpu_records.hpp). Filled from the scene's material here.
GpuMaterial packMaterial(const Material& m);

// Reversed-Z infinite perspective: depth = near / view distance; 1 at the near plane, 0 at
// infinity. Paired with glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE) and GL_GREATER.
glm::mat4 reversedInfinitePerspective(float fov_y_rad, float aspect, float near_plane);

FrameBlock makeFrameBlock(const Scene& scene, int width, int height);

}  // namespace hv::render
