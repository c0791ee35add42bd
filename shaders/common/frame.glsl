// Per-frame uniforms (binding 0) and the resource bindings every pass agrees on.
// C++ mirror: halfvec/render/frame_data.hpp (FrameBlock), checked by static_asserts there.
#ifndef HV_FRAME_GLSL
#define HV_FRAME_GLSL

layout(std140, binding = 0) uniform FrameBlock {
  mat4 u_view;
  mat4 u_proj;
  mat4 u_view_proj;
  mat4 u_inv_view_proj;
  vec4 u_camera_pos;   // xyz world position
  uvec4 u_viewport;    // width, height, tiles x, tiles y
  uvec4 u_counts;      // lights, tile-index capacity, debug view, HV_FRAME_* flags
  vec4 u_output;       // exposure, dither strength, environment intensity, environment rotation (rad)
  vec4 u_near_params;  // near plane, unused...
};

// u_counts.w bits (hv::render::FrameFlag), set for the per-term debug views.
#define HV_FRAME_NO_BACKGROUND 1u  // background pixels stay black (ambient.comp)
#define HV_FRAME_NO_EMISSIVE 2u    // no emissive in the HDR target (C++ masks the G-buffer write)

// Storage-buffer bindings.
#define HV_BINDING_MATERIALS 1
#define HV_BINDING_LIGHTS 2
#define HV_BINDING_TILE_RANGES 4
#define HV_BINDING_TILE_INDICES 5
#define HV_BINDING_TILE_TYPES 6     // per tile: (points, spheres) of its range, tubes follow
#define HV_BINDING_TILE_BOUNDS 7    // culling only: per tile view-space AABB of its surface
#define HV_BINDING_TILE_COUNTERS 3  // culling only: per (tile, light type) count / next slot

// Largest finite half float: the RGBA16F accumulation target turns anything above into Inf, so the
// passes clamp what they store (a 1e6-intensity light next to a surface must not write Inf).
#define HV_HDR_MAX 65504.0

// Light culling tile: HV_TILE_SIZE x HV_TILE_HEIGHT pixels (also the light pass's workgroup;
// the ambient pass uses HV_TILE_SIZE square groups). Why 8 x 4: docs/lights.md "Tiled culling".
#define HV_TILE_SIZE 8
#define HV_TILE_HEIGHT 4
// Tiles per workgroup of the light pass (stacked vertically, each with its own light list): with
// 4 pixels per invocation a tile is 8 invocations, which alone would fill a quarter of a 32-wide
// GPU SIMD unit. 8 tiles = 64 invocations. Neutral on llvmpipe (1, 2, 4, 8: same time, measured).
#define HV_LIGHT_GROUP_TILES 8

#endif
