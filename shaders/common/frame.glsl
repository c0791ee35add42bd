// Per-frame uniforms (binding HV_UBO_FRAME): the block's members are listed once, in
// frame_block.glsl, for this declaration (as u_<name>) and the C++ struct
// (halfvec/render/frame_data.hpp, FrameBlock). The resource slots every pass agrees on are in
// bindings.glsl.
#ifndef HV_FRAME_GLSL
#define HV_FRAME_GLSL

#include "bindings.glsl"

#define HV_BLOCK_MEMBER(type, name) type u_##name;
layout(std140, binding = HV_UBO_FRAME) uniform FrameBlock {
#include "frame_block.glsl"
};
#undef HV_BLOCK_MEMBER

// Largest finite half float: the RGBA16F accumulation target turns anything above into Inf, so the
// passes clamp what they store (a 1e6-intensity light next to a surface must not write Inf).
#define HV_HDR_MAX 65504.0

#endif
