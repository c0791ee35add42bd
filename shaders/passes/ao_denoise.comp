#version 450 core
// The AO pass's second half: an edge-keeping spatial denoise of the raw GTAO (gtao.comp). Each
// AO texel averages a 4x4 block of texels, which holds each of the 16 slice rotations and step
// offsets of gtaoNoise once (Jimenez et al. 2016, section 7; at the image's border the block
// shifts inside rather than repeating texels). The block is read as its four 2x2 quads, one
// bilinear fetch at the corner each quad's texels share (their mean), and a quad is weighted down
// to 0 as its mean position leaves the centre's tangent plane by 1/kPlaneTolerance of the view
// distance, so that a silhouette does not bleed the occlusion of one surface onto the one behind
// it (a quad across the silhouette leaves the plane and drops out whole). The raw target holds
// the inverse view distance, affine in screen space on a plane, so a plane's quad means lie on it
// exactly and all four count however grazing the view (a test on view distance alone dropped the
// rows above and below there, and with them most of the 16 rotations). Out (HV_IMAGE_AO):
// visibility, inverse view distance, bent normal (world, octahedral; with HV_AO_BENT_NORMAL).
#include "../common/frame.glsl"
#include "../common/gbuffer.glsl"

#ifndef HV_AO_BENT_NORMAL
#define HV_AO_BENT_NORMAL 1
#endif

layout(local_size_x = HV_TILE_SIZE, local_size_y = HV_TILE_SIZE) in;

layout(binding = HV_UNIT_NORMAL) uniform sampler2D t_normal;
layout(binding = HV_UNIT_AO) uniform sampler2D t_raw_ao;  // bilinear, clamped to the edge
layout(rgba16f, binding = HV_IMAGE_AO) uniform writeonly image2D i_ao;
layout(location = HV_LOC_AO_PARAMS) uniform vec4 u_ao;  // as gtao.comp

// Distance from the centre's tangent plane, over the view distance, at which a quad's weight
// reaches 0: 2%.
const float kPlaneTolerance = 50.0;

// The view ray of AO texel coordinate q (its pixel: q x scale, as gtao.comp) to view distance 1.
vec3 texelRay(vec2 q) {
  vec2 ndc = (q * u_ao.y + 0.5) / vec2(u_viewport.xy) * 2.0 - 1.0;
  return vec3(ndc.x / u_proj[0][0], ndc.y / u_proj[1][1], -1.0);
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
#if HV_AO_BENT_NORMAL
  vec3 Nc = normalize(mat3(u_view) * octDecode(texelFetch(t_normal, q * int(u_ao.y), 0).xy));
#else
  vec3 Nc = octDecode(c.zw);  // view space (gtao.comp)
#endif
  // A point at inverse distance w on the view ray r lies off the centre's tangent plane by
  // N.r / w - N.Pc, over the view distance 1 / w_c; N.r is affine in the texel coordinate.
  ivec2 lo = clamp(q - 1, ivec2(0), max(size - 4, ivec2(0)));
  float plane_c = dot(Nc, texelRay(vec2(q))) / c.y;
  vec2 corner0 = vec2(lo) + 0.5;  // the mean position of the first quad's texels
  float ray0 = dot(Nc, texelRay(corner0));
  vec2 ray_step = vec2(dot(Nc, texelRay(corner0 + vec2(1.0, 0.0))),
                       dot(Nc, texelRay(corner0 + vec2(0.0, 1.0)))) - ray0;
  float scale = kPlaneTolerance * c.y;
  vec2 inv_size = 1.0 / vec2(size);
  float vis = 0.0;
  float wsum = 0.0;
#if HV_AO_BENT_NORMAL
  vec3 bent = vec3(0.0);
#endif
  for (int y = 0; y < 4; y += 2) {
    for (int x = 0; x < 4; x += 2) {
      vec2 uv = (corner0 + vec2(x, y) + 0.5) * inv_size;
      vec4 s = textureLod(t_raw_ao, uv, 0.0);
      float plane = abs((ray0 + dot(vec2(x, y), ray_step)) / max(s.y, 1e-30) - plane_c) * scale;
      float w = clamp(1.0 - plane, 0.0, 1.0);
      vis += s.x * w;
      wsum += w;
#if HV_AO_BENT_NORMAL
      // The quad's four bent normals, decoded one by one: a mean of octahedral codes is not the
      // code of the mean direction where the codes straddle the folded half.
      vec4 bx = textureGather(t_raw_ao, uv, 2);
      vec4 by = textureGather(t_raw_ao, uv, 3);
      vec3 quad = vec3(0.0);
      for (int k = 0; k < 4; ++k) quad += octDecode(vec2(bx[k], by[k]));
      bent += quad * w;
#endif
    }
  }
  // A lone texel whose quads all leave its plane (a thin sliver) keeps its own raw value.
  vis = wsum > 1e-4 ? vis / wsum : c.x;
#if HV_AO_BENT_NORMAL
  vec3 B = dot(bent, bent) > 1e-12 ? normalize(bent) : octDecode(c.zw);
  imageStore(i_ao, q, vec4(clamp(vis, 0.0, 1.0), c.y, octEncode(B)));
#else
  imageStore(i_ao, q, vec4(clamp(vis, 0.0, 1.0), c.y, 0.0, 0.0));
#endif
}
