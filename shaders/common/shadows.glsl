// Shadows of point, sphere and tube lights from omnidirectional shadow maps (docs/lights.md,
// "Shadows"): one cube map of linear distance per shadowed light, the cube faces of all of them
// layers of one depth cube map array (the atlas, engine/render/src/shadow_pass.cpp). The geometry
// of the filters (texel angle, Fernando's penumbra, the emitter's extent, the taps, the receiver
// plane) is shared by GLSL and C++ (halfvec/shading/glsl.hpp); the lookups are GLSL only.
//
// Defines (the C++ side sets them from the scene, render/src/variant_key.cpp lightDefines):
//  HV_SHADOWS 0|1             compile the lookup (a scene without shadowed lights has none)
//  HV_SHADOW_FILTER 2|1|0     2 = PCSS (Fernando 2005), 1 = PCF (fixed radius), 0 = hard
//                             (values: setting_values.glsl)
//  HV_SHADOW_MAP_SIZE 512     texels per cube face side (settings.shadow_map_size)
//  HV_SHADOW_RESOLUTION       full: the light pass looks the maps up per pixel; half: the shadow
//                             mask pass does, per 2x2 pixels (shadow_mask.glsl)
//  HV_SHADOW_QUALITY          medium | high: PCSS's blocker search, HV_PCSS_SEARCH_GATHERS
#ifndef HV_SHADOWS_GLSL
#define HV_SHADOWS_GLSL

#include "gpu_records.glsl"
#include "math.glsl"
#include "sampling.glsl"
#include "setting_values.glsl"

#ifndef HV_SHADOWS
#define HV_SHADOWS 0
#endif
#ifndef HV_SHADOW_FILTER
#define HV_SHADOW_FILTER HV_SHADOW_FILTER_PCSS
#endif
#ifndef HV_SHADOW_MAP_SIZE
#define HV_SHADOW_MAP_SIZE 512
#endif
#ifndef HV_SHADOW_RESOLUTION
#define HV_SHADOW_RESOLUTION HV_SHADOW_RESOLUTION_FULL
#endif
#ifndef HV_SHADOW_QUALITY
#define HV_SHADOW_QUALITY HV_SHADOW_QUALITY_MEDIUM
#endif
// Bias, in texels of the map at the receiver's distance (measured: docs/lights.md, "Shadows",
// acne at 80 degrees from the normal against light leaking at contact). The receiver moves along
// its normal by HV_SHADOW_NORMAL_OFFSET texels before the lookup (normal offset); each tap then
// compares against the receiver's plane along that tap's ray (receiver-plane depth), less
// (HV_SHADOW_CONST_BIAS + HV_SHADOW_SLOPE_BIAS tan(theta)) texels: the depth a texel spans on a
// plane at angle theta to the light (slope scale), tan clamped at HV_SHADOW_MAX_SLOPE.
const float HV_SHADOW_NORMAL_OFFSET = 1.0f;
const float HV_SHADOW_CONST_BIAS = 0.5f;
const float HV_SHADOW_SLOPE_BIAS = 1.0f;
const float HV_SHADOW_MAX_SLOPE = 10.0f;
// PCF's filter radius and PCSS's smallest one, in texels (PCSS of a point light: the same).
const float HV_SHADOW_PCF_RADIUS = 1.5f;
// PCSS's blocker search covers the emitter's angular radius seen from the receiver times this:
// blockers down to a third of the way from the light to the receiver are found (a blocker at
// distance z from the light occludes part of an emitter of radius r from a receiver at d when
// it lies within r (d - z) / (d z) of the receiver's direction, r / d for z = d / 2).
const float HV_PCSS_SEARCH_SCALE = 2.0f;
// Widest filter, radians: a receiver far behind a close blocker under a large light would
// otherwise sample half the cube.
const float HV_SHADOW_MAX_FILTER = 0.35f;

// Angle of one texel at a cube face's center, radians: a face spans tan = -1 .. 1 (towards the
// edges texels subtend less, down to 1/3 of this in solid angle at the corners).
float shadowTexelAngle() { return 2.0f / float(HV_SHADOW_MAP_SIZE); }

// Fernando 2005, "Percentage-Closer Soft Shadows", eq. 1 (similar triangles): the penumbra's
// half-width on the receiver, w = r (d_receiver - d_blocker) / d_blocker, of an emitter of
// half-extent r, distances from the light. As an angle seen from the light: w / d_receiver.
float pcssPenumbraAngle(float d_receiver, float d_blocker, float half_extent) {
  float db = max(d_blocker, 1e-4f);
  return half_extent * max(d_receiver - db, 0.0f) / (db * max(d_receiver, 1e-4f));
}

// The emitter as the filter sees it from a receiver in direction D (unit, light to receiver):
// an ellipse in the plane across D with half-axes ext.x along u and ext.y along v (metres). A
// sphere (or point) is a disk of its radius; a capsule of radius r and segment length len is
// r + (len / 2) sin(axis, D) along the segment's projection u and r across it (the capsule's
// silhouette's extents seen along D). u, v: unit, across D.
vec2 emitterExtent(vec3 D, vec3 axis, float radius, float len, HV_OUT(vec3) u, HV_OUT(vec3) v) {
  tangentFrame(D, u, v);
  vec3 ap = axis - dot(axis, D) * D;  // the segment's direction projected across D
  float s = length(ap);               // sin of the angle between the axis and D
  // Along the segment's projection when there is one (len = 0 or axis along D: the disk).
  if (s * len > 1e-6f) {
    u = ap / s;
    v = cross(D, u);
  }
  return vec2(radius + 0.5f * len * s, radius);
}

// Tap i of n of a Vogel disk (Vogel 1979; golden-angle spiral): points at radius
// sqrt((i + 0.5) / n) of the unit disk, uniform in area, so n taps average the disk.
vec2 vogelTap(int i, int n) {
  float r = sqrt((float(i) + 0.5f) / float(n));
  float a = float(i) * 2.39996323f;  // the golden angle, pi (3 - sqrt(5))
  return vec2(r * cos(a), r * sin(a));
}

// The lookups walk the Vogel disk by rotating the tap's direction by the golden angle, (cos,
// sin) of 2.39996323 as a complex product: tap i is sqrt((i + 0.5) / n) times the i-th rotation
// of (1, 0), the points of vogelTap without a sine and a cosine per tap.
const vec2 HV_VOGEL_STEP = vec2(-0.73736888f, 0.67549029f);
vec2 vogelNext(vec2 rot) {
  return vec2(rot.x * HV_VOGEL_STEP.x - rot.y * HV_VOGEL_STEP.y,
              rot.x * HV_VOGEL_STEP.y + rot.y * HV_VOGEL_STEP.x);
}

// Distance from the light, along unit direction dir, to the receiver's plane (through the point
// at toP from the light, normal N): the depth a tap of the filter compares against (receiver-
// plane depth; Isidoro 2006). A ray that misses the plane (it faces away or is parallel)
// gets `far` (beyond every caster: shadowed by any). Clamped to [d / 2, far].
float receiverPlaneDistance(vec3 toP, vec3 N, vec3 dir, float far) {
  float num = dot(toP, N);  // < 0 on the lit side
  float den = dot(dir, N);
  float t = num / min(den, -1e-6f);
  t = den < -1e-6f ? t : far;
  return clamp(t, 0.5f * length(toP), far);
}

// The depth bias of a tap, metres, at distance d on a plane whose normal is at angle theta to
// the light (cos_theta = |N.L|): slope-scaled (see HV_SHADOW_SLOPE_BIAS).
float shadowDepthBias(float d, float cos_theta) {
  float c = max(cos_theta, 1e-4f);
  float tan_theta = min(sqrt(max(1.0f - c * c, 0.0f)) / c, HV_SHADOW_MAX_SLOPE);
  return (HV_SHADOW_CONST_BIAS + HV_SHADOW_SLOPE_BIAS * tan_theta) * shadowTexelAngle() * d;
}

// The receiver-plane distance of a tap (receiverPlaneDistance), with what depends only on the
// receiver computed once for all of its taps: the tap's ray is dir = D + o.x u + o.y v for the
// offset o (radians at unit distance, across the unit direction D; u, v, D orthonormal), not
// normalized, so |dir| = sqrt(1 + |o|^2) and the distance along it to the plane is
// dot(toP, N) |dir| / dot(dir, N), with dot(dir, N) = dot(D, N) + o.x dot(u, N) + o.y dot(v, N).
// plane = (dot(toP, N), dot(D, N), dot(u, N), dot(v, N)); near = |toP| / 2, far as there.
float shadowTapDistance(vec4 plane, vec2 o, float near, float far) {
  float den = plane.y + o.x * plane.z + o.y * plane.w;
  float t = plane.x * sqrt(1.0f + dot(o, o)) / min(den, -1e-6f);
  t = den < -1e-6f ? t : far;
  return clamp(t, near, far);
}

// PCF's taps (Reeves et al. 1987 with bilinear depth comparison, each tap a 2 x 2 PCF): four at
// (+-a, +-a) texels with a = HV_SHADOW_PCF_RADIUS / 2, whose spread (a^2 per axis) is that of a
// uniform disk of radius HV_SHADOW_PCF_RADIUS (R^2 / 4 per axis), the kernel the filter had as
// 16 point taps on a Vogel disk of that radius; the bilinear footprints overlap, so the kernel
// is a continuous, monotone ramp across an edge.
vec2 pcfTap(int i) {
  return vec2((i & 1) != 0 ? 0.5f : -0.5f, (i & 2) != 0 ? 0.5f : -0.5f);
}

#if HV_SHADOWS && !defined(HV_CPP)
// The atlas twice (engine/render/src/shadow_pass.cpp): raw distances (nearest; PCSS's blocker
// search, hard shadows) and with depth comparison (bilinear PCF of 2 x 2 texels per tap). Each
// texel holds distance / far from the light center, far = the light's culling radius.
layout(binding = HV_UNIT_SHADOW_DEPTH) uniform samplerCubeArray t_shadow_depth;
layout(binding = HV_UNIT_SHADOW_COMPARE) uniform samplerCubeArrayShadow t_shadow_compare;

// Receivers per call of shadowVisibility: the light pass's pixels per invocation
// (light_shade.comp checks that the two agree).
#define HV_SHADOW_RECEIVERS 4

// The taps of PCSS's filter (a Vogel disk of bilinear comparisons; twice as many over an ellipse
// more than twice as long as wide) and of its blocker search (a Vogel disk of gathers, each the
// 2 x 2 texels around its point: four distances per fetch). `shadow_quality: high` searches with
// 32 gathers: the farthest blocker is found more surely, penumbrae come closer to the traced
// reference's widths and the bands that 8 gathers leave under a long tube go, for a light pass
// some 70-80% dearer wherever pcss shadows are looked up (docs/lights.md, "Shadow quality").
#define HV_PCSS_FILTER_TAPS 16
#if HV_SHADOW_QUALITY == HV_SHADOW_QUALITY_HIGH
#define HV_PCSS_SEARCH_GATHERS 32
#else
#define HV_PCSS_SEARCH_GATHERS 8
#endif

// What the taps of one receiver share (computed once per receiver and light): its direction D
// from the light and the frame u, v across it, the receiver plane's coefficients
// (shadowTapDistance), the nearest distance a tap may compare against, and the bias, both over
// `far` as the map stores distances. Every tap then costs a 2D offset, its ray and the plane's
// distance along it.
struct ShadowReceiver {
  vec3 D;
  vec3 u;
  vec3 v;
  vec4 plane;
  float near;
  float bias;
};

// The map's comparison value of the tap at offset o (radians across D): the receiver plane's
// distance along the tap's ray less the bias, over far.
float shadowTapRef(ShadowReceiver r, vec2 o, float far, float inv_far) {
  return shadowTapDistance(r.plane, o, r.near, far) * inv_far - r.bias;
}

// Percentage-closer filtering over the ellipse of half-axes `radii` (radians) along u and v:
// the mean of n bilinear comparisons on a Vogel disk of n points (PCSS step 3); n, the loop's
// count, is set at run time (shadowVisibility).
float shadowPcfDisk(ShadowReceiver r, vec2 radii, float far, float inv_far, float layer, int n) {
  float lit = 0.0f;
  vec2 rot = vec2(1.0f, 0.0f);
  for (int i = 0; i < n; ++i) {
    vec2 o = sqrt((float(i) + 0.5f) / float(n)) * rot * radii;
    rot = vogelNext(rot);
    vec3 dir = r.D + r.u * o.x + r.v * o.y;
    lit += texture(t_shadow_compare, vec4(dir, layer), shadowTapRef(r, o, far, inv_far));
  }
  return lit / float(max(n, 1));
}

// Visibility (0 shadowed .. 1 lit) of a light centered at Lpos whose map is cube `layer` of the
// atlas (< 0: none; lit), distances stored over `far`, at HV_SHADOW_RECEIVERS receivers P[j]
// with normals N[j] (`use[j]` false: not needed, e.g. a background pixel); the emitter (PCSS):
// radius, segment axis and length. Every skip is a loop of one pass or none: on a SIMD CPU
// implementation (llvmpipe) an `if` costs its body even when no lane takes it, a loop that no
// lane enters costs nothing. The tap loops run all their taps or none (their count is the number
// of taps times `lookup`, 1 or 0): no lane leaves early, and the count is not a constant that
// the compiler would unroll into a copy of the texture lookup per tap (slower on llvmpipe:
// docs/lights.md, "Cost").
vec4 shadowVisibility(vec3 Lpos, float far, float layer, float radius, vec3 axis, float len,
                      vec3 P[HV_SHADOW_RECEIVERS], vec3 N[HV_SHADOW_RECEIVERS], bvec4 use) {
  vec4 vis = vec4(1.0f);
  // A loop of one pass or none: nothing below runs for a light without a map.
  int lookups = layer >= 0.0f ? 1 : 0;
  for (int k = 0; k < lookups; ++k) {
    float texel = shadowTexelAngle();
    float inv_far = 1.0f / far;
    for (int j = 0; j < HV_SHADOW_RECEIVERS; ++j) {
      // Normal offset: the receiver moves along its normal (towards the light on a lit face).
      vec3 toP0 = P[j] - Lpos;
      vec3 toP = toP0 + N[j] * (HV_SHADOW_NORMAL_OFFSET * texel * length(toP0));
      float d = length(toP);
      ShadowReceiver r;
      r.D = toP / max(d, 1e-6f);
      float cos_theta = dot(N[j], r.D);
      r.bias = shadowDepthBias(d, abs(cos_theta)) * inv_far;
      r.near = 0.5f * d;
      // The emitter wholly below the receiver's horizon (its highest point over the tangent
      // plane, -N.toP0 + radius + len / 2 |N.axis|, below it): the surface shadows itself and
      // the light's evaluation is 0 there too; no lookup.
      bool below = radius + 0.5f * len * abs(dot(N[j], axis)) < dot(N[j], toP0);
      vis[j] = below ? 0.0f : 1.0f;
      // Beyond the map (the light's culling radius) the light is 0 anyway.
      int lookup = use[j] && !below && d < far ? 1 : 0;
#if HV_SHADOW_FILTER == HV_SHADOW_FILTER_HARD
      for (int i = 0; i < lookup; ++i) {
        float z = textureLod(t_shadow_depth, vec4(r.D, layer), 0.0f).r;
        vis[j] = step(d * inv_far - r.bias, z);
      }
#elif HV_SHADOW_FILTER == HV_SHADOW_FILTER_PCF
      for (int i = 0; i < lookup; ++i) {
        tangentFrame(r.D, r.u, r.v);
        r.plane = vec4(dot(toP, N[j]), cos_theta, dot(r.u, N[j]), dot(r.v, N[j]));
        float lit = 0.0f;
        for (int t = 0; t < 4 * lookup; ++t) {
          vec2 o = pcfTap(t) * (HV_SHADOW_PCF_RADIUS * texel);
          vec3 dir = r.D + r.u * o.x + r.v * o.y;
          lit += texture(t_shadow_compare, vec4(dir, layer), shadowTapRef(r, o, far, inv_far));
        }
        vis[j] = 0.25f * lit;
      }
#else
      for (int i = 0; i < lookup; ++i) {
        vec2 ext = emitterExtent(r.D, axis, radius, len, r.u, r.v);
        r.plane = vec4(dot(toP, N[j]), cos_theta, dot(r.u, N[j]), dot(r.v, N[j]));
        // Blocker search (Fernando 2005, step 1), over the emitter's extent seen from the
        // receiver: the farthest texel nearer than the receiver, not the paper's mean. The
        // penumbra is cast by the occluder's silhouette as seen from the light, and a convex
        // occluder's silhouette is the farthest part of it in the search region: the mean,
        // pulled towards the light by the occluder's near side, widens the penumbra
        // (docs/accuracy.md, "Shadows"). Each gather's four texels lie within a texel of its
        // point, whose plane distance they are compared with: the slope-scaled bias covers the
        // plane's change over a texel. The search region is the emitter's ellipse (a capsule's
        // half-axes differ), scaled: only a blocker inside it hides part of the emitter; a disk of
        // the larger half-axis spread the 8 gathers so thinly across a long capsule that a
        // resting sphere's blockers were missed, lit wedges inside its shadow (docs/lights.md,
        // "Shadows").
        vec2 search = clamp(HV_PCSS_SEARCH_SCALE * ext / d, vec2(HV_SHADOW_PCF_RADIUS * texel),
                            vec2(HV_SHADOW_MAX_FILTER));
        float blocker_far = 0.0f;  // over far; 0: no blocker
        vec2 rot = vec2(1.0f, 0.0f);
        for (int g = 0; g < HV_PCSS_SEARCH_GATHERS * lookup; ++g) {
          vec2 o = sqrt((float(g) + 0.5f) / float(HV_PCSS_SEARCH_GATHERS)) * search * rot;
          rot = vogelNext(rot);
          vec3 dir = r.D + r.u * o.x + r.v * o.y;
          float ref = shadowTapRef(r, o, far, inv_far);
          vec4 z = textureGather(t_shadow_depth, vec4(dir, layer));
          vec4 zb = z * step(z, vec4(ref));  // the blockers' distances, 0 for the others
          blocker_far = max(blocker_far, max(max(zb.x, zb.y), max(zb.z, zb.w)));
        }
        // Penumbra (step 2) from the emitter's half-extents, at least PCF's radius.
        float zb = blocker_far * far;
        vec2 radii = clamp(vec2(pcssPenumbraAngle(d, zb, ext.x), pcssPenumbraAngle(d, zb, ext.y)),
                           vec2(HV_SHADOW_PCF_RADIUS * texel), vec2(HV_SHADOW_MAX_FILTER));
        // No blocker: lit, nothing to filter.
        int filters = blocker_far > 0.0f ? 1 : 0;
        for (int f = 0; f < filters; ++f) {
          // An ellipse more than twice as long as wide (a capsule seen across its axis) gets
          // twice the taps: spread along a long axis, 16 left bands in a tube's penumbra
          // (docs/lights.md, "Contact shadows of a long capsule").
          int taps = radii.x > 2.0f * radii.y ? 2 * HV_PCSS_FILTER_TAPS : HV_PCSS_FILTER_TAPS;
          vis[j] = shadowPcfDisk(r, radii, far, inv_far, layer, taps * lookup);
        }
      }
#endif
    }
  }
  return vis;
}

// ---- Directional lights: orthographic maps (docs/lights.md, "Directional lights") -------------
// One map per shadowed directional light, layer shadow_cube - 1 of a 2D depth array, rendered
// along the light's travel direction over the casters' bounds (GpuSunShadow, gpu_records.glsl):
// each texel holds the depth along that direction over the map's range. Raw depths (nearest) and
// with depth comparison (bilinear), as the atlas.
layout(binding = HV_UNIT_SUN_SHADOW_DEPTH) uniform sampler2DArray t_sun_depth;
layout(binding = HV_UNIT_SUN_SHADOW_COMPARE) uniform sampler2DArrayShadow t_sun_compare;
layout(std140, binding = HV_UBO_SUN_SHADOWS) uniform SunShadowBlock {
  GpuSunShadow u_sun_shadows[4];  // hv::kMaxDirectionalLights
};
// The widest PCSS filter of a directional light's map, in texels (a receiver far below its
// blocker under a wide disk would otherwise average half the map).
const float HV_SUN_MAX_FILTER_TEXELS = 24.0f;

// Visibility of directional light map `layer` (< 0: none; lit) at the receivers P[j], normals
// N[j] (`use[j]` false: not needed). The same filters as shadowVisibility with the geometry of a
// parallel projection: a tap's offset is metres across the light, the receiver plane's depth
// changes along it by -(N.right, N.up) / N.forward per metre (receiver-plane depth), the bias
// is the atlas's in texels of this map, and PCSS's penumbra is Fernando 2005 eq. 1 for a light
// at infinity: w = (z_receiver - z_blocker) tan(sigma), the emitter's angular radius sigma. The
// blocker search covers the widest penumbra a blocker between the map's near plane and the
// receiver casts, z_receiver tan(sigma). A receiver outside the map's square (no caster above
// it) is lit.
vec4 sunShadowVisibility(float layer, vec3 P[HV_SHADOW_RECEIVERS], vec3 N[HV_SHADOW_RECEIVERS],
                         bvec4 use) {
  vec4 vis = vec4(1.0f);
  int lookups = layer >= 0.0f ? 1 : 0;
  for (int k = 0; k < lookups; ++k) {
    GpuSunShadow m = u_sun_shadows[int(layer)];
    vec3 F = vec3(m.forward_tan);
    vec3 Rt = vec3(m.right_inv_extent);
    vec3 U = vec3(m.up_texel);
    float texel = m.up_texel.w;
    float inv_extent = m.right_inv_extent.w;
    float range = 1.0f / m.origin_inv_range.w;
    float tan_sigma = m.forward_tan.w;
    for (int j = 0; j < HV_SHADOW_RECEIVERS; ++j) {
      vec3 q = P[j] + N[j] * (HV_SHADOW_NORMAL_OFFSET * texel) - vec3(m.origin_inv_range);
      vec2 uv = vec2(dot(q, Rt), dot(q, U)) * inv_extent + 0.5f;
      float z = dot(q, F) / range;  // the receiver's depth in the map's units
      float nf = dot(N[j], F);      // < 0 on the lit side
      vec2 grad = clamp(-vec2(dot(N[j], Rt), dot(N[j], U)) / min(nf, -1e-4f),
                        vec2(-HV_SHADOW_MAX_SLOPE), vec2(HV_SHADOW_MAX_SLOPE)) / range;
      float bias = shadowDepthBias(1.0f, abs(nf)) / shadowTexelAngle() * texel / range;
      bool inside = all(greaterThanEqual(uv, vec2(0.0f))) && all(lessThanEqual(uv, vec2(1.0f)));
      int lookup = use[j] && inside ? 1 : 0;
#if HV_SHADOW_FILTER == HV_SHADOW_FILTER_HARD
      for (int i = 0; i < lookup; ++i) {
        vis[j] = step(z - bias, textureLod(t_sun_depth, vec3(uv, layer), 0.0f).r);
      }
#elif HV_SHADOW_FILTER == HV_SHADOW_FILTER_PCF
      for (int i = 0; i < lookup; ++i) {
        float lit = 0.0f;
        for (int t = 0; t < 4 * lookup; ++t) {
          vec2 o = pcfTap(t) * (HV_SHADOW_PCF_RADIUS * texel);  // metres
          lit += texture(t_sun_compare, vec4(uv + o * inv_extent, layer, z + dot(grad, o) - bias));
        }
        vis[j] = 0.25f * lit;
      }
#else
      for (int i = 0; i < lookup; ++i) {
        // Blocker search (step 1): the farthest blocker nearer than the receiver, as for the
        // other lights (shadowVisibility says why).
        float search = clamp(z * range * tan_sigma, HV_SHADOW_PCF_RADIUS * texel,
                             HV_SUN_MAX_FILTER_TEXELS * texel);
        float blocker = 0.0f;  // depth; 0: no blocker
        vec2 rot = vec2(1.0f, 0.0f);
        for (int g = 0; g < HV_PCSS_SEARCH_GATHERS * lookup; ++g) {
          vec2 o = sqrt((float(g) + 0.5f) / float(HV_PCSS_SEARCH_GATHERS)) * search * rot;
          rot = vogelNext(rot);
          vec4 zt = textureGather(t_sun_depth, vec3(uv + o * inv_extent, layer));
          vec4 zb = zt * step(zt, vec4(z + dot(grad, o) - bias));
          blocker = max(blocker, max(max(zb.x, zb.y), max(zb.z, zb.w)));
        }
        // Penumbra (step 2), metres, at least PCF's radius; then the filter (step 3).
        float radius = clamp(max(z - blocker, 0.0f) * range * tan_sigma,
                             HV_SHADOW_PCF_RADIUS * texel, HV_SUN_MAX_FILTER_TEXELS * texel);
        int filters = blocker > 0.0f ? 1 : 0;
        for (int f = 0; f < filters; ++f) {
          float lit = 0.0f;
          rot = vec2(1.0f, 0.0f);
          for (int t = 0; t < HV_PCSS_FILTER_TAPS * lookup; ++t) {
            vec2 o = sqrt((float(t) + 0.5f) / float(HV_PCSS_FILTER_TAPS)) * radius * rot;
            rot = vogelNext(rot);
            lit += texture(t_sun_compare, vec4(uv + o * inv_extent, layer, z + dot(grad, o) - bias));
          }
          vis[j] = lit / float(HV_PCSS_FILTER_TAPS);
        }
      }
#endif
    }
  }
  return vis;
}
#endif

#endif
