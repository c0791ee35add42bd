// Image-based lighting math shared by the ambient pass and the CPU bake (engine/ibl). See
// halfvec/shading/glsl.hpp for the GLSL/C++ rules. Roughness is perceptual (the material value);
// alpha = roughness^2 (Karis 2013).
#ifndef HV_IBL_GLSL
#define HV_IBL_GLSL

#include "math.glsl"
#include "brdf.glsl"
#include "sampling.glsl"
#include "setting_values.glsl"

#ifndef HV_IBL_DIRECTION
#define HV_IBL_DIRECTION HV_IBL_DIRECTION_DOMINANT
#endif
#ifndef HV_IBL_SPECULAR
#define HV_IBL_SPECULAR HV_IBL_SPECULAR_SPLIT_SUM
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

// The mip a surface of perceptual roughness r reads its ambient specular from. From mip 1 up, the
// mip prefiltered at r (roughnessToMip). Below mip 1's roughness r1 the lobe is narrower than any
// prefiltered one, and a blend of mip 0 (the environment) and mip 1 stands in for it. GGX far from
// its peak is D ~ alpha^2 / (pi tan^4 theta) (Walter et al. 2007, eq. 33, for tan theta >> alpha),
// so the lobe's tail is (alpha / alpha1)^2 times mip 1's while its core lies within a texel of mip
// 0: a weight (alpha / alpha1)^2 = (r / r1)^4 of mip 1 keeps the tail's light, where the linear
// blend of roughnessToMip (lod 0.44 at roughness 0.045 for a 256^2 cube) gave small bright sources
// a halo 2-14 times the reference's around a dimmed core (docs/ibl.md, "Glossy lookups").
float specularLookupMip(float roughness, float maxMip) {
  if (maxMip < 1.0f) return roughnessToMip(roughness, maxMip);
  float r1 = mipToRoughness(1.0f, maxMip);
  float r = saturate(roughness);
  if (r >= r1) return roughnessToMip(r, maxMip);
  float q = r / r1;
  q *= q;
  return q * q;
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

// --- Lobe-sampled prefiltered radiance (ibl_specular: sampled) --------------------------------
// The split sum (Karis 2013 eq. 8) reads one prefiltered texel, filtered for n = v = r, whatever
// the view. At grazing angles the real lobe is stretched, leans towards N and is cut by the
// horizon, and one lookup along any direction cannot follow it (docs/ibl.md, "Lobe-sampled
// ambient specular"). `sampled` keeps the split sum's second factor, the env BRDF (scale, bias),
// which the table holds exactly, and replaces its first, the prefiltered radiance, by the
// radiance averaged over the pixel's own lobe: kIblLobeSamples directions drawn from GGX's
// visible normals at the pixel's V (Heitz 2018; sampleGGXVNDF), each read from the prefiltered
// cube at the mip whose lobe covers the sample's share of the solid angle (filtered importance
// sampling: Colbert & Krivanek 2007, "GPU-Based Importance Sampling", GPU Gems 3 chapter 20,
// eq. 13, with the prefiltered mips in place of a box-filtered chain). Only where the split sum
// is off (iblSampledWeight): rough surfaces seen at grazing angles.
// Two averages, weighted as the table's two integrals are (Karis 2013 eq. 8: scale sums
// (1 - Fc) G, bias sums Fc G, Fc = (1 - VoH)^5), because the Fresnel part's lobe lies nearer R at
// grazing angles than the F0 part's. The weights' G is the exact height-correlated Smith
// masking-shadowing of GGX (Heitz 2014 eq. 99) whatever the scene's V term: they only place the
// lobe's weight, the table still sets its size; the visible-normal pdf's G1(V) / NoV is the same
// for every sample and cancels in the averages. A uniform environment therefore gives exactly the
// split sum. The pattern is a fixed Hammersley set (no noise) and its mirror image, laid out in the
// frame whose x axis is V's tangent part: symmetric about the plane of incidence, as the lobe is.
const uint kIblLobeSamples = 16u;

// The frame of the lobe: T along V's part in the tangent plane (any tangent where V = N),
// B = N x T.
void iblLobeFrame(vec3 N, vec3 V, float NoV, HV_OUT(vec3) T, HV_OUT(vec3) B) {
  vec3 Vt = V - N * NoV;
  float len2 = dot(Vt, Vt);
  if (len2 > 1e-12f) {
    T = Vt * inversesqrt(len2);
    B = cross(N, T);
  } else {
    tangentFrame(N, T, B);
  }
}

// Sample i of n of the lobe of a surface of normal N (frame T, B), view cos NoV (> 0) and alpha:
// returns the direction L (xyz) and the mip to read it at (w); `weight` gets the sample's (1 - Fc)
// G and Fc G, both 0 for a direction below the horizon. `faceSize`: mip 0's face size in texels;
// `maxMip`: the mip of roughness 1 (roughnessToMip).
vec4 iblLobeSample(uint i, uint n, vec3 N, vec3 T, vec3 B, float NoV, float alpha, float faceSize,
                   float maxMip, HV_OUT(vec2) weight) {
  float sinV = sqrt(max(0.0f, 1.0f - NoV * NoV));
  vec3 Vl = vec3(sinV, 0.0f, NoV);  // V in the lobe's frame
  // Hammersley points of m = ceil(n / 2) in the half 0 < phi < pi, moved to the middle of their
  // strata, and their mirror images (phi -> 2 pi - phi) about the plane of incidence.
  uint m = (n + 1u) / 2u;
  uint j = i < m ? i : i - m;
  float x = (float(j) + 0.5f) / float(2u * m);
  vec2 u = vec2(i < m ? x : 1.0f - x, radicalInverseVdC(j) + 0.5f / float(m));
  vec3 H = sampleGGXVNDF(Vl, alpha, u);
  float VoH = dot(Vl, H);
  vec3 Ll = 2.0f * VoH * H - Vl;
  float NoL = Ll.z;
  weight = vec2(0.0f);
  if (NoL > 0.0f && VoH > 0.0f) {
    // Heitz 2014 eq. 99 with Lambda from the roots sqrt(a^2 + (1 - a^2) cos^2): G2 = 2 NoV NoL /
    // (NoL root(V) + NoV root(L)).
    float G2 = 2.0f * NoV * NoL / (NoL * smithGgxRoot(alpha, NoV) + NoV * smithGgxRoot(alpha, NoL));
    float Fc = pow5(1.0f - VoH);
    weight = vec2((1.0f - Fc) * G2, Fc * G2);
  }
  // Filtered importance sampling: the sample stands for the solid angle 1 / (n pdf(L)), pdf(L) =
  // D_V(H) / (4 VoH) (Heitz 2018 eq. 3 and Walter et al. 2007 eq. 14). The prefiltered mip of
  // roughness r holds a lobe whose peak pdf, 1 / (4 pi alpha_r^2) at n = v = r, spreads over about
  // 4 pi alpha_r^2: the mip whose lobe covers the sample's solid angle has alpha_r^2 = omega /
  // (4 pi), biased below. A lobe narrower than mip 0's texels reads mip 0 (the environment).
  float pdf = pdfGGXVNDF(Vl, H, alpha) / max(4.0f * VoH, 1e-8f);
  float omega = 1.0f / (float(n) * max(pdf, 1e-8f));
  float texel = 4.0f * PI / (6.0f * faceSize * faceSize);
  // The paper biases the lookup by one mip (eq. 13's "+ 1": four times the solid angle) so that
  // the filtered samples overlap; with 16 fixed samples over a stretched grazing lobe and a small
  // bright source (a sun), two mips (16 times) measured closer to the reference than one in three
  // environments (docs/ibl.md, "Lobe-sampled ambient specular").
  float r = omega > texel ? sqrt(sqrt(16.0f * omega / (4.0f * PI))) : 0.0f;
  vec3 L = T * Ll.x + B * Ll.y + N * Ll.z;
  return vec4(L, roughnessToMip(r, maxMip));
}

// Where the samples replace the split sum's texel: the split sum's n = v = r assumption holds for a
// surface seen face on and for a narrow lobe (measured within a few percent at N.V >= 0.4 and at
// roughness <= 0.25 on sphere_grid, docs/ibl.md), and fails at grazing angles on rough surfaces.
// The weight goes from 0 to 1 as N.V falls from 0.4 to 0.2 and the roughness rises from 0.25 to
// 0.45; between, the two are blended, so no seam shows where one method takes over.
float iblSampledWeight(float NoV, float roughness) {
  return saturate((0.4f - NoV) * 5.0f) * saturate((roughness - 0.25f) * 5.0f);
}

// The lobe's two weighted radiance sums and their weights (see iblLobeSample).
struct IblLobeSum {
  vec3 a;  // sum of (1 - Fc) G L
  vec3 b;  // sum of Fc G L
  float wa;
  float wb;
};

void addLobeSample(HV_INOUT(IblLobeSum) sum, vec3 radiance, vec2 weight) {
  sum.a += radiance * weight.x;
  sum.b += radiance * weight.y;
  sum.wa += weight.x;
  sum.wb += weight.y;
}

// The sampled ambient specular before ambientSpecularScale: f0 x scale x (the F0 part's mean
// radiance) + bias x (the Fresnel part's), Karis 2013 eq. 8's two integrals with the radiance
// inside them; `fallback` (the split sum's prefiltered radiance) where no sample is above the
// horizon.
vec3 sampledSpecularIBL(IblLobeSum sum, vec3 fallback, vec3 f0, vec2 scaleBias) {
  vec3 la = sum.wa > 0.0f ? sum.a / sum.wa : fallback;
  vec3 lb = sum.wb > 0.0f ? sum.b / sum.wb : fallback;
  return f0 * (la * scaleBias.x) + lb * scaleBias.y;
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

#ifndef HV_CPP
// The mean radiance over the lobe, read from the prefiltered cube `radiance` (GLSL only: the
// lookups are the GPU's; the CPU side tests the samples and the sums above).
vec3 sampledAmbientSpecular(samplerCube radiance, Surface s, vec3 V, float NoV, vec3 fallback,
                            vec2 scaleBias, float maxMip) {
  vec3 T;
  vec3 B;
  iblLobeFrame(s.N, V, NoV, T, B);
  float faceSize = float(textureSize(radiance, 0).x);
  IblLobeSum sum;
  sum.a = vec3(0.0f);
  sum.b = vec3(0.0f);
  sum.wa = 0.0f;
  sum.wb = 0.0f;
  for (uint i = 0u; i < kIblLobeSamples; ++i) {
    vec2 w;
    vec4 l = iblLobeSample(i, kIblLobeSamples, s.N, T, B, NoV, s.alpha, faceSize, maxMip, w);
    addLobeSample(sum, textureLod(radiance, l.xyz, l.w).rgb, w);
  }
  return sampledSpecularIBL(sum, fallback, s.f0, scaleBias);
}

// ambientSpecular of surface s seen from V with the radiance the setting ibl_specular reads: the
// split sum's `prefiltered` texel, or the mean over the lobe's samples from `cube`.
vec3 ambientSpecularFromCube(samplerCube cube, Surface s, vec3 V, vec3 prefiltered, vec2 scaleBias,
                             float NoV, float maxMip, bool energy_compensation,
                             bool specular_occlusion) {
#if HV_IBL_SPECULAR == HV_IBL_SPECULAR_SAMPLED
  vec3 specular = specularIBL(prefiltered, s.f0, scaleBias);
  float w = iblSampledWeight(NoV, s.roughness);
  if (w > 0.0f) {
    specular =
        mix(specular, sampledAmbientSpecular(cube, s, V, NoV, prefiltered, scaleBias, maxMip), w);
  }
  return specular *
         ambientSpecularScale(s, scaleBias, NoV, energy_compensation, specular_occlusion);
#else
  return ambientSpecular(s, prefiltered, scaleBias, NoV, energy_compensation, specular_occlusion);
#endif
}
#endif

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
