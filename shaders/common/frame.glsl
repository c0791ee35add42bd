// Per-frame uniforms (binding HV_UBO_FRAME); the resource slots every pass agrees on are in
// bindings.glsl. C++ mirror: halfvec/render/frame_data.hpp (FrameBlock), checked by static_asserts
// there. std140: the four uints after u_viewport sit at the offsets of one uvec4 (each scalar is
// 4-byte aligned), so u_output starts on its 16-byte boundary.
#ifndef HV_FRAME_GLSL
#define HV_FRAME_GLSL

#include "bindings.glsl"

layout(std140, binding = HV_UBO_FRAME) uniform FrameBlock {
  mat4 u_view;
  mat4 u_proj;
  mat4 u_view_proj;
  mat4 u_inv_view_proj;
  vec4 u_camera_pos;   // xyz world position
  uvec4 u_viewport;    // width, height, tiles x, tiles y
  uint u_light_count;
  uint u_tile_capacity;  // entries the tile index list holds after its header (light culling)
  uint u_debug_view;     // hv::DebugView (debug_view.frag)
  uint u_frame_flags;    // HV_FRAME_* bits (bindings.glsl)
  vec4 u_output;       // exposure, dither strength, environment intensity, environment rotation (rad)
  vec4 u_near_params;  // near plane, unused...
};

// Largest finite half float: the RGBA16F accumulation target turns anything above into Inf, so the
// passes clamp what they store (a 1e6-intensity light next to a surface must not write Inf).
#define HV_HDR_MAX 65504.0

#endif
