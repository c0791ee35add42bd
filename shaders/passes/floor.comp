#version 450 core
// The floor pass (render::DebugOptions::floor_pass, `halfvec bench --frame`): the least any
// full-screen pass after the G-buffer costs, reading the 16 B/px G-buffer and writing one RGBA16F
// texel per pixel, in HV_TILE_SIZE square workgroups like the ambient pass. The bench times it
// in the same frames as the real passes and reports each pass as a multiple of it, a yardstick
// that the load of a shared machine scales alike. Every fetched channel reaches the store, so no
// fetch can be compiled away; the target is a scratch image, not the frame's.
#include "../common/frame.glsl"

layout(local_size_x = HV_TILE_SIZE, local_size_y = HV_TILE_SIZE) in;

layout(binding = HV_UNIT_BASE_CAVITY) uniform sampler2D t_base_cavity;
layout(binding = HV_UNIT_MATERIAL) uniform sampler2D t_material;
layout(binding = HV_UNIT_NORMAL) uniform sampler2D t_normal;
layout(binding = HV_UNIT_DEPTH) uniform sampler2D t_depth;
layout(rgba16f, binding = HV_IMAGE_FLOOR) uniform writeonly image2D i_floor;

void main() {
  ivec2 px = ivec2(gl_GlobalInvocationID.xy);
  if (px.x >= int(u_viewport.x) || px.y >= int(u_viewport.y)) return;
  vec4 bc = texelFetch(t_base_cavity, px, 0);
  vec4 mat = texelFetch(t_material, px, 0);
  vec2 n = texelFetch(t_normal, px, 0).xy;
  float d = texelFetch(t_depth, px, 0).r;
  imageStore(i_floor, px, vec4(bc.rgb + mat.rgb, bc.a + mat.a + n.x + n.y + d));
}
