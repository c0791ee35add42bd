#version 450 core
// Ground-truth-based ambient occlusion (Jimenez, Wu, Pesce, Jarabo 2016, "Practical Real-Time
// Strategies for Accurate Indirect Occlusion"), the AO pass's first half: per AO texel, a horizon
// search in the depth buffer along a few screen directions (slices) within a world-space radius,
// the cosine-weighted visibility of each slice by eq. 10 with the projected normal, and a bent
// normal. Out (raw, HV_IMAGE_AO): visibility, view distance, bent normal (world, octahedral); the
// denoise (ao_denoise.comp) averages the 4x4 rotation pattern away. Math: common/ao.glsl.
#include "../common/frame.glsl"
#include "../common/gbuffer.glsl"
#include "../common/ao.glsl"

// Specialization (the settings table's SettingPass::Ao rows; docs/variants.md).
//   HV_AO_QUALITY: directions x steps (aoDirections / aoSteps).
//   HV_AO_HALF_RESOLUTION 1|0: one AO texel per 2x2 pixels (the pixel at its lower left).
#ifndef HV_AO_QUALITY
#define HV_AO_QUALITY HV_AO_QUALITY_MEDIUM
#endif
#ifndef HV_AO_HALF_RESOLUTION
#define HV_AO_HALF_RESOLUTION 1
#endif

layout(local_size_x = HV_TILE_SIZE, local_size_y = HV_TILE_SIZE) in;

layout(binding = HV_UNIT_NORMAL) uniform sampler2D t_normal;
layout(binding = HV_UNIT_DEPTH) uniform sampler2D t_depth;
layout(rgba16f, binding = HV_IMAGE_AO) uniform writeonly image2D i_ao;
// x: radius (m), y: pixels per AO texel, zw: the AO target's size.
layout(location = HV_LOC_AO_PARAMS) uniform vec4 u_ao;

// View-space position of the full-resolution pixel px at reversed-Z depth d (> 0): the infinite
// projection gives the distance along the view axis as near / d (frame_data.cpp).
vec3 viewPosition(vec2 px, float d) {
  vec2 ndc = (px + 0.5) / vec2(u_viewport.xy) * 2.0 - 1.0;
  float z = u_near_params.x / d;
  return vec3(ndc.x * z / u_proj[0][0], ndc.y * z / u_proj[1][1], -z);
}

// The cosine of the highest horizon along `dir` (pixels) from P seen from V, over the samples
// at distances t_k = (k + offset) / steps x radius_px; -1 (no occluder) where none is nearer
// than the radius. Background and off-screen samples occlude nothing.
float horizonCos(vec2 px, vec2 dir, float radius_px, float offset, vec3 P, vec3 V) {
  const int steps = aoSteps(HV_AO_QUALITY);
  float best = -1.0;
  float r2 = u_ao.x * u_ao.x;
  for (int k = 0; k < steps; ++k) {
    // At least one pixel out, so that the first step never reads the pixel itself.
    float t = max((float(k) + offset) / float(steps) * radius_px, float(k + 1));
    vec2 s = floor(px + dir * t) + 0.5;
    if (s.x < 0.0 || s.y < 0.0 || s.x >= float(u_viewport.x) || s.y >= float(u_viewport.y)) break;
    float d = texelFetch(t_depth, ivec2(s), 0).r;
    vec3 delta = viewPosition(floor(s), max(d, 1e-30)) - P;
    float l2 = dot(delta, delta);
    if (d > 0.0 && l2 < r2 && l2 > 0.0) best = max(best, dot(delta, V) * inversesqrt(l2));
  }
  return best;
}

void main() {
  ivec2 q = ivec2(gl_GlobalInvocationID.xy);
  if (q.x >= int(u_ao.z) || q.y >= int(u_ao.w)) return;
  ivec2 px = q * int(u_ao.y);
  float d = texelFetch(t_depth, px, 0).r;
  if (d <= 0.0) {  // background: nothing to occlude (the ambient pass draws the environment)
    imageStore(i_ao, q, vec4(1.0, 0.0, 0.0, 0.0));
    return;
  }
  vec3 P = viewPosition(vec2(px), d);
  vec3 V = normalize(-P);
  vec3 N = normalize(mat3(u_view) * octDecode(texelFetch(t_normal, px, 0).xy));
  // The radius projected to pixels at this depth: r x P11 / z in NDC, half the height per unit.
  float radius_px = u_ao.x * u_proj[1][1] / -P.z * 0.5 * float(u_viewport.y);
  radius_px = min(radius_px, float(u_viewport.y));
  vec2 noise = gtaoNoise(q.x, q.y);
  const int dirs = aoDirections(HV_AO_QUALITY);
  float visibility = 0.0;
  vec3 bent = vec3(0.0);
  for (int i = 0; i < dirs; ++i) {
    float phi = (float(i) + noise.x) * PI / float(dirs);
    vec2 dir = vec2(cos(phi), sin(phi));
    vec3 d3 = vec3(dir, 0.0);
    // The slice: the plane through V and the screen direction; `ortho` is its axis across V.
    vec3 ortho = normalize(d3 - dot(d3, V) * V);
    vec3 axis = cross(ortho, V);
    vec3 proj_n = N - axis * dot(N, axis);
    float proj_len = length(proj_n);
    float cos_n = clamp(dot(proj_n, V) / max(proj_len, 1e-6), -1.0, 1.0);
    float n = (dot(proj_n, ortho) >= 0.0 ? 1.0 : -1.0) * acos(cos_n);
    // Clamped: a rounded cosine just above 1 would make acos NaN.
    float h1 = acos(clamp(horizonCos(vec2(px), dir, radius_px, noise.y, P, V), -1.0, 1.0));
    float h0 = -acos(clamp(horizonCos(vec2(px), -dir, radius_px, noise.y, P, V), -1.0, 1.0));
    h0 = gtaoClampLow(h0, n);
    h1 = gtaoClampHigh(h1, n);
    float slice = proj_len * gtaoSliceVisibility(h0, h1, n);
    visibility += slice;
    // Bent normal: the slice's mid-horizon direction, weighted by what the slice sees.
    float hb = 0.5 * (h0 + h1);
    bent += (V * cos(hb) + ortho * sin(hb)) * slice;
  }
  visibility = clamp(visibility / float(dirs), 0.0, 1.0);
  // View to world: the view matrix is a rotation and a translation (lookAt).
  vec3 B = dot(bent, bent) > 1e-12 ? normalize(transpose(mat3(u_view)) * bent)
                                   : octDecode(texelFetch(t_normal, px, 0).xy);
  imageStore(i_ao, q, vec4(visibility, -P.z, octEncode(B)));
}
