// Analytic lights of the UE4 shading model (Karis 2013, "Real Shading in Unreal Engine 4",
// section "Lighting"): point, sphere and tube (capsule) lights, shared by GLSL and C++ (see
// halfvec/shading/glsl.hpp). Physical definition of each light (units, emitted power, emitter
// radiance): docs/lights.md. The light record GpuLight: gpu_records.glsl; its packing:
// halfvec/shading/light_gpu.hpp.
//
// Defines (defaults first; the C++ side sets them from RenderSettings in hv::brdfDefines):
//  HV_FALLOFF_PLUS_ONE 1|0      Karis eq. 9 1/(d^2+1), or physical 1/d^2 (accuracy comparisons)
//  HV_SPHERE_DIFFUSE 0|1        0 = Karis point approximation, 1 = Lagarde & de Rousiers 2014
//                               horizon-correct sphere irradiance (order of hv::SphereDiffuse)
//  HV_SPHERE_NORMALIZATION 1|0  (alpha/alpha')^2 energy normalization (Karis eqs. 10, 14)
//  HV_SPHERE_SPECULAR 0|1       0 = representative point (Karis eqs. 10, 11, 14), 1 = LTC: the
//                               sphere's cone integrated under the fitted LTC (ltc_lights.glsl)
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
//  HV_HAS_SPOT_LIGHTS 1|0       compile the spot cone (spot.glsl) into the point and sphere lights
//  HV_HAS_DIRECTIONAL_LIGHTS 1|0 compile the directional light (a sphere at infinity: the sphere
//                               settings above govern it)
//  HV_DIRECT_TERMS 3|1|2|0      bit 1 diffuse, bit 2 specular: the terms shadeLight returns (the
//                               others are 0); for per-term images (`halfvec render --aov`)
//  HV_SHADOWS, HV_SHADOW_FILTER, HV_SHADOW_MAP_SIZE: shadows.glsl (lightShadow below)
//  HV_ERROR_BUDGET 0|1          settings.max_error > 0: a sphere or directional light shaded with
//                               the representative point takes the LTC where the point's
//                               predicted error exceeds the budget HV_MAX_ERROR (error_budget.glsl)
#ifndef HV_LIGHTS_GLSL
#define HV_LIGHTS_GLSL

#include "gpu_records.glsl"
#include "math.glsl"
#include "brdf.glsl"
#include "ltc.glsl"
#include "setting_values.glsl"
#include "shadows.glsl"
#include "spot.glsl"
#include "error_budget.glsl"

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
#ifndef HV_HAS_SPOT_LIGHTS
#define HV_HAS_SPOT_LIGHTS 1
#endif
#ifndef HV_HAS_DIRECTIONAL_LIGHTS
#define HV_HAS_DIRECTIONAL_LIGHTS 1
#endif
#ifndef HV_DIRECT_TERMS
#define HV_DIRECT_TERMS 3
#endif
// The budget's sphere and sun specular: the representative point, or the LTC where the budget
// asks for it (sphereNeedsLtc).
#define HV_SPHERE_BUDGET                                                                    \
  (HV_ERROR_BUDGET && (HV_HAS_SPHERE_LIGHTS || HV_HAS_DIRECTIONAL_LIGHTS) &&                \
   HV_SPHERE_SPECULAR == HV_SPHERE_SPECULAR_REPRESENTATIVE_POINT)
#if HV_ERROR_BUDGET && !defined(HV_MAX_ERROR)
#define HV_MAX_ERROR u_frame_params.y  // frame_block.glsl
#endif
// The LTC table is read, once per pixel, when a compiled light type shades its specular with it.
#define HV_LTC_TABLE                                                                        \
  (((HV_HAS_SPHERE_LIGHTS || HV_HAS_DIRECTIONAL_LIGHTS) &&                                  \
    HV_SPHERE_SPECULAR == HV_SPHERE_SPECULAR_LTC) ||                                        \
   (HV_HAS_TUBE_LIGHTS && HV_TUBE_SPECULAR == HV_TUBE_SPECULAR_LTC) || HV_SPHERE_BUDGET)

// The light's type code (HV_LIGHT_*, gpu_records.glsl): a spot's is its shape's.
int lightType(GpuLight light) {
#if HV_HAS_SPOT_LIGHTS
  return int(light.type & HV_LIGHT_TYPE_MASK);
#else
  return int(light.type);
#endif
}

#if HV_HAS_SPOT_LIGHTS
// The spot's cone attenuation (spotAttenuation, spot.glsl) in direction L (unit, from the shading
// point toward the light's center), 1 for a light that is not a spot: a select, so a scene's
// points and spheres share one loop whether or not they are spots.
float lightCone(GpuLight light, vec3 L) {
  float a = spotAttenuation(L, light.axis_length);
  return (light.type & HV_LIGHT_SPOT_FLAG) != 0u ? a : 1.0f;
}
#endif

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

// What every light shading a pixel shares, computed once per pixel before the light loop (as
// UE4's BxDFContext): the view direction, N.V, the reflection ray of Karis eq. 11 and 19, the
// BRDF terms' factors of the view alone (brdfView), and the pixel's LTC and the magnitude of its
// lobe (ltcShadingSetup: only read, and so only computed, with an LTC mode).
struct ShadingPoint {
  vec3 P;         // world position
  vec3 V;         // unit, from P toward the eye
  vec3 R;         // reflect(-V, N): the reflection ray of the representative-point methods
  float NoV;      // max(dot(N, V), HV_MIN_NOV): the BRDF's N.V
  BrdfView brdf;  // brdfView(s, NoV): the BRDF terms' factors of the view alone
  Ltc ltc;        // the LTC of this pixel's (roughness, N.V), world space
  vec3 ltc_spec;  // ltcSpecularMagnitude: what the LTC's integral (<= 1) is multiplied by
};

// Karis 2013 "Lighting" / "Material Model": the two terms of one light. diffuseTerm: the diffuse
// lobe (Lambert or Burley) for direction Ld times diffuse_irr = I * falloff * cos (irradiance
// per unit color). specularTerm: the specular lobe for the representative direction Ls times
// spec_irr = I * falloff (N.L applied here), D scaled by spec_norm.
vec3 diffuseTerm(Surface s, ShadingPoint sp, vec3 Ld, float diffuse_irr) {
  vec3 Hd = safeNormalize(sp.V + Ld);
  float NoLd = saturate(dot(s.N, Ld));
  float LoHd = saturate(dot(Ld, Hd));
  return s.diffuse_color * (diffuseLobeForView(s.roughness, sp.brdf, NoLd, LoHd) * diffuse_irr);
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
  return specularLobeForView(s, sp.brdf, sp.NoV, NoL, NoH, dot(NxH, NxH), VoH, spec_norm) *
         (spec_irr * NoL);
}

// The LTC paths (they use ShadingPoint and specularTerm above; Ltc comes from ltc.glsl).
#include "ltc_lights.glsl"

ShadingPoint makeShadingPoint(Surface s, vec3 P, vec3 V) {
  ShadingPoint sp;
  sp.P = P;
  sp.V = V;
  sp.R = reflect(-V, s.N);
  sp.NoV = max(dot(s.N, V), HV_MIN_NOV);
  sp.brdf = brdfView(s, sp.NoV);
  ltcShadingSetup(s, V, sp.NoV, sp.ltc, sp.ltc_spec);
  return sp;
}

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
#if HV_HAS_SPOT_LIGHTS
  falloff *= lightCone(light, L);  // a point spot: exact (the cone scales the intensity)
#endif
  return shadeLight(s, sp, L, L, vec3(light.color_inv_range), falloff * saturate(dot(s.N, L)), falloff,
                    1.0f);
}
vec3 evaluatePointLight(GpuLight light, Surface s, vec3 P, vec3 V) {
  return evaluatePointLightAt(light, s, makeShadingPoint(s, P, V));
}
#endif

#if HV_HAS_SPHERE_LIGHTS || HV_HAS_DIRECTIONAL_LIGHTS
// Sphere light specular, Karis 2013 eqs. 11 and 14: the representative point of the sphere
// closest to the reflection ray, with the energy normalization (alpha / alpha')^2.
vec3 sphereSpecularRepresentativePoint(Surface s, ShadingPoint sp, vec3 Lc, float d2,
                                       float radius, float falloff) {
  vec3 Ls = safeNormalize(closestPointOnSphereToRay(Lc, radius, sp.R));
  float norm = sphereNormalization(s.alpha, radius, d2);
  return specularTerm(s, sp, Ls, falloff, norm);
}
#endif

#if (HV_HAS_SPHERE_LIGHTS || HV_HAS_DIRECTIONAL_LIGHTS) && \
    (HV_SPHERE_SPECULAR == HV_SPHERE_SPECULAR_LTC || HV_SPHERE_BUDGET)
// The sphere's LTC specular (ltc_lights.glsl): over its whole cone, or for a sphere straddling the
// surface's horizon over the part above it (ltcSphereSpecularAbove). Arguments as
// ltcSphereSpecular's; a directional light's disk is the sphere at distance 1.
vec3 sphereLtcSpecular(Surface s, ShadingPoint sp, vec3 Lc, vec3 L, float d2, float radius,
                       float falloff) {
  if (ltcSphereSpecularStraddles(s.N, Lc, d2, radius)) {
    return ltcSphereSpecularAbove(s, sp, Lc, L, d2, radius, falloff);
  }
  return ltcSphereSpecular(s, sp, Lc, L, d2, radius, falloff);
}
#endif

#if HV_HAS_SPHERE_LIGHTS
// What a sphere light's methods share at one shading point: the direction to its center, the
// falloff (with a spot's cone) and the diffuse term.
struct SphereTerms {
  vec3 Lc;        // the center, relative to the shading point
  vec3 L;         // unit, toward the center
  float d2;       // |Lc|^2
  float radius;
  float falloff;  // distanceFalloff times the spot cone
  vec3 diffuse;   // the diffuse term (diffuseTerm), before combineTerms
};

// Sphere light diffuse: from the center (Karis point approximation) or the horizon-correct
// sphere irradiance (Lagarde & de Rousiers 2014 section 4.7.2).
SphereTerms sphereTerms(GpuLight light, Surface s, ShadingPoint sp) {
  SphereTerms t;
  t.radius = light.position_radius.w;
  t.Lc = vec3(light.position_radius) - sp.P;
  t.d2 = dot(t.Lc, t.Lc);
  t.L = t.Lc * inversesqrt(max(t.d2, 1e-30f));
  t.falloff = distanceFalloff(t.d2, t.radius, light.color_inv_range.w);
#if HV_HAS_SPOT_LIGHTS
  // A sphere spot: the cone of the direction to the center scales the sphere's whole emission
  // seen from this point (docs/lights.md, "Spot lights"), diffuse and specular, in every method.
  t.falloff *= lightCone(light, t.L);
#endif
#if HV_SPHERE_DIFFUSE == HV_SPHERE_DIFFUSE_HORIZON
  // sin^2(sigma) = r^2 / d^2, with d^2 >= HV_MIN_LIGHT_DIST2 (the factor clamps it to <= 1).
  float cos_factor =
      sphereHorizonFactor(dot(s.N, t.L), t.radius * t.radius / max(t.d2, HV_MIN_LIGHT_DIST2));
#else
  float cos_factor = saturate(dot(s.N, t.L));
#endif
  // Inside the sphere the whole hemisphere emits L_e = I / (pi r^2): the irradiance pi L_e is
  // I / r^2, the falloff (whose d^2 is clamped to r^2) times 1, from the hemisphere's mean
  // direction N, whichever side of the surface the center is on (the reference's emitter and the
  // `ltc` specular alike; neither method's horizon applies there). A select.
  bool inside = t.d2 <= t.radius * t.radius;
  cos_factor = mix(cos_factor, 1.0f, inside);
  t.diffuse = diffuseTerm(s, sp, mix(t.L, s.N, bvec3(inside)), t.falloff * cos_factor);
  return t;
}

#if HV_ERROR_BUDGET
float sphereSinSigma(SphereTerms t) {
  // sin(sigma) = r / d (above 1 inside the sphere, where the budget takes the LTC).
  return t.radius * inversesqrt(max(t.d2, HV_MIN_LIGHT_DIST2));
}

// The predicted_error view's pair (sphereViewError).
vec2 sphereLightPredictedError(GpuLight light, Surface s, ShadingPoint sp) {
  SphereTerms t = sphereTerms(light, s, sp);
  vec3 rp = sphereSpecularRepresentativePoint(s, sp, t.Lc, t.d2, t.radius, t.falloff);
  return sphereViewError(s, sp.R, sp.NoV, t.L, sphereSinSigma(t), t.diffuse, rp,
                         vec3(light.color_inv_range));
}
#endif

#if HV_SPHERE_SPECULAR == HV_SPHERE_SPECULAR_LTC
// The tiled light pass's two parts of evaluateSphereLightAt (light_shade.comp): the light's
// radiance with the whole cone's LTC and whether the sphere straddles the horizon; and what the
// cut at the horizon changes in that radiance (0 where it does not straddle). The pass shades
// every pair with the first and the straddling pairs with the second, in a loop of their own: on
// a SIMD CPU implementation (llvmpipe) the cut's polygon inside the loop over lights doubled the
// many-lights pass even where no pair straddles (docs/lights.md, "Straddling spheres").
vec3 evaluateSphereLightWholeAt(GpuLight light, Surface s, ShadingPoint sp, HV_OUT(bool) straddles) {
  SphereTerms t = sphereTerms(light, s, sp);
  straddles = ltcSphereSpecularStraddles(s.N, t.Lc, t.d2, t.radius);
  vec3 specular = ltcSphereSpecular(s, sp, t.Lc, t.L, t.d2, t.radius, t.falloff);
  return combineTerms(s, vec3(light.color_inv_range), t.diffuse, specular);
}
vec3 sphereLightStraddleCorrection(GpuLight light, Surface s, ShadingPoint sp) {
  SphereTerms t = sphereTerms(light, s, sp);
  vec3 cut = ltcSphereSpecularCut(s, sp, t.Lc, t.L, t.d2, t.radius, t.falloff);
  bool straddles = ltcSphereSpecularStraddles(s.N, t.Lc, t.d2, t.radius);
  return combineTerms(s, vec3(light.color_inv_range), vec3(0.0f), straddles ? cut : vec3(0.0f));
}
#endif

#if HV_SPHERE_BUDGET
// The budget's parts (error_budget.glsl): the light's radiance with the representative point's
// specular and whether the budget takes the LTC for it; and what the LTC changes in that
// radiance, for the pairs that take it. The tiled light pass shades every pair with the first and
// the pairs that need it with the second, in a loop of their own (light_shade.comp).
vec3 evaluateSphereLightRpAt(GpuLight light, Surface s, ShadingPoint sp, HV_OUT(bool) need) {
  SphereTerms t = sphereTerms(light, s, sp);
  vec3 rp = sphereSpecularRepresentativePoint(s, sp, t.Lc, t.d2, t.radius, t.falloff);
  need = sphereNeedsLtc(s, sp.R, sp.NoV, t.L, sphereSinSigma(t), t.diffuse, rp, HV_MAX_ERROR);
  return combineTerms(s, vec3(light.color_inv_range), t.diffuse, rp);
}
vec3 sphereLightLtcCorrection(GpuLight light, Surface s, ShadingPoint sp) {
  SphereTerms t = sphereTerms(light, s, sp);
  vec3 rp = sphereSpecularRepresentativePoint(s, sp, t.Lc, t.d2, t.radius, t.falloff);
  vec3 ltc = sphereLtcSpecular(s, sp, t.Lc, t.L, t.d2, t.radius, t.falloff);
  return combineTerms(s, vec3(light.color_inv_range), vec3(0.0f), ltc - rp);
}
#endif

// Sphere light: the diffuse of sphereTerms; specular from the representative point
// (sphereSpecularRepresentativePoint) or, with HV_SPHERE_SPECULAR_LTC, the pixel's LTC over the
// sphere's cone cut at the horizon (sphereLtcSpecular), or with a budget the LTC where it asks for
// it (sphereNeedsLtc).
vec3 evaluateSphereLightAt(GpuLight light, Surface s, ShadingPoint sp) {
  SphereTerms t = sphereTerms(light, s, sp);
#if HV_SPHERE_SPECULAR == HV_SPHERE_SPECULAR_LTC
  vec3 specular = sphereLtcSpecular(s, sp, t.Lc, t.L, t.d2, t.radius, t.falloff);
#else
  vec3 specular = sphereSpecularRepresentativePoint(s, sp, t.Lc, t.d2, t.radius, t.falloff);
#if HV_SPHERE_BUDGET
  if (sphereNeedsLtc(s, sp.R, sp.NoV, t.L, sphereSinSigma(t), t.diffuse, specular,
                     HV_MAX_ERROR)) {
    specular = sphereLtcSpecular(s, sp, t.Lc, t.L, t.d2, t.radius, t.falloff);
  }
#endif
#endif
  return combineTerms(s, vec3(light.color_inv_range), t.diffuse, specular);
}
vec3 evaluateSphereLight(GpuLight light, Surface s, vec3 P, vec3 V) {
  return evaluateSphereLightAt(light, s, makeShadingPoint(s, P, V));
}
#endif

#if HV_HAS_TUBE_LIGHTS
// Tube light diffuse, Karis 2013 eq. 16: E = I (saturate(n.L0/|L0|) + saturate(n.L1/|L1|)) /
// (|L0||L1| + L0.L1 + 2), the exact irradiance of a line of total intensity I (n.L clipped at
// each end, the "+2" being the "+1" of eq. 9). |L0||L1| + L0.L1 -> 2 d^2 as len -> 0, so it
// is clamped to >= 2 max(r^2, HV_MIN_LIGHT_DIST2) as the sphere clamps d^2 (it is 0 on the
// segment itself). One inversesqrt per end; |L0||L1| from their product, no extra sqrt.
// Irradiance per unit I, windowed.
float tubeIrradianceKaris(Surface s, vec3 L0, vec3 L1, float radius, float window) {
  float l0_2 = dot(L0, L0);
  float l1_2 = dot(L1, L1);
  float inv_l0 = inversesqrt(max(l0_2, 1e-30f));
  float inv_l1 = inversesqrt(max(l1_2, 1e-30f));
  float geom = (l0_2 * inv_l0) * (l1_2 * inv_l1) + dot(L0, L1);  // paired: no overflow at 1e6 m
  float den = 2.0f * (max(0.5f * geom, max(radius * radius, HV_MIN_LIGHT_DIST2)) +
                      float(HV_FALLOFF_PLUS_ONE));
  return (saturate(dot(s.N, L0) * inv_l0) + saturate(dot(s.N, L1) * inv_l1)) / den * window;
}

// Tube light specular, Karis 2013 eqs. 18-20: the point of the segment chosen for the reflection
// ray R (closest, eq. 19, or smallest angle, eq. 18, with HV_TUBE_SPECULAR = 1), then the sphere
// representative point around it (eq. 11), normalized by alpha/alpha' (eq. 20) times the
// sphere's (alpha/alpha'')^2 (eq. 14). Lc: the segment's center, L0 its start and Ld = L1 - L0
// (ld2 = |Ld|^2) relative to the shading point; window: the falloff window.
vec3 tubeSpecularRepresentativePoint(Surface s, ShadingPoint sp, vec3 Lc, vec3 L0, vec3 Ld,
                                     float ld2, float radius, float len, float window) {
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
  return specularTerm(s, sp, Ls, spec_irr, norm);
}

// Tube light (capsule: segment of length len along axis, radius r). Diffuse: Karis's line-segment
// irradiance (tubeIrradianceKaris) or, with HV_TUBE_DIFFUSE_LTC, the capsule's irradiance with the
// identity LTC (ltcTubeIrradiance, ltc_lights.glsl); specular: the representative point
// (tubeSpecularRepresentativePoint) or, with HV_TUBE_SPECULAR_LTC, the pixel's LTC over the
// capsule (ltcTubeSpecular).
// What a tube light's terms share at one shading point: the segment's center and ends relative
// to it, the squared distance to its closest point, the falloff window there and the diffuse term.
struct TubeTerms {
  vec3 Lc;  // the segment's center
  vec3 Ld;  // L1 - L0
  vec3 L0;
  vec3 L1;
  float ld2;  // |Ld|^2
  float dp2;  // squared distance to the closest segment point
  float window;
  float radius;
  float len;
  vec3 diffuse;  // the diffuse term (diffuseTerm), before combineTerms
};

TubeTerms tubeTerms(GpuLight light, Surface s, ShadingPoint sp) {
  TubeTerms t;
  t.radius = light.position_radius.w;
  t.len = light.axis_length.w;
  t.Lc = vec3(light.position_radius) - sp.P;
  t.Ld = vec3(light.axis_length) * t.len;  // segment vector L1 - L0
  t.L0 = t.Lc - 0.5f * t.Ld;
  t.L1 = t.Lc + 0.5f * t.Ld;
  t.ld2 = dot(t.Ld, t.Ld);
  // Closest point of the segment to P: the window distance and the diffuse direction. 1e-30
  // guards 0/0 for len = 0 (then t = 0 and L0 = Lc: the sphere light).
  float tp = saturate(-dot(t.L0, t.Ld) / max(t.ld2, 1e-30f));
  vec3 Lp = t.L0 + tp * t.Ld;
  t.dp2 = dot(Lp, Lp);
  t.window = falloffWindow(t.dp2, light.color_inv_range.w);
  vec3 Ldiff = Lp * inversesqrt(max(t.dp2, 1e-30f));  // safeNormalize(Lp) reusing dp2
#if HV_TUBE_DIFFUSE == HV_TUBE_DIFFUSE_LTC
  float irradiance = ltcTubeIrradiance(s, t.L0, t.L1, t.dp2, t.radius, t.len, t.window);
#else
  float irradiance = tubeIrradianceKaris(s, t.L0, t.L1, t.radius, t.window);
#endif
  t.diffuse = diffuseTerm(s, sp, Ldiff, irradiance);
  return t;
}

vec3 evaluateTubeLightAt(GpuLight light, Surface s, ShadingPoint sp) {
  TubeTerms t = tubeTerms(light, s, sp);
#if HV_TUBE_SPECULAR == HV_TUBE_SPECULAR_LTC
  vec3 specular = ltcTubeSpecular(s, sp, t.Lc, t.Ld, t.L0, t.L1, t.dp2, t.radius, t.len, t.window);
#else
  vec3 specular =
      tubeSpecularRepresentativePoint(s, sp, t.Lc, t.L0, t.Ld, t.ld2, t.radius, t.len, t.window);
#endif
  return combineTerms(s, vec3(light.color_inv_range), t.diffuse, specular);
}

#if HV_TUBE_SPECULAR == HV_TUBE_SPECULAR_LTC
// The tiled light pass's two parts of evaluateTubeLightAt (light_shade.comp), as the sphere's
// (evaluateSphereLightWholeAt): the light's radiance with the whole capsule's LTC and whether
// the capsule straddles the horizon; and what the cut at the horizon changes in it.
vec3 evaluateTubeLightWholeAt(GpuLight light, Surface s, ShadingPoint sp, HV_OUT(bool) straddles) {
  TubeTerms t = tubeTerms(light, s, sp);
  straddles = ltcTubeSpecularStraddles(s, t.L0, t.L1, t.dp2, t.radius);
  vec3 specular = ltcTubeSpecularOver(s, sp, t.Lc, t.Ld, t.L0, t.L1, t.dp2, t.radius, t.len,
                                      t.window, false);
  return combineTerms(s, vec3(light.color_inv_range), t.diffuse, specular);
}
vec3 tubeLightStraddleCorrection(GpuLight light, Surface s, ShadingPoint sp) {
  TubeTerms t = tubeTerms(light, s, sp);
  vec3 above = ltcTubeSpecularOver(s, sp, t.Lc, t.Ld, t.L0, t.L1, t.dp2, t.radius, t.len,
                                   t.window, true);
  vec3 whole = ltcTubeSpecularOver(s, sp, t.Lc, t.Ld, t.L0, t.L1, t.dp2, t.radius, t.len,
                                   t.window, false);
  bool straddles = ltcTubeSpecularStraddles(s, t.L0, t.L1, t.dp2, t.radius);
  return combineTerms(s, vec3(light.color_inv_range), vec3(0.0f),
                      straddles ? above - whole : vec3(0.0f));
}
#endif
vec3 evaluateTubeLight(GpuLight light, Surface s, vec3 P, vec3 V) {
  return evaluateTubeLightAt(light, s, makeShadingPoint(s, P, V));
}
#endif
#if HV_HAS_DIRECTIONAL_LIGHTS
// Directional light: a distant disk of uniform radiance seen under the angular radius sigma (the
// sun of Lagarde & de Rousiers 2014, section 4.7), whose illuminance at normal incidence is E.
// Seen from the shading point it is the cone of directions of a sphere of radius sin(sigma) at
// distance 1, so the sphere light's code shades it exactly as it shades that sphere, with E in
// place of the falloff I / d^2 (a sphere's irradiance at normal incidence): diffuse from the
// center direction (Karis point approximation, exact while the disk is above the horizon) or
// the horizon-clipped disk (Lagarde & de Rousiers 2014 section 4.7.2, their illuminance of a
// sphere or disk); specular from the representative point, the disk's direction closest to R
// (Karis 2013 eq. 11; Lagarde & de Rousiers 2014 listing 9 for the sun), with the normalization
// of eq. 14 at sin(sigma) / 1, or the pixel's LTC over the cone (HV_SPHERE_SPECULAR_LTC). A disk
// of angular radius 0 is a single direction: the point-light limit of either method.
vec3 evaluateDirectionalLightAt(GpuLight light, Surface s, ShadingPoint sp) {
  vec3 L = vec3(light.position_radius);  // unit, toward the light
  float sin_sigma = light.position_radius.w;
#if HV_SPHERE_DIFFUSE == HV_SPHERE_DIFFUSE_HORIZON
  float cos_factor = sphereHorizonFactor(dot(s.N, L), sin_sigma * sin_sigma);
#else
  float cos_factor = saturate(dot(s.N, L));
#endif
  vec3 diffuse = diffuseTerm(s, sp, L, cos_factor);
#if HV_SPHERE_SPECULAR == HV_SPHERE_SPECULAR_LTC
  vec3 specular = sphereLtcSpecular(s, sp, L, L, 1.0f, sin_sigma, 1.0f);
#else
  vec3 specular = sphereSpecularRepresentativePoint(s, sp, L, 1.0f, sin_sigma, 1.0f);
#if HV_SPHERE_BUDGET
  if (sphereNeedsLtc(s, sp.R, sp.NoV, L, sin_sigma, diffuse, specular, HV_MAX_ERROR)) {
    specular = sphereLtcSpecular(s, sp, L, L, 1.0f, sin_sigma, 1.0f);
  }
#endif
#endif
  return combineTerms(s, vec3(light.color_inv_range), diffuse, specular);
}
#if HV_ERROR_BUDGET
// The predicted_error view's pair (sphereViewError) for the sun: the representative point with
// the Karis point diffuse, as the budget judges it.
vec2 directionalLightPredictedError(GpuLight light, Surface s, ShadingPoint sp) {
  vec3 L = vec3(light.position_radius);
  float sin_sigma = light.position_radius.w;
  vec3 diffuse = diffuseTerm(s, sp, L, saturate(dot(s.N, L)));
  vec3 rp = sphereSpecularRepresentativePoint(s, sp, L, 1.0f, sin_sigma, 1.0f);
  return sphereViewError(s, sp.R, sp.NoV, L, sin_sigma, diffuse, rp,
                         vec3(light.color_inv_range));
}
#endif
vec3 evaluateDirectionalLight(GpuLight light, Surface s, vec3 P, vec3 V) {
  return evaluateDirectionalLightAt(light, s, makeShadingPoint(s, P, V));
}
#endif

// Karis 2013 "Lighting": outgoing radiance at P toward V (unit, from P to the eye) from one light,
// for surface s (docs/lights.md).
// Cavity is applied to all of it (see shadeLight). Only the compiled light types are handled;
// a light of a type compiled out contributes 0.
vec3 evaluateLightAt(GpuLight light, Surface s, ShadingPoint sp) {
  int type = lightType(light);
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
#if HV_HAS_DIRECTIONAL_LIGHTS
  if (type == HV_LIGHT_DIRECTIONAL) result = evaluateDirectionalLightAt(light, s, sp);
#endif
  return result;
}
vec3 evaluateLight(GpuLight light, Surface s, vec3 P, vec3 V) {
  return evaluateLightAt(light, s, makeShadingPoint(s, P, V));
}

// Karis 2013 eq. 9 (the window bounds the light): world-space radius, around the light
// position, outside which the light contributes exactly 0 (the window is 0 beyond range R of the
// nearest emitting point): R for points and spheres, R + len/2 for tubes. Precomputed by
// packLight; the shadow map's far distance.
float lightCullRadius(GpuLight light) { return light.cull_radius; }

// The world-space sphere (center, radius) outside which the light contributes exactly 0, for
// tiled culling: the range sphere, or for a spot the bounding sphere of its cone's sector
// (spotBoundingSphere: its cone attenuation is 0 outside the outer cone).
vec4 lightCullSphere(GpuLight light) {
  vec3 p = vec3(light.position_radius.x, light.position_radius.y, light.position_radius.z);
  vec4 sphere = vec4(p, lightCullRadius(light));
#if HV_HAS_SPOT_LIGHTS
  if ((light.type & HV_LIGHT_SPOT_FLAG) != 0u) {
    sphere = spotBoundingSphere(p, light.axis_length, lightCullRadius(light));
  }
#endif
  return sphere;
}

#if HV_SHADOWS && !defined(HV_CPP)
// The shadow of light l at the light pass's receivers (shadows.glsl): its map is cube
// shadow_cube - 1 of the atlas (-1: none), distances over the culling radius; the emitter's
// radius, axis and length size PCSS's penumbra. Multiplies the light's whole contribution, diffuse and specular
// (light_shade.comp). For a point, sphere, tube or spot light: the tiled loops, which know the
// type, call it (and sunShadowVisibility for directional lights) directly.
vec4 lightShadow(GpuLight l, vec3 P[HV_SHADOW_RECEIVERS], vec3 N[HV_SHADOW_RECEIVERS], bvec4 use) {
  float len = l.axis_length.w;
#if HV_HAS_SPOT_LIGHTS
  // A spot's axis_length is its cone: its emitter is its point or sphere (length 0), and its map
  // is a point light's whole cube.
  len = (l.type & HV_LIGHT_SPOT_FLAG) != 0u ? 0.0f : len;
#endif
  return shadowVisibility(vec3(l.position_radius), lightCullRadius(l), float(l.shadow_cube) - 1.0f,
                          l.position_radius.w, vec3(l.axis_length), len, P, N, use);
}

// The shadow of a light of any type, for the loops that mix them (brute force, the forward
// pass): a directional light's map is orthographic (sunShadowVisibility). The branch is uniform,
// one light for the whole invocation.
vec4 anyLightShadow(GpuLight l, vec3 P[HV_SHADOW_RECEIVERS], vec3 N[HV_SHADOW_RECEIVERS],
                    bvec4 use) {
#if HV_HAS_DIRECTIONAL_LIGHTS
  if (lightType(l) == HV_LIGHT_DIRECTIONAL) {
    return sunShadowVisibility(float(l.shadow_cube) - 1.0f, P, N, use);
  }
#endif
  return lightShadow(l, P, N, use);
}
#endif

#endif
