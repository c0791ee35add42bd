// Image-based lighting math shared by the ambient pass and the CPU bake (engine/ibl). See
// halfvec/shading/glsl.hpp for the GLSL/C++ rules. Roughness is perceptual (the material value);
// alpha = roughness^2 (Karis 2013).
#ifndef HV_IBL_GLSL
#define HV_IBL_GLSL

#include "math.glsl"
#include "brdf.glsl"
#include "setting_values.glsl"

#ifndef HV_IBL_DIRECTION
#define HV_IBL_DIRECTION HV_IBL_DIRECTION_DOMINANT
#endif

// --- Prefiltered radiance: roughness <-> mip ------------------------------------------------
// Mip 0 is the unfiltered environment (roughness 0); the last mip holds roughness 1. The mapping
// lod = maxMip * r * (2 - r) (Filament, "Physically Based Rendering in Filament", section
// "IBL / pre-filtered importance sampling": perceptualRoughnessToLod) spends more mips on low
// roughness, where the GGX lobe changes fastest. Its inverse is r = 1 - sqrt(1 - lod / maxMip).
float roughnessToMip(float roughness, float maxMip) {
  float r = saturate(roughness);
  return maxMip * r * (2.0f - r);
}
float mipToRoughness(float mip, float maxMip) {
  if (maxMip <= 0.0f) return 0.0f;
  return 1.0f - sqrt(saturate(1.0f - mip / maxMip));
}

// --- Prefiltered radiance: the direction it is read along -----------------------------------
// The prefilter assumes n = v = r (Karis 2013 eq. 7), so its lobe is centred on R. The lobe of a
// rough BRDF times NoL is not: its peak moves from R towards N as roughness grows (the
// off-specular peak), and at roughness 1 it is nearly the cosine lobe around N. Read along R, a
// rough surface takes the environment from where R points (the ground, for the lower half of a
// rough metal plane facing the camera), not from where its lobe does. Lagarde & de Rousiers 2014,
// "Moving Frostbite to Physically Based Rendering 3.0", section 4.9.3, listing 22
// (getSpecularDominantDir), fitted to GGX with height-correlated Smith: the direction is
// lerp(N, R, f), f = s (sqrt(s) + alpha), s = 1 - alpha (their "roughness" is alpha). At the glossy
// end the fit's shift away from R is linear in alpha (1 - f ~ alpha / 2), while a lobe of width
// ~alpha times N.L has its peak moved by ~alpha^2 tan(theta): for a mirror-like lobe the fit moves
// a sun's glint by about its own width. Below alpha = 0.1 (roughness 0.32) the shift is therefore
// faded out linearly, so it is quadratic in alpha there; above, the listing is unchanged (measured:
// docs/ibl.md). Normalized here, so that the C++ callers get a unit vector (a cube lookup would
// not need it).
vec3 specularDominantDirection(vec3 N, vec3 R, float alpha) {
  float s = saturate(1.0f - alpha);
  float f = s * (sqrt(s) + alpha);
  f = 1.0f - (1.0f - f) * saturate(alpha * 10.0f);
  return normalize(mix(N, R, f));
}

// The direction the prefiltered radiance is read along for a surface of normal N, mirror direction
// R and alpha (RenderSettings::ibl_direction: the dominant direction, or R as in Karis 2013).
vec3 prefilteredDirection(vec3 N, vec3 R, float alpha) {
#if HV_IBL_DIRECTION == HV_IBL_DIRECTION_REFLECT
  return R;
#else
  return specularDominantDirection(N, R, alpha);
#endif
}

// --- Split-sum specular ---------------------------------------------------------------------
// Karis 2014, "Physically Based Shading on Mobile": analytic fit of the env BRDF table (Karis
// 2013 eq. 8), returns specColor * scale + bias.
vec3 EnvBRDFApprox(vec3 specColor, float roughness, float NoV) {
  const vec4 c0 = vec4(-1.0f, -0.0275f, -0.572f, 0.022f);
  const vec4 c1 = vec4(1.0f, 0.0425f, 1.04f, -0.04f);
  vec4 r = roughness * c0 + c1;
  float a004 = min(r.x * r.x, exp2(-9.28f * NoV)) * r.x + r.y;
  float scale = -1.04f * a004 + r.z;
  float bias = 1.04f * a004 + r.w;
  return specColor * scale + bias;
}

// The same fit as (scale, bias), for energyCompensation() when no table is bound.
vec2 EnvBRDFApproxScaleBias(float roughness, float NoV) {
  vec3 sb = EnvBRDFApprox(vec3(1.0f, 0.0f, 0.0f), roughness, NoV);
  return vec2(sb.x - sb.y, sb.y);
}

// Split-sum specular of Karis 2013 eq. 8: prefiltered radiance times (F0 * scale + bias).
vec3 specularIBL(vec3 prefiltered, vec3 f0, vec2 scaleBias) {
  return prefiltered * (f0 * scaleBias.x + scaleBias.y);
}

// Multiple-scattering energy compensation for the specular lobe: Fdez-Aguera 2019, "A
// Multiple-Scattering Microfacet Model for Real-Time Image-based Lighting", in the form of the
// Filament documentation (section "Energy loss in specular reflectance"): the single-scattering
// albedo of a white (F0 = 1) surface is E = scale + bias, and the specular lobe is scaled by
// 1 + F0 * (1 / E - 1), so a white furnace reflects exactly 1. Multiply it into the specular
// term of both the image-based and the analytic lights. E is clamped away from 0 (it never goes
// below ~0.4 for GGX, so the clamp only guards bad input).
vec3 energyCompensation(vec3 f0, vec2 scaleBias) {
  float E = max(scaleBias.x + scaleBias.y, 1e-4f);
  return 1.0f + f0 * (1.0f / E - 1.0f);
}

// Lagarde & de Rousiers 2014, "Moving Frostbite to Physically Based Rendering 3.0", section
// 4.10.2, listing 26 (computeSpecOcclusion): specular occlusion from ambient occlusion. Their
// `roughness` is alpha (the squared perceptual roughness).
float specularOcclusion(float NoV, float ao, float alpha) {
  return saturate(pow(NoV + ao, exp2(-16.0f * alpha - 1.0f)) - 1.0f + ao);
}

// --- The ambient terms of a surface -----------------------------------------------------------
// How the image-based terms combine, written once for the ambient pass (ambient.comp) and the
// CPU reference (which integrates the environment instead of looking it up, but weights the terms
// the same way). Diffuse (Lambert): albedo / pi times irradiance, occluded by the cavity (Karis
// 2013, "Material Model": cavity on ambient diffuse).
vec3 ambientDiffuse(Surface s, vec3 irradiance) {
  return s.diffuse_color * irradiance * (INV_PI * s.cavity);
}

// The factor the ambient specular is multiplied by: the multiple-scattering energy compensation
// (energyCompensation) and the specular occlusion from the cavity (specularOcclusion), each when
// enabled (RenderSettings::energy_compensation, ::specular_occlusion). `scaleBias` is the env BRDF
// (scale, bias) at (NoV, roughness).
vec3 ambientSpecularScale(Surface s, vec2 scaleBias, float NoV, bool energy_compensation,
                          bool specular_occlusion) {
  vec3 scale = vec3(1.0f);
  if (energy_compensation) scale = energyCompensation(s.f0, scaleBias);
  if (specular_occlusion) scale = scale * specularOcclusion(NoV, s.cavity, s.alpha);
  return scale;
}

// Split-sum ambient specular (Karis 2013 eq. 8) with ambientSpecularScale.
vec3 ambientSpecular(Surface s, vec3 prefiltered, vec2 scaleBias, float NoV,
                     bool energy_compensation, bool specular_occlusion) {
  return specularIBL(prefiltered, s.f0, scaleBias) *
         ambientSpecularScale(s, scaleBias, NoV, energy_compensation, specular_occlusion);
}

// --- Diffuse: order-2 spherical harmonics ---------------------------------------------------
// Coefficient order (l, m): (0,0) (1,-1) (1,0) (1,1) (2,-2) (2,-1) (2,0) (2,1) (2,2); basis
// functions of Ramamoorthi & Hanrahan 2001 eq. 3 in world axes (x, y, z) of the direction:
// 0.282095; 0.488603 y, z, x; 1.092548 xy, yz; 0.315392 (3z^2 - 1); 1.092548 xz;
// 0.546274 (x^2 - y^2). sh[] holds the radiance coefficients L_lm (projectSH9 in engine/ibl).
// Returns irradiance E(n) by eq. 13 with the eq. 12 constants (Lambert diffuse = albedo/PI * E).
vec3 evalSH9Irradiance(vec3 sh[9], vec3 n) {
  const float c1 = 0.429043f;
  const float c2 = 0.511664f;
  const float c3 = 0.743125f;
  const float c4 = 0.886227f;
  const float c5 = 0.247708f;
  float x = n.x;
  float y = n.y;
  float z = n.z;
  vec3 e = c1 * sh[8] * (x * x - y * y) + c3 * sh[6] * (z * z) + c4 * sh[0] - c5 * sh[6];
  e += 2.0f * c1 * (sh[4] * (x * y) + sh[7] * (x * z) + sh[5] * (y * z));
  e += 2.0f * c2 * (sh[3] * x + sh[1] * y + sh[2] * z);
  return max(e, vec3(0.0f));
}

#endif
