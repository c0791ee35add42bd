// C++ mirror of shaders/common/frame.glsl's FrameBlock (std140) and material.glsl's GpuMaterial.
#pragma once

#include <cstdint>

#include <glm/glm.hpp>

#include "halfvec/scene/scene.hpp"
#include "halfvec/shaders/common/bindings.glsl"

namespace hv::render {

constexpr int kTileSize = HV_TILE_SIZE;      // culling tile width (shaders/common/bindings.glsl)
constexpr int kTileHeight = HV_TILE_HEIGHT;  // culling tile height
// Tiles per workgroup (a column) of the light pass.
constexpr int kLightGroupTiles = HV_LIGHT_GROUP_TILES;

// FrameBlock::counts.w bits (HV_FRAME_* in bindings.glsl), set for the per-term debug views.
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
  glm::uvec4 viewport;    // width, height, tiles x, tiles y
  glm::uvec4 counts;      // lights, tile-index capacity, debug view, FrameFlag bits
  glm::vec4 output;       // exposure, dither, environment intensity, environment rotation (rad)
  glm::vec4 near_params;  // near plane
};
static_assert(sizeof(FrameBlock) == 4 * 64 + 5 * 16, "FrameBlock must match std140 layout");

struct alignas(16) GpuMaterial {
  glm::vec4 base_color;
  glm::vec4 params;  // metallic, roughness, cavity, alpha cutoff
  glm::vec4 emissive;
  glm::vec4 extra;  // normal scale, occlusion strength, emissive texcoord set
  glm::uvec4 texcoords;
  glm::uvec4 flags;        // texture bits, alpha mode, shading model, unused
  glm::vec4 uv_linear[5];  // KHR_texture_transform per texture (material.glsl)
  glm::vec4 uv_offset[5];
};
static_assert(sizeof(GpuMaterial) == 256, "GpuMaterial must match std140 layout");

enum MaterialFlag : uint32_t {
  kBaseColorTex = 1,
  kMetalRoughTex = 2,
  kNormalTex = 4,
  kOcclusionTex = 8,
  kEmissiveTex = 16,
  kVertexColor = 32,   // HV_MAT_VERTEX_COLOR_BIT
  kTexTransform = 64,  // HV_MAT_TEX_TRANSFORM_BIT
};

GpuMaterial packMaterial(const Material& m);

// Reversed-Z infinite perspective: depth = near / view distance; 1 at the near plane, 0 at
// infinity. Paired with glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE) and GL_GREATER.
glm::mat4 reversedInfinitePerspective(float fov_y_rad, float aspect, float near_plane);

FrameBlock makeFrameBlock(const Scene& scene, int width, int height);

}  // namespace hv::render
