#version 450 core
// Ground-truth-based ambient occlusion (Jimenez, Wu, Pesce, Jarabo 2016, "Practical Real-Time
// Strategies for Accurate Indirect Occlusion"), the AO pass's first half: per AO texel, a horizon
// search in the depth buffer along a few screen directions (slices) within a world-space radius,
// the cosine-weighted visibility of each slice by eq. 10 with the projected normal, and a bent
// normal. Out (raw, HV_IMAGE_AO): visibility, inverse view distance (1 / m: affine in screen space
// on a plane, so that a bilinear fetch of a plane's texels lies on it), and the bent normal
// (world, octahedral) or, without HV_AO_BENT_NORMAL, the view-space normal; the denoise
// (ao_denoise.comp) averages the 4x4 rotation pattern away. Math: common/ao.glsl.
#include "../common/frame.glsl"
#include "../common/gbuffer.glsl"
#include "../common/ao.glsl"

// Specialization (the settings table's SettingPass::Ao rows; docs/variants.md).
//   HV_AO_QUALITY: directions x steps (aoDirections / aoSteps).
//   HV_AO_HALF_RESOLUTION 1|0: one AO texel per 2x2 pixels (the pixel at its lower left).
//   HV_AO_BENT_NORMAL 1|0: the bent normal, which only the cone specular occlusion reads
//   (ao_specular: cone); without it zw are 0 and the slices' mid-horizon sums are not made.
#ifndef HV_AO_QUALITY
#define HV_AO_QUALITY HV_AO_QUALITY_MEDIUM
#endif
#ifndef HV_AO_HALF_RESOLUTION
#define HV_AO_HALF_RESOLUTION 1
#endif
#ifndef HV_AO_BENT_NORMAL
#define HV_AO_BENT_NORMAL 1
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
  float z = u_frame_params.x / d;
  return vec3(ndc.x * z / u_proj[0][0], ndc.y * z / u_proj[1][1], -z);
}

// The cosine of the highest horizon along `dir` (pixels) from P seen from V, over the samples
// at distances t_k = (k + offset) / steps x radius_px; -1 (no occluder) where none is nearer
// than the radius. Background and off-screen samples occlude nothing. The depth is read with
// bilinear filtering at the exact point on the slice's line: reversed-Z depth is near / z, affine
// in screen space on a plane, so a plane's samples lie exactly on it and in the slice (a texel
// centre would leave the slice by up to half a texel, which the max over samples turns into
// false occlusion at grazing angles).
float horizonCos(vec2 px, vec2 dir, float radius_px, float offset, vec3 P, vec3 V) {
  const int steps = aoSteps(HV_AO_QUALITY);
  float best = -1.0;
  float r2 = u_ao.x * u_ao.x;
  vec2 size = vec2(u_viewport.xy);
  vec2 inv_size = 1.0 / size;
  // The sample at screen point s and depth d lies at (near / d) ray(s), ray(s) the view ray to
  // distance 1, affine along the line s = px + 0.5 + dir t. Its offset from P times d,
  // near ray(s) - d P, has the same cosine to V and turns the radius test into l2 < r2 d^2: no
  // division per sample.
  vec2 proj = vec2(u_proj[0][0], u_proj[1][1]);
  vec3 ray0 = u_frame_params.x * vec3(((px + 0.5) * inv_size * 2.0 - 1.0) / proj, -1.0);
  vec3 ray_dir = u_frame_params.x * vec3(dir * 2.0 * inv_size / proj, 0.0);
  for (int k = 0; k < steps; ++k) {
    // At least one pixel out, so that the first step never reads the pixel itself.
    float t = max((float(k) + offset) / float(steps) * radius_px, float(k + 1));
    vec2 s = px + 0.5 + dir * t;
    // Off screen: no occluder. A mask, not a break: the march leaves the screen only once, and
    // a loop without an exit unrolls (the fetch is clamped to the edge, in bounds).
    bool inside = s.x >= 0.5 && s.y >= 0.5 && s.x <= size.x - 0.5 && s.y <= size.y - 0.5;
    float d = textureLod(t_depth, s * inv_size, 0.0).r;
    vec3 delta = ray0 + ray_dir * t - P * d;
    float l2 = dot(delta, delta);
    if (inside && d > 0.0 && l2 < r2 * d * d && l2 > 0.0) {
      best = max(best, dot(delta, V) * inversesqrt(l2));
    }
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
#if HV_AO_BENT_NORMAL
  vec3 bent = vec3(0.0);
  float open_sum = 0.0;
#endif
  // The slices turn uniformly about V (eq. 9 integrates over that rotation): `ortho`, the slice's
  // direction across V, runs over the plane normal to V from T (the screen's x axis made normal
  // to V). Uniform screen-space angles would not be uniform about V off the image's centre (the
  // open plane then came out 1-9% dark, more at grazing angles).
  vec3 T = normalize(vec3(1.0, 0.0, 0.0) - V.x * V);
  vec3 Bt = cross(V, T);
  for (int i = 0; i < dirs; ++i) {
    float phi = (float(i) + noise.x) * PI / float(dirs);
    vec3 ortho = T * cos(phi) + Bt * sin(phi);
    vec3 axis = cross(ortho, V);
    // The screen direction of the slice: the derivative of the projection at P along `ortho`
    // (square pixels: x and y scale alike), so that the march stays in the slice's plane.
    vec2 dir = normalize(vec2(ortho.x * -P.z + P.x * ortho.z, ortho.y * -P.z + P.y * ortho.z));
    vec3 proj_n = N - axis * dot(N, axis);
    float proj_len = length(proj_n);
    float cos_n = clamp(dot(proj_n, V) / max(proj_len, 1e-6), -1.0, 1.0);
    float side = dot(proj_n, ortho) >= 0.0 ? 1.0 : -1.0;
    float n = side * acos(cos_n);
    float sin_n = side * sqrt(max(1.0 - cos_n * cos_n, 0.0));
    // Clamped: a rounded cosine just above 1 would make acos NaN.
    float c1 = clamp(horizonCos(vec2(px), dir, radius_px, noise.y, P, V), -1.0, 1.0);
    float c0 = clamp(horizonCos(vec2(px), -dir, radius_px, noise.y, P, V), -1.0, 1.0);
    float h0, h1;
    float slice = proj_len * gtaoSliceVisibilityCos(c0, c1, n, cos_n, sin_n, h0, h1);
    visibility += slice;
#if HV_AO_BENT_NORMAL
    // Bent normal: the slice's mid-horizon direction weighted by what the slice sees, minus the
    // same for open horizons (mid-angle n, weight proj_len (cos n + n sin n)): the sum alone leans
    // towards V even on an open plane, its difference from the open sum is what the occluders
    // turn (added to N below).
    float hb = 0.5 * (h0 + h1);
    float open_w = proj_len * (cos_n + n * sin_n);
    bent += (V * cos(hb) + ortho * sin(hb)) * slice - (V * cos_n + ortho * sin_n) * open_w;
    open_sum += open_w;
#endif
  }
  // Not clamped to 1 here: a single slice's share can exceed 1 (eq. 10 is 1 only on average over
  // the slices), and clamping before the denoise averages the 4x4 rotations would bias every
  // surface seen at a grazing angle dark (the open plane by up to 4%); ao_denoise.comp clamps.
  visibility = max(visibility / float(dirs), 0.0);
#if HV_AO_BENT_NORMAL
  // View to world: the view matrix is a rotation and a translation (lookAt).
  vec3 Bv = safeNormalize(N + bent / max(open_sum, 1e-6));
  vec3 B = dot(Bv, Bv) > 0.5 ? transpose(mat3(u_view)) * Bv
                             : octDecode(texelFetch(t_normal, px, 0).xy);
  imageStore(i_ao, q, vec4(visibility, d / u_frame_params.x, octEncode(B)));
#else
  // The view-space normal for the denoise's plane test, which then needs no G-buffer fetch.
  imageStore(i_ao, q, vec4(visibility, d / u_frame_params.x, octEncode(N)));
#endif
}
