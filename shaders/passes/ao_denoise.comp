#version 450 core
// The AO pass's second half: an edge-keeping spatial denoise of the raw GTAO (gtao.comp). Each
// AO texel averages a 4x4 block of texels, which holds each of the 16 slice rotations and step
// offsets of gtaoNoise once (Jimenez et al. 2016, section 7; at the image's border the block
// shifts inside rather than repeating texels), weighting a neighbour down to 0 as its position
// leaves the centre's tangent plane by 1/kPlaneTolerance of the view distance, so that a silhouette
// does not bleed the occlusion of one surface onto the one behind it. A plane's neighbours all
// count however grazing the view (a test on view distance alone dropped the rows above and below
// there, and with them most of the 16 rotations). Out (HV_IMAGE_AO): visibility, view distance,
// bent normal (world, octahedral), as the raw target.
#include "../common/frame.glsl"
#include "../common/gbuffer.glsl"

layout(local_size_x = HV_TILE_SIZE, local_size_y = HV_TILE_SIZE) in;

layout(binding = HV_UNIT_NORMAL) uniform sampler2D t_normal;
layout(binding = HV_UNIT_AO) uniform sampler2D t_raw_ao;
layout(rgba16f, binding = HV_IMAGE_AO) uniform writeonly image2D i_ao;
layout(location = HV_LOC_AO_PARAMS) uniform vec4 u_ao;  // as gtao.comp

// Distance from the centre's tangent plane, over the view distance, at which a neighbour's weight
// reaches 0: 2%.
const float kPlaneTolerance = 50.0;

// View-space position of AO texel q at view distance z (its pixel: q x scale, as gtao.comp).
vec3 texelPosition(ivec2 q, float z) {
  vec2 ndc = (vec2(q) * u_ao.y + 0.5) / vec2(u_viewport.xy) * 2.0 - 1.0;
  return vec3(ndc.x * z / u_proj[0][0], ndc.y * z / u_proj[1][1], -z);
}

void main() {
  ivec2 q = ivec2(gl_GlobalInvocationID.xy);
  ivec2 size = ivec2(u_ao.zw);
  if (q.x >= size.x || q.y >= size.y) return;
  vec4 c = texelFetch(t_raw_ao, q, 0);
  if (c.y <= 0.0) {  // background
    imageStore(i_ao, q, c);
    return;
  }
  vec3 Pc = texelPosition(q, c.y);
  vec3 Nc = normalize(mat3(u_view) * octDecode(texelFetch(t_normal, q * int(u_ao.y), 0).xy));
  ivec2 lo = clamp(q - 1, ivec2(0), max(size - 4, ivec2(0)));
  float vis = 0.0;
  vec3 bent = vec3(0.0);
  float wsum = 0.0;
  for (int y = 0; y < 4; ++y) {
    for (int x = 0; x < 4; ++x) {
      ivec2 t = min(lo + ivec2(x, y), size - 1);
      vec4 s = texelFetch(t_raw_ao, t, 0);
      float plane = abs(dot(Nc, texelPosition(t, s.y) - Pc)) / c.y;
      float w = s.y > 0.0 ? clamp(1.0 - plane * kPlaneTolerance, 0.0, 1.0) : 0.0;
      vis += s.x * w;
      bent += octDecode(s.zw) * w;
      wsum += w;
    }
  }
  // The centre is in its own block with weight 1, so wsum >= 1.
  vec3 B = dot(bent, bent) > 1e-12 ? normalize(bent) : octDecode(c.zw);
  imageStore(i_ao, q, vec4(clamp(vis / wsum, 0.0, 1.0), c.y, octEncode(B)));
}
