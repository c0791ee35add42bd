// Ambient occlusion math shared by the AO pass (passes/gtao.comp), the ambient pass and the C++
// tests (halfvec/shading/ao.hpp; rules in halfvec/shading/glsl.hpp). GTAO: Jimenez, Wu, Pesce,
// Jarabo 2016, "Practical Real-Time Strategies for Accurate Indirect Occlusion" (the paper's
// equation numbers below). Angles in a slice are measured from the view vector V, positive
// towards the slice's screen direction; docs/ambient-occlusion.md derives the rest.
#ifndef HV_AO_GLSL
#define HV_AO_GLSL

#include "math.glsl"
#include "setting_values.glsl"

// Horizon-search directions (slices) per pixel and steps per side of each slice, per ao_quality.
// The 4x4 pixel pattern of slice rotations (gtaoNoise) is averaged out by the 4x4 denoise, so
// the effective count per pixel after the denoise is 16 x directions: 16 slices at low and
// medium, 32 at high: the pattern, not the texel, supplies the directions (the paper's spatial
// denoising, section 7), so one slice per texel suffices where its 16 rotations are averaged;
// docs/ambient-occlusion.md gives each quality's accuracy and cost.
int aoDirections(int quality) {
  if (quality == HV_AO_QUALITY_HIGH) return 2;
  return 1;
}
int aoSteps(int quality) {
  if (quality == HV_AO_QUALITY_LOW) return 3;
  if (quality == HV_AO_QUALITY_MEDIUM) return 5;
  return 6;
}

// The two horizon angles h0 <= 0 <= h1 (eq. 10's h1, h2) limited to the hemisphere around the
// normal projected into the slice, whose angle from V is n (section 4, "the horizons are
// clamped to the normal hemisphere": h = n -+ pi/2 at most).
float gtaoClampLow(float h0, float n) { return n + max(h0 - n, -0.5f * PI); }
float gtaoClampHigh(float h1, float n) { return n + min(h1 - n, 0.5f * PI); }

// Eq. 10: the cosine-weighted visibility of one slice between the horizons h0 and h1 (already
// clamped), for the projected normal at angle n; in the slice's measure |sin(h)| dh, each side is
// 1/4 (-cos(2h - n) + cos(n) + 2 h sin(n)). An unoccluded slice whose normal lies in it (n = 0)
// gives 1; the frame's AO is the mean over slices of (projected normal length) x this (eq. 9).
float gtaoSliceVisibility(float h0, float h1, float n) {
  float cn = cos(n);
  float sn = sin(n);
  float a0 = -cos(2.0f * h0 - n) + cn + 2.0f * h0 * sn;
  float a1 = -cos(2.0f * h1 - n) + cn + 2.0f * h1 * sn;
  return 0.25f * (a0 + a1);
}

// Eq. 10 as gtaoSliceVisibility, from the horizon cosines c0 (the -dir side) and c1 (+dir) that
// the march finds, with cos(n) and sin(n) of the projected normal's angle n given: the angles
// h = -+acos(c) are clamped as by gtaoClampLow / gtaoClampHigh and returned in h0, h1 (for the
// bent normal), and cos(2h - n) = cos(2h) cos(n) + sin(2h) sin(n) comes from c and sin(h) =
// -+sqrt(1 - c^2) (or is -cos(n) where h is clamped to n -+ pi/2), so the slice needs no
// trigonometric call but the acos of each angle.
float gtaoSliceVisibilityCos(float c0, float c1, float n, float cos_n, float sin_n,
                             HV_OUT(float) h0, HV_OUT(float) h1) {
  h0 = -acos(c0);
  h1 = acos(c1);
  float s0 = -sqrt(max(1.0f - c0 * c0, 0.0f));
  float s1 = sqrt(max(1.0f - c1 * c1, 0.0f));
  float k0 = (2.0f * c0 * c0 - 1.0f) * cos_n + 2.0f * s0 * c0 * sin_n;
  float k1 = (2.0f * c1 * c1 - 1.0f) * cos_n + 2.0f * s1 * c1 * sin_n;
  if (h0 - n < -0.5f * PI) {
    h0 = n - 0.5f * PI;
    k0 = -cos_n;
  }
  if (h1 - n > 0.5f * PI) {
    h1 = n + 0.5f * PI;
    k1 = -cos_n;
  }
  return 0.25f * (2.0f * cos_n - k0 - k1 + 2.0f * (h0 + h1) * sin_n);
}

// Section 5, "Multiple bounces": the visibility with interreflection from the albedo, the
// paper's cubic fit a(albedo) x^3 + b x^2 + c x in x = visibility, never below the visibility.
vec3 gtaoMultiBounce(float visibility, vec3 albedo) {
  vec3 a = 2.0404f * albedo - vec3(0.3324f);
  vec3 b = -4.7951f * albedo + vec3(0.6417f);
  vec3 c = 2.7552f * albedo + vec3(0.6903f);
  float x = visibility;
  return max(vec3(x), ((x * a + b) * x + c) * x);
}

// How the material's occlusion (the G-buffer's cavity: material cavity x glTF occlusion texture)
// combines with the screen-space visibility: their product. The reference multiplies all
// environment light by the cavity and traces the geometry's occlusion on top (a texture records
// detail below the mesh, which no depth buffer sees); docs/ambient-occlusion.md says why not min.
float combineOcclusion(float cavity, float visibility) { return cavity * visibility; }

// Section 6, "Specular occlusion": the visible directions as a cone around the bent normal whose
// cosine-weighted solid angle is the visibility A: a cone of half-angle a holds sin^2(a) of the
// cosine-weighted hemisphere, so cos(a) = sqrt(1 - A).
float visibilityConeCos(float visibility) { return sqrt(saturate(1.0f - visibility)); }

// The specular lobe as a cone around R: GGX's half vectors have the distribution
// P(theta_h < t) = tan^2(t) / (alpha^2 + tan^2(t)) (D(h) cos(theta_h) integrated), whose median
// is tan(theta_h) = alpha; reflection doubles the angle, so the cone of half the lobe has
// half-angle 2 atan(alpha): cos = (1 - alpha^2) / (1 + alpha^2), clamped to a hemisphere.
float specularConeCos(float alpha) {
  float a2 = alpha * alpha;
  return max((1.0f - a2) / (1.0f + a2), 0.0f);
}

// Solid angle of the intersection of two spherical caps (cosines of their half-angles, cosine of
// the angle between their axes) over 2 pi: exact when one cap holds the other or they are apart,
// else Oat & Sander 2007 ("Ambient Aperture Lighting", section 3.2)'s smoothstep between the two.
float capIntersectionOver2Pi(float cos_a, float cos_b, float cos_d) {
  float ra = acos(clamp(cos_a, -1.0f, 1.0f));
  float rb = acos(clamp(cos_b, -1.0f, 1.0f));
  float d = acos(clamp(cos_d, -1.0f, 1.0f));
  float small_cap = 1.0f - max(cos_a, cos_b);
  if (d <= abs(ra - rb)) return small_cap;  // the smaller cap lies inside the larger
  if (d >= ra + rb) return 0.0f;            // disjoint
  float t = 1.0f - (d - abs(ra - rb)) / max(ra + rb - abs(ra - rb), 1e-6f);
  return small_cap * t * t * (3.0f - 2.0f * t);
}

// The cone-cone specular occlusion: the part of the specular cone (around R, from alpha) inside
// the visibility cone (around the bent normal B, from the visibility), over the part inside the
// hemisphere of an open surface (the cone around N of half-angle 90 degrees). Without that
// normalisation a rough lobe whose cone dips below the horizon would be occluded on an open
// plane (the split sum already integrates the whole lobe; tests/render/test_ao_gpu.cpp checks the
// open plane, docs/ambient-occlusion.md gives the error without it).
float specularOcclusionCone(vec3 B, vec3 N, vec3 R, float visibility, float alpha) {
  float cos_v = visibilityConeCos(visibility);
  float cos_s = specularConeCos(alpha);
  float open = capIntersectionOver2Pi(0.0f, cos_s, dot(N, R));
  if (open <= 1e-6f) return 1.0f;  // the lobe's cone lies wholly below the horizon
  return saturate(capIntersectionOver2Pi(cos_v, cos_s, dot(B, R)) / open);
}

// The traced specular occlusion (ao_specular: traced; the march is ambient.comp's, GPU only). A
// glossy lobe's occlusion is where its dominant direction goes, which the AO, a cosine-weighted
// mean over the hemisphere, does not say: on DamagedHelmet the visor and trims reflect the
// helmet's own parts (docs/ambient-occlusion.md, "Traced specular occlusion", measures how much
// of the error that is). The ray is marched through the depth buffer at HV_AO_TRACE_STEPS
// points t = start + reach ((k + 0.5) / steps)^2 (dense near the
// surface, where a seam's occluder is), reach = HV_AO_TRACE_REACH ao_radius, the first
// HV_AO_TRACE_START of the view distance out (past the surface's own depth: a curved surface
// would occlude itself). A point behind the depth buffer's surface by more than
// HV_AO_TRACE_EPSILON of its view distance and less than aoTraceThickness (what a screen-space
// march must assume of an occluder's thickness) is a hit. The visibility replaces Lagarde's
// occlusion with weight aoTraceWeight: 1 up to roughness HV_AO_TRACE_ROUGH_FULL, 0 from
// HV_AO_TRACE_ROUGH_NONE (a ray stands for a narrow lobe only). Constants chosen on DamagedHelmet
// under two HDRs against the reference with visibility and on a glossy floor before a box
// (tests/render/test_ao_gpu.cpp); the measurements: docs/ambient-occlusion.md.
#define HV_AO_TRACE_STEPS 12
const float HV_AO_TRACE_REACH = 3.0f;
const float HV_AO_TRACE_START = 0.02f;
const float HV_AO_TRACE_EPSILON = 0.002f;
const float HV_AO_TRACE_ROUGH_FULL = 0.2f;
const float HV_AO_TRACE_ROUGH_NONE = 0.6f;
float aoTraceThickness(float radius, float t) { return 0.1f * radius + 0.5f * t; }

// The traced visibility's weight for a lobe of perceptual roughness r (1: the ray decides, 0:
// Lagarde's occlusion from the AO alone).
float aoTraceWeight(float roughness) {
  return saturate((HV_AO_TRACE_ROUGH_NONE - roughness) /
                  (HV_AO_TRACE_ROUGH_NONE - HV_AO_TRACE_ROUGH_FULL));
}

// The 4x4 pattern of the slice rotations and step offsets (section 7, "spatial denoising": the
// 4x4 box of the denoise pass sees each of the 16 values once). Bayer order (4 b2(x, y) + b2 of
// the next bit, b2 = the 2x2 matrix 0 2 / 3 1), so that neighbours differ by large rotations;
// returns (rotation, step offset) in [0, 1).
int bayer2(int x, int y) { return 2 * ((x ^ y) & 1) + (y & 1); }
vec2 gtaoNoise(int x, int y) {
  int i = 4 * bayer2(x & 1, y & 1) + bayer2((x >> 1) & 1, (y >> 1) & 1);
  // The step offset runs through the 16 values in another order (i * 5 mod 16 is a permutation).
  return vec2((float(i) + 0.5f) / 16.0f, (float((i * 5) & 15) + 0.5f) / 16.0f);
}

#endif
