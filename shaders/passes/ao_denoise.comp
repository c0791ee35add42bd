#version 450 core
// The AO pass's second half: an edge-keeping spatial denoise of the raw GTAO (gtao.comp). Each
// AO texel averages the 4x4 block around it, which holds each of the 16 slice rotations and step
// offsets of gtaoNoise once (Jimenez et al. 2016, section 7), weighting a neighbour down to 0 as
// its view distance departs from the centre's by 1/kDepthTolerance of that distance, so that a
// silhouette does not bleed the occlusion of one surface onto the one behind it. Out (HV_IMAGE_AO):
// visibility, view distance, bent normal (world, octahedral), as the raw target.
#include "../common/frame.glsl"
#include "../common/gbuffer.glsl"

layout(local_size_x = HV_TILE_SIZE, local_size_y = HV_TILE_SIZE) in;

layout(binding = HV_UNIT_AO) uniform sampler2D t_raw_ao;
layout(rgba16f, binding = HV_IMAGE_AO) uniform writeonly image2D i_ao;
layout(location = HV_LOC_AO_PARAMS) uniform vec4 u_ao;  // as gtao.comp

// Relative depth difference at which a neighbour's weight reaches 0: 5% of the distance keeps a
// sloped floor's neighbours (at most a few texels of slope) and drops an object in front.
const float kDepthTolerance = 20.0;

void main() {
  ivec2 q = ivec2(gl_GlobalInvocationID.xy);
  ivec2 size = ivec2(u_ao.zw);
  if (q.x >= size.x || q.y >= size.y) return;
  vec4 c = texelFetch(t_raw_ao, q, 0);
  if (c.y <= 0.0) {  // background
    imageStore(i_ao, q, c);
    return;
  }
  float vis = 0.0;
  vec3 bent = vec3(0.0);
  float wsum = 0.0;
  for (int y = -1; y <= 2; ++y) {
    for (int x = -1; x <= 2; ++x) {
      vec4 s = texelFetch(t_raw_ao, clamp(q + ivec2(x, y), ivec2(0), size - 1), 0);
      float w = s.y > 0.0 ? clamp(1.0 - abs(s.y - c.y) / c.y * kDepthTolerance, 0.0, 1.0) : 0.0;
      vis += s.x * w;
      bent += octDecode(s.zw) * w;
      wsum += w;
    }
  }
  // The centre always weighs 1, so wsum >= 1.
  vec3 B = dot(bent, bent) > 1e-12 ? normalize(bent) : octDecode(c.zw);
  imageStore(i_ao, q, vec4(vis / wsum, c.y, octEncode(B)));
}
