// Analytic lights of the UE4 shading model (Karis 2013, "Real Shading in Unreal Engine 4",
// section "Lighting"): point, sphere and tube (capsule) lights, shared by GLSL and C++ (see
// halfvec/shading/glsl.hpp). Physical definition of each light (units, emitted power, emitter
// radiance): docs/lights.md. C++ mirror of GpuLight and packing: halfvec/shading/light_gpu.hpp.
//
// Defines (defaults first; the C++ side sets them from RenderSettings in hv::brdfDefines):
//  HV_FALLOFF_PLUS_ONE 1|0      Karis eq. 9 1/(d^2+1), or physical 1/d^2 (accuracy comparisons)
//  HV_SPHERE_DIFFUSE 0|1        0 = Karis point approximation, 1 = Lagarde & de Rousiers 2014
//                               horizon-correct sphere irradiance (order of hv::SphereDiffuse)
//  HV_SPHERE_NORMALIZATION 1|0  (alpha/alpha')^2 energy normalization (Karis eqs. 10, 14)
//  HV_SPHERE_SPECULAR 0|1       0 = representative point (Karis eqs. 10, 11, 14), 1 = LTC: the
//                               sphere's cone integrated under the fitted LTC (ltc.glsl)
//                               (order of hv::SphereSpecular)
//  HV_TUBE_SPECULAR 0|1|2       0 = closest point to the reflection ray (Karis eq. 19),
//                               1 = smallest angle (eq. 18), 2 = LTC over the capsule
//                               (order of hv::TubeSpecular)
//  HV_TUBE_NORMALIZATION 1|0    alpha/alpha' line normalization (Karis eq. 20)
//  HV_TUBE_DIFFUSE 0|1          0 = Karis eq. 16, 1 = the capsule's irradiance with the identity
//                               LTC (order of hv::TubeDiffuse)
//  HV_LTC_V_RATIO 1|0           the LTC lobe is fitted with height-correlated Smith V; with another
//                               V term, 1 scales its magnitude by V / V_Smith at the mirror
//                               direction (docs/lights.md, "Other BRDF choices")
//  HV_LTC_LIGHT_CORRECTION 1|0  LTC spheres and tubes: corrects the LTC's integral by the ratio
//                               lobe / LTC at two points of the light, where those points represent
//                               it (ltcCorrection; measurement in docs/lights.md)
//  HV_HAS_POINT_LIGHTS / HV_HAS_SPHERE_LIGHTS / HV_HAS_TUBE_LIGHTS 1|0: compile that light type
//  HV_DIRECT_TERMS 3|1|2|0      bit 1 diffuse, bit 2 specular: the terms shadeLight returns (the
//                               others are 0); for per-term images (`halfvec render --aov`)
//  HV_SHADOWS, HV_SHADOW_FILTER, HV_SHADOW_MAP_SIZE: shadows.glsl (lightShadow below)
#ifndef HV_LIGHTS_GLSL
#define HV_LIGHTS_GLSL

#include "math.glsl"
#include "brdf.glsl"
#include "ltc.glsl"
#include "setting_values.glsl"
#include "shadows.glsl"

#ifndef HV_FALLOFF_PLUS_ONE
#define HV_FALLOFF_PLUS_ONE 1
#endif
#ifndef HV_SPHERE_DIFFUSE
#define HV_SPHERE_DIFFUSE HV_SPHERE_DIFFUSE_KARIS_POINT
#endif
#ifndef HV_SPHERE_NORMALIZATION
#define HV_SPHERE_NORMALIZATION 1
#endif
#ifndef HV_SPHERE_SPECULAR
#define HV_SPHERE_SPECULAR HV_SPHERE_SPECULAR_REPRESENTATIVE_POINT
#endif
#ifndef HV_TUBE_SPECULAR
#define HV_TUBE_SPECULAR HV_TUBE_SPECULAR_CLOSEST_POINT
#endif
#ifndef HV_TUBE_NORMALIZATION
#define HV_TUBE_NORMALIZATION 1
#endif
#ifndef HV_TUBE_DIFFUSE
#define HV_TUBE_DIFFUSE HV_TUBE_DIFFUSE_KARIS_EQ16
#endif
#ifndef HV_LTC_V_RATIO
#define HV_LTC_V_RATIO 1
#endif
#ifndef HV_LTC_LIGHT_CORRECTION
#define HV_LTC_LIGHT_CORRECTION 1
#endif
#ifndef HV_HAS_POINT_LIGHTS
#define HV_HAS_POINT_LIGHTS 1
#endif
#ifndef HV_HAS_SPHERE_LIGHTS
#define HV_HAS_SPHERE_LIGHTS 1
#endif
#ifndef HV_HAS_TUBE_LIGHTS
#define HV_HAS_TUBE_LIGHTS 1
#endif
#ifndef HV_DIRECT_TERMS
#define HV_DIRECT_TERMS 3
#endif
// The LTC table is read, once per pixel, when a compiled light type shades its specular with it.
#define HV_LTC_TABLE                                                             \
  ((HV_HAS_SPHERE_LIGHTS && HV_SPHERE_SPECULAR == HV_SPHERE_SPECULAR_LTC) || \
   (HV_HAS_TUBE_LIGHTS && HV_TUBE_SPECULAR == HV_TUBE_SPECULAR_LTC))

// Light type codes stored (as float) in GpuLight.params.y; = hv::LightType.
#define HV_LIGHT_POINT 0
#define HV_LIGHT_SPHERE 1
#define HV_LIGHT_TUBE 2

// One light as the GPU reads it: std430, 4 x vec4 = 64 bytes (C++ mirror: hv::GpuLight).
//  position_radius: x,y,z world position (tube: segment center), w sphere/capsule radius (m)
//  color_inv_range: rgb linear color premultiplied by intensity I (W/sr), w 1/R (eq. 9 window)
//  axis_length:     x,y,z unit tube axis, w tube segment length (m); 0 for point and sphere
//  params:          x range R (Karis eq. 9 window), y type (0/1/2), z culling radius, w the
//                   light's cube in the shadow atlas + 1 (0: no shadow map; written by the shadow
//                   pass, engine/render/src/shadow_pass.cpp)
// Points and spheres read only the first two vec4 in the light pass, tubes three.
struct GpuLight {
  vec4 position_radius;
  vec4 color_inv_range;
  vec4 axis_length;
  vec4 params;
};

// Smallest squared light distance (1 cm)^2. With HV_FALLOFF_PLUS_ONE = 0 a point light at
// distance 0 would be 1/0; Filament likewise treats a punctual light as a 1 cm sphere. With the
// +1 falloff this changes d^2 + 1 by at most 1e-4.
const float HV_MIN_LIGHT_DIST2 = 1e-4f;

// Karis 2013 eq. 9, window part: saturate(1 - (d/R)^4)^2, computed from d^2 / R^2 so no sqrt is
// needed. Reaches exactly 0 at d = R, which makes R a hard culling bound.
float falloffWindow(float d2, float inv_range) {
  float x = d2 * inv_range * inv_range;
  return sq(saturate(1.0f - x * x));
}

// Karis 2013 eq. 9: window / (d^2 + 1), or window / d^2 with HV_FALLOFF_PLUS_ONE = 0 (inverse
// square law). d^2 is clamped to the light's own radius^2 (a point inside a sphere or capsule
// sees it as from its surface) and to HV_MIN_LIGHT_DIST2.
float distanceFalloff(float d2, float radius, float inv_range) {
  float d2c = max(d2, max(radius * radius, HV_MIN_LIGHT_DIST2));
  return falloffWindow(d2, inv_range) / (d2c + float(HV_FALLOFF_PLUS_ONE));
}

// sphereHorizonFactor (Lagarde & de Rousiers 2014 section 4.7.2, horizon-clipped sphere
// irradiance): ltc_integrals.glsl, where the LTC integrals use it for the horizon as well.

// Karis 2013 eq. 11: the point of a sphere (center Lc relative to the shading point, radius r)
// closest to the reflection ray R. Returns the unnormalized vector to it.
vec3 closestPointOnSphereToRay(vec3 Lc, float radius, vec3 R) {
  vec3 center_to_ray = dot(Lc, R) * R - Lc;
  // radius / |center_to_ray| saturated; 1e-30 guards 0/0 when the ray passes through the center
  // (then center_to_ray = 0 and the center itself is returned).
  return Lc + center_to_ray * saturate(radius * inversesqrt(max(dot(center_to_ray, center_to_ray),
                                                                1e-30f)));
}

// Karis 2013 eqs. 10 and 14: energy normalization of the representative-point sphere light,
// (alpha / alpha')^2 with alpha' = saturate(alpha + radius / (3 distance)): the sphere widens the
// lobe by about a third of its angular radius. 1 when HV_SPHERE_NORMALIZATION = 0.
float sphereNormalization(float alpha, float radius, float d2) {
#if HV_SPHERE_NORMALIZATION
  // radius / distance from d^2 with one inversesqrt; d^2 >= radius^2 (inside the sphere the
  // angular radius is capped at 1 radian-ish, alpha' = alpha + 1/3) and >= HV_MIN_LIGHT_DIST2.
  float d2c = max(d2, max(radius * radius, HV_MIN_LIGHT_DIST2));
  float alpha_p = saturate(alpha + radius * inversesqrt(d2c) * (1.0f / 3.0f));
  return sq(alpha / alpha_p);
#else
  return 1.0f;
#endif
}

// Karis 2013 eq. 20: line normalization alpha / alpha' of the tube light. The paper widens alpha
// in one dimension only, hence the first power. Widening: half the line's angular half-extent,
// alpha' = saturate(alpha + 0.5 saturate(length / distance)), as UE4's AreaLightSpecular
// (LineAngle); distance = distance to the segment center. 1 when HV_TUBE_NORMALIZATION = 0.
float lineNormalization(float alpha, float len, float d2) {
#if HV_TUBE_NORMALIZATION
  float d2c = max(d2, HV_MIN_LIGHT_DIST2);
  float alpha_p = saturate(alpha + 0.5f * saturate(len * inversesqrt(d2c)));
  return alpha / alpha_p;
#else
  return 1.0f;
#endif
}

#if HV_LTC_TABLE
// The two textures of the LTC table (ltc.glsl), sampled like the C++ side (ltc_table.hpp):
// bilinear, clamp to edge, level 0.
#ifdef HV_CPP
vec4 ltcFetch0(vec2 uv) { return ::hv::ltcTableSample(0, uv); }
vec4 ltcFetch1(vec2 uv) { return ::hv::ltcTableSample(1, uv); }
#else
layout(binding = HV_LTC_TEXTURE_UNIT0) uniform sampler2D t_ltc0;
layout(binding = HV_LTC_TEXTURE_UNIT1) uniform sampler2D t_ltc1;
vec4 ltcFetch0(vec2 uv) { return textureLod(t_ltc0, uv, 0.0f); }
vec4 ltcFetch1(vec2 uv) { return textureLod(t_ltc1, uv, 0.0f); }
#endif

// The integral over the hemisphere of the specular lobe the LTC shades, f (n.l) with the
// surface's Fresnel: n_f f0 + n_fresnel (f90 - f0) (Schlick's F = f0 + (f90 - f0)(1 - V.H)^5
// integrated against the fitted lobe, Heitz et al. 2016 section 4.3), f90 = 1, or UE4's
// saturate(50 f0.g) with HV_F_SCHLICK_F90_OCCLUSION. Other F terms get Schlick's average. With a V
// term other than the fitted height-correlated Smith, HV_LTC_V_RATIO scales it by that term over
// Smith's at the mirror direction (N.L = N.V, H = N); docs/lights.md, "Other BRDF choices".
vec3 ltcSpecularMagnitude(Surface s, float NoV, vec4 t1) {
#if HV_BRDF_F == HV_F_SCHLICK_F90_OCCLUSION
  vec3 f90 = vec3(saturate(50.0f * s.f0.y));
#else
  vec3 f90 = vec3(1.0f);
#endif
  vec3 m = s.f0 * t1.x + (f90 - s.f0) * t1.y;
#if HV_LTC_V_RATIO && HV_BRDF_V != HV_V_SMITH_GGX_CORRELATED
  m = m * (visibility(s.roughness, s.alpha, NoV, NoV, 1.0f, NoV) /
           V_SmithGGXCorrelated(s.alpha, NoV, NoV));
#endif
  return m;
}
#endif

// What every light shading a pixel shares, computed once per pixel before the light loop (as
// UE4's BxDFContext): the view direction, N.V and the reflection ray of Karis eq. 11 and 19; with
// an LTC mode, the pixel's LTC and the magnitude of its lobe.
struct ShadingPoint {
  vec3 P;         // world position
  vec3 V;         // unit, from P toward the eye
  vec3 R;         // reflect(-V, N): the reflection ray of the representative-point methods
  float NoV;      // max(dot(N, V), HV_MIN_NOV): the BRDF's N.V
#if HV_LTC_TABLE
  Ltc ltc;        // the LTC of this pixel's (roughness, N.V), world space
  vec3 ltc_spec;  // ltcSpecularMagnitude: what the LTC's integral (<= 1) is multiplied by
#endif
};

ShadingPoint makeShadingPoint(Surface s, vec3 P, vec3 V) {
  ShadingPoint sp;
  sp.P = P;
  sp.V = V;
  sp.R = reflect(-V, s.N);
  sp.NoV = max(dot(s.N, V), HV_MIN_NOV);
#if HV_LTC_TABLE
  vec2 uv = ltcTableUv(s.roughness, sp.NoV);
  sp.ltc = makeLtc(s.N, V, s.alpha, ltcFetch0(uv));
  sp.ltc_spec = ltcSpecularMagnitude(s, sp.NoV, ltcFetch1(uv));
#endif
  return sp;
}

// Karis 2013 "Lighting" / "Material Model": the two terms of one light. diffuseTerm: the diffuse
// lobe (Lambert or Burley) for direction Ld times diffuse_irr = I * falloff * cos (irradiance
// per unit color). specularTerm: the specular lobe for the representative direction Ls times
// spec_irr = I * falloff (N.L applied here), D scaled by spec_norm.
vec3 diffuseTerm(Surface s, ShadingPoint sp, vec3 Ld, float diffuse_irr) {
  vec3 Hd = safeNormalize(sp.V + Ld);
  float NoLd = saturate(dot(s.N, Ld));
  float LoHd = saturate(dot(Ld, Hd));
  return s.diffuse_color * (diffuseLobe(s.roughness, sp.NoV, NoLd, LoHd) * diffuse_irr);
}
vec3 specularTerm(Surface s, ShadingPoint sp, vec3 Ls, float spec_irr, float spec_norm) {
  // H is normalized explicitly: the identity N.H = (N.V + N.L) / sqrt(2 + 2 V.L) (UE4's
  // BxDFContext) saves two dot products but loses precision where V and L are nearly opposite
  // (grazing mirror views: 1 + V.L cancels), which at roughness 0.05 raised the sphere light's
  // worst error against the reference from 9.7 to 14.8 (AccuracyFindings.SphereErrorBounds).
  vec3 H = safeNormalize(sp.V + Ls);
  float NoL = saturate(dot(s.N, Ls));
  float NoH = saturate(dot(s.N, H));
  // 1 - NoH^2 from |N x H|^2: exact near the mirror direction, where 1 - NoH^2 cancels (D_GGX).
  vec3 NxH = cross(s.N, H);
  float VoH = saturate(dot(sp.V, H));
  return specularLobe(s, sp.NoV, NoL, NoH, dot(NxH, NxH), VoH, spec_norm) * (spec_irr * NoL);
}

#if HV_LTC_TABLE && HV_LTC_LIGHT_CORRECTION
// Solid angle of a sphere of sin^2(angular radius) = sin2: 2 pi (1 - cos sigma) = 2 pi sin^2 /
// (1 + cos), no cancellation for small spheres.
float sphereSolidAngle(float sin2) {
  return 2.0f * PI * sin2 / (1.0f + sqrt(max(1.0f - sin2, 0.0f)));
}

// The LTC modes' light correction (docs/lights.md, "Light correction"). The LTC matches the lobe's
// integral over the sphere, not its value in every direction: a light sees the lobe over its own
// cone, where the ratio lobe / LTC is anywhere from 0.5 to 3 in the lobe's flanks and tails at
// grazing views and high roughness (1.4-1.6 for a sphere of r/d 0.25 overhead, seen at N.V 0.36,
// roughness 0.5). Where both vary smoothly over the cone, the ratio of their sums at a few of its
// points is the ratio of their integrals, and the LTC's exact integral I times it is the lobe's.
// The points: two, at +-k tan(sigma) (e1 - e2) / sqrt(2) around the cone's axis c (e1 across the
// plane of c and N, e2 = c x e1; sin2 = sin^2(sigma)); k = 0.6 measured best of 0.4-0.7. Whether
// two points represent the light is tested on the LTC itself, whose integral is known: their
// quadrature omega (D(x1) + D(x2)) / 2 against I, and against omega D(c). Each disagreement
// u = (a - b) / (a + b) lowers the correction's weight linearly, from 1 at u = 0 to 0 at |u| = 1
// against I, and against the axis to 0 at -0.7 (the center's density above the points': the
// LTC's peak within the light) but only to 0.5 at +1 (the points' above the center's: tolerance
// 2). Measured best of 0.2-1e6 against I, 0.5-0.85 and 0.7-1e6 against the axis, on the sphere
// sweep with elevation 30 and 126 configurations off it (docs/lights.md); weight 0: the LTC
// alone. As the light shrinks, both tests and the ratio become exact: the point light's limit,
// the lobe's own value times the solid angle. omega: the light's solid angle (for a capsule, a
// bound); the ratio is clamped to [0, 16].
const float HV_LTC_CORRECTION_K = 0.6f;
const float HV_LTC_CORRECTION_INTEGRAL_TOL = 1.0f;
const float HV_LTC_CORRECTION_AXIS_TOL = 0.7f;
const float HV_LTC_CORRECTION_AXIS_TOL_POINTS = 2.0f;
vec3 ltcCorrection(Surface s, ShadingPoint sp, vec3 c, vec3 along, float sin2, float omega,
                   float I) {
  // The offset stops at sin^2 = 0.9 (72 degrees): inside the sphere sin2 is 1, and the tests
  // below then keep the weight small.
  float s2 = min(sin2, 0.9f);
  vec3 e1;
  vec3 e2;
  tangentFrame(c, e1, e2);
  // e1 across the plane of c and N, e2 in it: a frame that turns with the scene, so the shading
  // does not depend on the world's axes. c along N (a light straight overhead) takes
  // tangentFrame's.
  vec3 a1 = cross(c, s.N);
  float l2 = dot(a1, a1);
  e1 = l2 > 1e-8f ? a1 * inversesqrt(l2) : e1;
  e2 = cross(c, e1);
  vec3 off = (HV_LTC_CORRECTION_K * 0.70710678f * sqrt(s2 / (1.0f - s2))) * (e1 - e2) + along;
  vec3 L1 = normalize(c + off);
  vec3 L2 = normalize(c - off);
  vec3 f = specularTerm(s, sp, L1, 1.0f, 1.0f) + specularTerm(s, sp, L2, 1.0f, 1.0f);
  float d = ltcDensity(sp.ltc, L1) + ltcDensity(sp.ltc, L2);
  vec3 ratio = clamp(f / max(sp.ltc_spec * d, vec3(1e-30f)), vec3(0.0f), vec3(16.0f));
  float quad = 0.5f * omega * d;
  float axis = omega * ltcDensity(sp.ltc, c);
  float u_int = (quad - I) / max(quad + I, 1e-30f);
  float u_axis = (quad - axis) / max(quad + axis, 1e-30f);
  float w = saturate(1.0f - abs(u_int) * (1.0f / HV_LTC_CORRECTION_INTEGRAL_TOL)) *
            saturate(1.0f - abs(u_axis) * mix(1.0f / HV_LTC_CORRECTION_AXIS_TOL,
                                              1.0f / HV_LTC_CORRECTION_AXIS_TOL_POINTS,
                                              step(0.0f, u_axis)));
  return mix(vec3(1.0f), ratio, w);
}
#endif
// The light's radiance toward V from its two terms: the term mask (HV_DIRECT_TERMS: a term left
// out is 0; the compiler drops its code), the cavity (Karis 2013 "Material Model": small-scale
// shadowing multiplies all direct light, diffuse and specular alike, as a shadow factor would)
// and the light's color times intensity.
vec3 combineTerms(Surface s, vec3 radiant, vec3 diffuse, vec3 specular) {
#if (HV_DIRECT_TERMS & 1) == 0
  diffuse = vec3(0.0f);
#endif
#if (HV_DIRECT_TERMS & 2) == 0
  specular = vec3(0.0f);
#endif
  return radiant * ((diffuse + specular) * s.cavity);
}
// Both terms from directions (the representative-point methods and the point light).
vec3 shadeLight(Surface s, ShadingPoint sp, vec3 Ld, vec3 Ls, vec3 radiant, float diffuse_irr,
                float spec_irr, float spec_norm) {
  return combineTerms(s, radiant, diffuseTerm(s, sp, Ld, diffuse_irr),
                      specularTerm(s, sp, Ls, spec_irr, spec_norm));
}

#if HV_HAS_POINT_LIGHTS
// Point light (Karis 2013 "Lighting", eq. 9 falloff): radiance toward V at P.
vec3 evaluatePointLightAt(GpuLight light, Surface s, ShadingPoint sp) {
  vec3 Lc = vec3(light.position_radius) - sp.P;
  float d2 = dot(Lc, Lc);
  vec3 L = Lc * inversesqrt(max(d2, 1e-30f));  // safeNormalize reusing d2: 0 at the light itself
  float falloff = distanceFalloff(d2, 0.0f, light.color_inv_range.w);
  return shadeLight(s, sp, L, L, vec3(light.color_inv_range), falloff * saturate(dot(s.N, L)), falloff,
                    1.0f);
}
vec3 evaluatePointLight(GpuLight light, Surface s, vec3 P, vec3 V) {
  return evaluatePointLightAt(light, s, makeShadingPoint(s, P, V));
}
#endif

#if HV_HAS_SPHERE_LIGHTS
// Sphere light: diffuse from the center (Karis point approximation) or the horizon-correct sphere
// irradiance (Lagarde & de Rousiers 2014 section 4.7.2); specular from the representative point
// closest to the reflection ray (Karis 2013 eq. 11) with the energy normalization of eq. 14, or
// (HV_SPHERE_SPECULAR_LTC) the integral of the pixel's LTC over the sphere's cone times the
// emitter radiance L_e = I / (pi r^2) (docs/lights.md), windowed (and with the +1) as the falloff.
vec3 evaluateSphereLightAt(GpuLight light, Surface s, ShadingPoint sp) {
  float radius = light.position_radius.w;
  vec3 Lc = vec3(light.position_radius) - sp.P;
  float d2 = dot(Lc, Lc);
  vec3 L = Lc * inversesqrt(max(d2, 1e-30f));
  float falloff = distanceFalloff(d2, radius, light.color_inv_range.w);
#if HV_SPHERE_DIFFUSE == HV_SPHERE_DIFFUSE_HORIZON
  // sin^2(sigma) = r^2 / d^2, with d^2 >= HV_MIN_LIGHT_DIST2 (the factor clamps it to <= 1).
  float cos_factor =
      sphereHorizonFactor(dot(s.N, L), radius * radius / max(d2, HV_MIN_LIGHT_DIST2));
#else
  float cos_factor = saturate(dot(s.N, L));
#endif
  vec3 diffuse = diffuseTerm(s, sp, L, falloff * cos_factor);
#if HV_SPHERE_SPECULAR == HV_SPHERE_SPECULAR_LTC
  // L_e per unit I: falloff d^2 / (pi r^2) (= window / (pi r^2), times d^2 / (d^2 + 1) with the
  // +1; d^2 clamped as the falloff clamps it). A radius below 1e-4 d is shaded as 1e-4 d: the
  // integral then equals the LTC's density times the solid angle to 1e-4, and r = 0 is the
  // limit, not 0/0.
  float d2c = max(d2, max(radius * radius, HV_MIN_LIGHT_DIST2));
  float r_eff = max(radius, 1e-4f * sqrt(d2c));
  float I = ltcSphereIntegral(sp.ltc, Lc, r_eff);
  vec3 specular = sp.ltc_spec * (I * falloff * d2c / (PI * r_eff * r_eff));
#if HV_LTC_LIGHT_CORRECTION
  // The lobe over the LTC at two points of the sphere's cone around its center (ltcCorrection).
  float sin2 = r_eff * r_eff / d2c;
  float omega = sphereSolidAngle(sin2);
  // Inside the sphere the integral is exact (the whole hemisphere emits): no correction there
  // (a select; LtcLights.InsideTheSphereTheWholeHemisphereEmits).
  specular = specular * mix(ltcCorrection(s, sp, L, vec3(0.0f), sin2, omega, I), vec3(1.0f),
                            bvec3(d2 <= r_eff * r_eff));
#endif
#else
  vec3 Ls = safeNormalize(closestPointOnSphereToRay(Lc, radius, sp.R));
  float norm = sphereNormalization(s.alpha, radius, d2);
  vec3 specular = specularTerm(s, sp, Ls, falloff, norm);
#endif
  return combineTerms(s, vec3(light.color_inv_range), diffuse, specular);
}
vec3 evaluateSphereLight(GpuLight light, Surface s, vec3 P, vec3 V) {
  return evaluateSphereLightAt(light, s, makeShadingPoint(s, P, V));
}
#endif

#if HV_HAS_TUBE_LIGHTS
// Tube light (capsule: segment of length len along axis, radius r). Diffuse: line-segment
// irradiance with Karis's modifications (Karis 2013 eq. 16), or (HV_TUBE_DIFFUSE_LTC) the
// capsule's irradiance with the identity LTC; specular: point on the segment closest to the
// reflection ray (eq. 19; eq. 18 with HV_TUBE_SPECULAR = 1), then the sphere representative
// point around it (eq. 11), normalized by alpha/alpha' (eq. 20) times the sphere's
// (alpha/alpha'')^2 (eq. 14), or (HV_TUBE_SPECULAR_LTC) the pixel's LTC integrated over the
// capsule, times the emitter radiance L_e = I / (pi r^2 + pi r len / 2) (docs/lights.md).
vec3 evaluateTubeLightAt(GpuLight light, Surface s, ShadingPoint sp) {
  float radius = light.position_radius.w;
  float len = light.axis_length.w;
  vec3 Lc = vec3(light.position_radius) - sp.P;
  vec3 Ld = vec3(light.axis_length) * len;  // segment vector L1 - L0
  vec3 L0 = Lc - 0.5f * Ld;
  vec3 L1 = Lc + 0.5f * Ld;
  float ld2 = dot(Ld, Ld);
  // Closest point of the segment to P: the window distance and the diffuse direction. 1e-30
  // guards 0/0 for len = 0 (then t = 0 and L0 = Lc: the sphere light).
  float tp = saturate(-dot(L0, Ld) / max(ld2, 1e-30f));
  vec3 Lp = L0 + tp * Ld;
  float dp2 = dot(Lp, Lp);
  float window = falloffWindow(dp2, light.color_inv_range.w);
  vec3 Ldiff = Lp * inversesqrt(max(dp2, 1e-30f));  // safeNormalize(Lp) reusing dp2
#if HV_TUBE_DIFFUSE == HV_TUBE_DIFFUSE_LTC || HV_TUBE_SPECULAR == HV_TUBE_SPECULAR_LTC
  // Emitter radiance per unit I (docs/lights.md): window / (pi r (r + len / 2)), times
  // d^2 / (d^2 + 1) with the +1 (d: the closest segment point, clamped as the falloff clamps it).
  // A radius below 1e-4 d is shaded as 1e-4 d (the line light's limit instead of 0/0).
  float dp2c = max(dp2, max(radius * radius, HV_MIN_LIGHT_DIST2));
  float r_eff = max(radius, 1e-4f * sqrt(dp2c));
  float emit = window * (dp2c / (dp2c + float(HV_FALLOFF_PLUS_ONE))) /
               (PI * r_eff * (r_eff + 0.5f * len));
#endif

#if HV_TUBE_DIFFUSE == HV_TUBE_DIFFUSE_LTC
  // Irradiance per unit I: pi L_e times the capsule's integral of the clamped cosine.
  float irradiance = emit * PI * capsuleCosineIntegral(s.N, L0, L1, r_eff);
#else
  // Diffuse, Karis eq. 16: E = I (saturate(n.L0/|L0|) + saturate(n.L1/|L1|)) /
  // (|L0||L1| + L0.L1 + 2), the exact irradiance of a line of total intensity I (n.L clipped at
  // each end, the "+2" being the "+1" of eq. 9). |L0||L1| + L0.L1 -> 2 d^2 as len -> 0, so it
  // is clamped to >= 2 max(r^2, HV_MIN_LIGHT_DIST2) as the sphere clamps d^2 (it is 0 on the
  // segment itself). One inversesqrt per end; |L0||L1| from their product, no extra sqrt.
  float l0_2 = dot(L0, L0);
  float l1_2 = dot(L1, L1);
  float inv_l0 = inversesqrt(max(l0_2, 1e-30f));
  float inv_l1 = inversesqrt(max(l1_2, 1e-30f));
  float geom = (l0_2 * inv_l0) * (l1_2 * inv_l1) + dot(L0, L1);  // paired: no overflow at 1e6 m
  float den = 2.0f * (max(0.5f * geom, max(radius * radius, HV_MIN_LIGHT_DIST2)) +
                      float(HV_FALLOFF_PLUS_ONE));
  float irradiance =
      (saturate(dot(s.N, L0) * inv_l0) + saturate(dot(s.N, L1) * inv_l1)) / den * window;
#endif
  vec3 diffuse = diffuseTerm(s, sp, Ldiff, irradiance);

#if HV_TUBE_SPECULAR == HV_TUBE_SPECULAR_LTC
  float I = ltcCapsuleIntegral(sp.ltc, L0, L1, r_eff);
  vec3 specular = sp.ltc_spec * (emit * I);
#if HV_LTC_LIGHT_CORRECTION
  // As the sphere's (evaluateSphereLightAt), around the capsule's center, its two points also
  // spread along the axis at +-1/sqrt(3) of the half-length (the two-point Gauss rule of a
  // segment), with the capsule's solid angle (at most (pi r^2 + 2 r len) / d^2, d the closest
  // segment point) and integral. len = 0 gives the sphere's correction exactly.
  float sin2 = r_eff * r_eff / dp2c;
  float omega = sphereSolidAngle(sin2) + 2.0f * r_eff * len / dp2c;
  float inv_lc = inversesqrt(max(dot(Lc, Lc), 1e-30f));
  specular = specular * ltcCorrection(s, sp, Lc * inv_lc, (0.57735027f * 0.5f * inv_lc) * Ld,
                                      sin2, omega, I);
#endif
#else
  // Specular: the point of the segment chosen for the reflection ray R (Karis eqs. 18, 19).
  vec3 R = sp.R;
  float rl0 = dot(R, L0);
  float rld = dot(R, Ld);
  float l0ld = dot(L0, Ld);
#if HV_TUBE_SPECULAR == HV_TUBE_SPECULAR_SMALLEST_ANGLE
  // Karis eq. 18: smallest angle to R. The denominator may have either sign; +-1e-30 (sign kept)
  // only guards 0/0 (len = 0 or R parallel to the segment: any t is then as good).
  float tden = l0ld * rld - ld2 * rl0;
  float t = (rl0 * l0ld - rld * dot(L0, L0)) /
            (tden + 1e-30f * (2.0f * step(0.0f, tden) - 1.0f));
#else
  // Karis eq. 19: smallest distance to R; the denominator len^2 (1 - (R.axis)^2) >= 0, and is
  // 0 only when len = 0 or R is parallel to the segment, where the numerator is 0 as well.
  float t = (rl0 * rld - l0ld) / max(ld2 - rld * rld, 1e-30f);
#endif
  vec3 Lt = L0 + saturate(t) * Ld;
  vec3 Ls = safeNormalize(closestPointOnSphereToRay(Lt, radius, R));
  float dt2 = dot(Lt, Lt);
  float norm = lineNormalization(s.alpha, len, dot(Lc, Lc)) * sphereNormalization(s.alpha, radius,
                                                                                   dt2);
  // Specular irradiance scale: the inverse-square falloff of the chosen segment point (the
  // sphere's falloff when len = 0), windowed like the diffuse.
  float spec_irr = window / (max(dt2, max(radius * radius, HV_MIN_LIGHT_DIST2)) +
                             float(HV_FALLOFF_PLUS_ONE));
  vec3 specular = specularTerm(s, sp, Ls, spec_irr, norm);
#endif
  return combineTerms(s, vec3(light.color_inv_range), diffuse, specular);
}
vec3 evaluateTubeLight(GpuLight light, Surface s, vec3 P, vec3 V) {
  return evaluateTubeLightAt(light, s, makeShadingPoint(s, P, V));
}
#endif

// Karis 2013 "Lighting": outgoing radiance at P toward V (unit, from P to the eye) from one light,
// for surface s (docs/lights.md).
// Cavity is applied to all of it (see shadeLight). Only the compiled light types are handled;
// a light of a type compiled out contributes 0.
vec3 evaluateLightAt(GpuLight light, Surface s, ShadingPoint sp) {
  int type = int(light.params.y + 0.5f);  // stored as float; +0.5 rounds
  vec3 result = vec3(0.0f);
#if HV_HAS_POINT_LIGHTS
  if (type == HV_LIGHT_POINT) result = evaluatePointLightAt(light, s, sp);
#endif
#if HV_HAS_SPHERE_LIGHTS
  if (type == HV_LIGHT_SPHERE) result = evaluateSphereLightAt(light, s, sp);
#endif
#if HV_HAS_TUBE_LIGHTS
  if (type == HV_LIGHT_TUBE) result = evaluateTubeLightAt(light, s, sp);
#endif
  return result;
}
vec3 evaluateLight(GpuLight light, Surface s, vec3 P, vec3 V) {
  return evaluateLightAt(light, s, makeShadingPoint(s, P, V));
}

// Karis 2013 eq. 9 (the window bounds the light): world-space radius, around the light
// position, outside which the light contributes exactly 0 (the window is 0 beyond range R of the
// nearest emitting point): R for points and spheres, R + len/2 for tubes. Precomputed by
// packLight; for tiled culling.
float lightCullRadius(GpuLight light) { return light.params.z; }

#if HV_SHADOWS && !defined(HV_CPP)
// The shadow of light l at the shading point (shadows.glsl): its map is cube params.w - 1 of the
// atlas, distances over the culling radius; the emitter's radius, axis and length size PCSS's
// penumbra. Multiplies the light's whole contribution, diffuse and specular (light_shade.comp).
float lightShadow(GpuLight l, Surface s, ShadingPoint sp) {
  return shadowVisibility(vec3(l.position_radius), lightCullRadius(l), l.params.w - 1.0f,
                          l.position_radius.w, vec3(l.axis_length), l.axis_length.w, sp.P, s.N);
}
#endif

#endif
