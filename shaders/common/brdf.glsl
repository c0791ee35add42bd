// BRDF terms of the UE4 shading model (Karis 2013, "Real Shading in Unreal Engine 4") and the
// alternatives it compares, shared by GLSL and C++ (see halfvec/shading/glsl.hpp for the rules).
//
// Conventions:
//  - roughness is perceptual roughness in [0,1]; alpha = roughness^2 (Karis 2013, "Specular D").
//  - V is the visibility term V = G / (4 NoL NoV), so the specular BRDF is D * V * F.
//  - Every term is always compiled; the define table below only picks what the dispatchers
//    (distribution(), visibility(), fresnel(), diffuseLobe()) call, so C++ can switch at run time
//    over the very same functions (halfvec/shading/brdf.hpp). Table and defaults: docs/brdf.md.
#ifndef HV_BRDF_GLSL
#define HV_BRDF_GLSL

#include "math.glsl"
// ---- Define table (Filament style): the values are in setting_values.glsl ----
#include "setting_values.glsl"

// Defaults = Karis 2013: GGX, Schlick-GGX, Schlick Fresnel, Lambert, Disney roughness remap.
#ifndef HV_BRDF_D
#define HV_BRDF_D HV_D_GGX
#endif
#ifndef HV_BRDF_V
#define HV_BRDF_V HV_V_SCHLICK_GGX
#endif
#ifndef HV_BRDF_F
#define HV_BRDF_F HV_F_SCHLICK
#endif
#ifndef HV_BRDF_FD
#define HV_BRDF_FD HV_FD_LAMBERT
#endif
#ifndef HV_REMAP_ROUGHNESS
#define HV_REMAP_ROUGHNESS 1
#endif

// Smallest perceptual roughness shaded. A perfectly smooth surface lit by a punctual light is a
// Dirac peak (D = 1/(pi alpha^2) -> inf); 0.045 (Filament's MIN_PERCEPTUAL_ROUGHNESS) keeps
// alpha^2 = 4.1e-6 > 0 so D <= 7.8e4 and every V term stays finite at NoV = NoL = 0.
const float HV_MIN_ROUGHNESS = 0.045f;
// Smallest NoV shaded (Filament MIN_N_DOT_V). Normals facing away from the viewer (normal maps,
// interpolated normals) give NoV <= 0; 1e-4 keeps every V term finite without visible bias.
const float HV_MIN_NOV = 1e-4f;

// ---- Normal distribution functions D(h); each satisfies integral D(h) (n.h) dw = 1 ----

// Each D takes sin2_NH = 1 - NoH^2 besides NoH. Near the mirror direction NoH rounds to within
// 2^-24 of 1 and 1 - NoH^2 computed from it cancels: at roughness 0.045 (alpha^2 = 4.1e-6) one
// ulp of NoH moves D_GGX's denominator by 3% (the peak came out 2.9% low at roughness 0.05 and
// about 6% at 0.045). Callers that have the vectors pass |N x H|^2 (as Filament's D_GGX does),
// which is exact to float precision however small; the two-argument forms compute it from NoH as
// (1 - NoH)(1 + NoH), exact for the NoH given. tests/shading/test_brdf.cpp,
// Brdf.GgxPeakMatchesDoublePrecision, checks D against double precision at roughness 0.045-0.1.

// Walter et al. 2007, "Microfacet Models for Refraction through Rough Surfaces", eq. 33;
// Karis 2013 eq. 2 (GGX / Trowbridge-Reitz): a^2 / (pi (NoH^2 (a^2 - 1) + 1)^2), the bracket
// written as sin2_NH + NoH^2 a^2 (two positive terms: no cancellation). For a unit H the bracket
// is a^2 + sin2_NH (1 - a^2) >= a^2, so max(., a^2) changes nothing but rounding; it keeps D at
// its peak value, finite, for the zero H of V = -L (safeNormalize), where both terms are 0.
float D_GGX(float alpha, float NoH, float sin2_NH) {
  float a2 = alpha * alpha;
  float d = max(sin2_NH + NoH * NoH * a2, a2);
  return a2 / (PI * d * d);
}
float D_GGX(float alpha, float NoH) { return D_GGX(alpha, NoH, (1.0f - NoH) * (1.0f + NoH)); }

// Walter et al. 2007 eq. 25 (Beckmann): exp(-tan^2/a^2) / (pi a^2 cos^4), with
// tan^2 = sin2_NH / cos^2 so no trigonometry is needed.
float D_Beckmann(float alpha, float NoH, float sin2_NH) {
  float a2 = alpha * alpha;
  // cos^2 >= 1e-8 (NoH >= 1e-4): at a grazing half vector exp(-inf) / 0 would be 0/0; with the
  // clamp the exponent is <= -1e8 sin2_NH / a2 and the result is 0, as the limit is. cos^2 is
  // also >= 1 - sin2_NH, which only matters for the zero H of V = -L (NoH = sin2_NH = 0): D is
  // then its finite peak value, as D_GGX's.
  float c2 = max(max(NoH * NoH, 1.0f - sin2_NH), 1e-8f);
  return exp(-sin2_NH / (a2 * c2)) / (PI * a2 * c2 * c2);
}
float D_Beckmann(float alpha, float NoH) {
  return D_Beckmann(alpha, NoH, (1.0f - NoH) * (1.0f + NoH));
}

// Blinn 1977 with the normalization (n+2)/(2 pi) and exponent n = 2/alpha^2 - 2 (Walter et al.
// 2007 eq. 30; Karis 2013 "Specular D"), so (n+2)/(2 pi) = 1/(pi alpha^2). NoH^n = exp(n ln NoH)
// with ln NoH = ln(1 - sin2_NH) / 2; for sin2_NH < 0.01 its series -s (1 + s/2 + s^2/3 + s^3/4)
// (truncation < 2e-9 relative), which keeps the precision of sin2_NH where n is large.
float D_BlinnPhong(float alpha, float NoH, float sin2_NH) {
  float a2 = alpha * alpha;
  float n = 2.0f / a2 - 2.0f;
  float s = sin2_NH;
  float ln_series = -0.5f * s * (1.0f + s * (0.5f + s * (1.0f / 3.0f + s * 0.25f)));
  // NoH >= 1e-6 keeps log() finite at a grazing half vector (the result, exp(-n 13.8), is 0 for
  // n > 3, and 1 for n = 0 as pow(0, 0) would be).
  float ln_direct = log(max(NoH, 1e-6f));
  float ln_noh = mix(ln_direct, ln_series, step(s, 0.01f));
  return INV_PI / a2 * exp(n * ln_noh);
}
float D_BlinnPhong(float alpha, float NoH) {
  return D_BlinnPhong(alpha, NoH, (1.0f - NoH) * (1.0f + NoH));
}

// ---- Smith masking G1 (used by the separable V terms and by VNDF sampling) ----

// Walter et al. 2007 eq. 34 (GGX): G1 = 2 / (1 + sqrt(1 + a^2 tan^2)), rewritten with
// tan^2 = (1-c^2)/c^2 as 2c / (c + sqrt(c^2 (1-a^2) + a^2)): no division by c.
float G1_SmithGGX(float alpha, float NoX) {
  float a2 = alpha * alpha;
  return 2.0f * NoX / (NoX + sqrt(NoX * NoX * (1.0f - a2) + a2));
}

// Karis 2013 eq. 4 (Schlick 1994 with k = alpha/2 to match Smith GGX at alpha = 1).
float G1_SchlickGGX(float k, float NoX) { return NoX / (NoX * (1.0f - k) + k); }

// Walter et al. 2007 eq. 27, rational approximation of Smith-Beckmann G1 with
// a = 1 / (alpha tan(theta)); G1 = 1 for a >= 1.6.
float G1_SmithBeckmann(float alpha, float NoX) {
  // a = c / (alpha sqrt(1 - c^2)); 1-c^2 >= 1e-8 so c = 1 gives a large finite a, not inf.
  float a = NoX * inversesqrt(max(1.0f - NoX * NoX, 1e-8f)) / alpha;
  // Branch-free "a < 1.6 ? rational : 1": the rational equals 1.0000 at a = 1.6, so clamping
  // a to 1.6 is continuous and gives the same result.
  a = min(a, 1.6f);
  // The fit overshoots 1 by up to 6e-5 just below a = 1.6; min() keeps G1 a probability.
  return min((3.535f * a + 2.181f * a * a) / (1.0f + 2.276f * a + 2.577f * a * a), 1.0f);
}

// ---- Visibility V = G / (4 NoL NoV) ----

// Heitz 2014, "Understanding the Masking-Shadowing Function in Microfacet-Based BRDFs", eq. 99
// (exact height-correlated Smith for GGX), in the division-free form of Filament
// (surface_brdf.fs): V = 0.5 / (NoL sqrt(NoV^2 (1-a^2) + a^2) + NoV sqrt(NoL^2 (1-a^2) + a^2)).
// Each V term below is split as the light pass evaluates it: a factor of the view alone
// (NAME_View, computed once per pixel, BrdfView) and the rest (NAME_ForView); NAME itself is the
// two composed, so every caller runs the same arithmetic.
float smithGgxRoot(float alpha, float NoX) {  // sqrt(NoX^2 (1-a^2) + a^2)
  float a2 = alpha * alpha;
  return sqrt(NoX * NoX * (1.0f - a2) + a2);
}
float V_SmithGGXCorrelated_View(float alpha, float NoV) { return smithGgxRoot(alpha, NoV); }
float V_SmithGGXCorrelated_ForView(float alpha, float view, float NoV, float NoL) {
  float GGXV = NoL * view;
  float GGXL = NoV * smithGgxRoot(alpha, NoL);
  return 0.5f / (GGXV + GGXL);
}
float V_SmithGGXCorrelated(float alpha, float NoV, float NoL) {
  return V_SmithGGXCorrelated_ForView(alpha, V_SmithGGXCorrelated_View(alpha, NoV), NoV, NoL);
}

// Hammon 2017, "PBR Diffuse Lighting for GGX+Smith Microsurfaces", slide 82; UE4
// Vis_SmithJointApprox: the sqrt of V_SmithGGXCorrelated replaced by its linear approximation,
// V = 0.5 / mix(2 NoL NoV, NoL + NoV, alpha). No sqrt.
float V_SmithGGXCorrelatedFast_View(float alpha, float NoV) { return NoV * (1.0f - alpha) + alpha; }
float V_SmithGGXCorrelatedFast_ForView(float alpha, float view, float NoV, float NoL) {
  float GGXV = NoL * view;
  float GGXL = NoV * (NoL * (1.0f - alpha) + alpha);
  return 0.5f / (GGXV + GGXL);
}
float V_SmithGGXCorrelatedFast(float alpha, float NoV, float NoL) {
  return V_SmithGGXCorrelatedFast_ForView(alpha, V_SmithGGXCorrelatedFast_View(alpha, NoV), NoV,
                                          NoL);
}

// Karis 2013 eq. 4: Schlick-GGX, G1(v) = NoV / (NoV (1-k) + k), k = alpha/2. The NoL NoV of G
// cancels against 4 NoL NoV, so V = 0.25 / ((NoV (1-k) + k)(NoL (1-k) + k)) (UE4 Vis_Schlick).
// The caller picks k: alpha/2 for image-based lighting, with alpha from the Disney remap
// ((roughness+1)/2)^2 for analytic lights (see visibility()).
float V_SchlickGGX_View(float k, float NoV) { return NoV * (1.0f - k) + k; }
float V_SchlickGGX_ForView(float k, float view, float NoL) {
  float GL = NoL * (1.0f - k) + k;
  return 0.25f / (view * GL);
}
float V_SchlickGGX(float k, float NoV, float NoL) {
  return V_SchlickGGX_ForView(k, V_SchlickGGX_View(k, NoV), NoL);
}

// Walter et al. 2007 eq. 34, separable (uncorrelated) Smith GGX, G = G1(v) G1(l). Each
// G1(c) / (2c) = 1 / (c + sqrt(c^2 (1-a^2) + a^2)), so V needs no division by NoV or NoL.
float V_SmithGGXSeparable_View(float alpha, float NoV) { return NoV + smithGgxRoot(alpha, NoV); }
float V_SmithGGXSeparable_ForView(float alpha, float view, float NoL) {
  float GL = NoL + smithGgxRoot(alpha, NoL);
  return 1.0f / (view * GL);
}
float V_SmithGGXSeparable(float alpha, float NoV, float NoL) {
  return V_SmithGGXSeparable_ForView(alpha, V_SmithGGXSeparable_View(alpha, NoV), NoL);
}

// Walter et al. 2007 eq. 27 (rational Smith-Beckmann G1), separable: G = G1(v) G1(l).
float V_SmithBeckmannSeparable_View(float alpha, float NoV) { return G1_SmithBeckmann(alpha, NoV); }
float V_SmithBeckmannSeparable_ForView(float alpha, float view, float NoV, float NoL) {
  float G = view * G1_SmithBeckmann(alpha, NoL);
  // G1(c) ~ 3.535 c / alpha as c -> 0, so G / (4 NoV NoL) has a finite limit; the 1e-8 floor
  // only avoids 0/0 when NoL = 0 (then G = 0 and V = 0, harmless since the light term has NoL).
  return G / max(4.0f * NoV * NoL, 1e-8f);
}
float V_SmithBeckmannSeparable(float alpha, float NoV, float NoL) {
  return V_SmithBeckmannSeparable_ForView(alpha, V_SmithBeckmannSeparable_View(alpha, NoV), NoV,
                                          NoL);
}

// Cook & Torrance 1982, "A Reflectance Model for Computer Graphics" (V-cavity G):
// G = min(1, 2 NoH NoV / VoH, 2 NoH NoL / VoH). Divided by 4 NoL NoV this is
// min(1 / (4 NoL NoV), NoH / (2 VoH max(NoV, NoL))), finite wherever the second term is the min.
float V_CookTorrance(float NoH, float NoV, float NoL, float VoH) {
  // 1e-12: 1/(4 NoL NoV) only needs to be large enough to lose the min() at NoL NoV -> 0.
  // VoH >= 1e-4: V and H are never perpendicular for a visible reflection; guards 0/0 only.
  return min(1.0f / max(4.0f * NoL * NoV, 1e-12f),
             NoH / (2.0f * max(VoH, 1e-4f) * max(NoV, NoL)));
}

// Karis 2013 "Specular G" (implicit: G = NoL NoV), so V = 1/4.
float V_Implicit() { return 0.25f; }

// ---- Fresnel ----

// Schlick 1994, "An Inexpensive BRDF Model for Physically-based Rendering", eq. 15, with a free
// f90 (Lagarde & de Rousiers 2014, "Moving Frostbite to PBR", section 4.2.1, listing 1).
vec3 F_Schlick(vec3 f0, float f90, float VoH) {
  return f0 + (vec3(f90) - f0) * pow5(1.0f - VoH);
}
float F_Schlick(float f0, float f90, float VoH) { return f0 + (f90 - f0) * pow5(1.0f - VoH); }

// Karis 2013 eq. 5: Schlick with the power replaced by a spherical-gaussian approximation,
// 2^((-5.55473 VoH - 6.98316) VoH) (constants fitted by Karis).
vec3 F_SchlickSG(vec3 f0, float f90, float VoH) {
  return f0 + (vec3(f90) - f0) * exp2((-5.55473f * VoH - 6.98316f) * VoH);
}

// Exact unpolarized Fresnel of a dielectric (Cook & Torrance 1982; Walter et al. 2007 eq. 22)
// with the index of refraction derived per channel from f0 = ((n-1)/(n+1))^2, i.e.
// n = (1 + sqrt(f0)) / (1 - sqrt(f0)). F(1) = f0 exactly; F(0) = 1.
vec3 F_ExactDielectric(vec3 f0, float VoH) {
  // f0 in [1e-6, 0.99]: f0 = 0 would give n = 1 and 0/0 at VoH = 0; f0 = 1 would give n = inf.
  // Metals (f0 > 0.99) are not dielectrics; this term is a comparison option, see docs/brdf.md.
  vec3 s = sqrt(clamp(f0, vec3(1e-6f), vec3(0.99f)));
  vec3 n = (vec3(1.0f) + s) / (vec3(1.0f) - s);
  float c = VoH;
  vec3 g = sqrt(n * n - vec3(1.0f - c * c));
  vec3 A = (g - vec3(c)) / (g + vec3(c));
  vec3 B = (vec3(c) * (g + vec3(c)) - vec3(1.0f)) / (vec3(c) * (g - vec3(c)) + vec3(1.0f));
  return 0.5f * A * A * (vec3(1.0f) + B * B);
}

// UE4 (BRDF.ush F_Schlick): f90 = saturate(50 f0.g). No real material has f0 < 0.02 (2%), so a
// smaller f0 is treated as pre-baked specular occlusion and also dims the grazing reflection.
vec3 F_SchlickF90Occlusion(vec3 f0, float VoH) {
  return F_Schlick(f0, saturate(50.0f * f0.y), VoH);
}

// ---- Diffuse ----

// Lambert: 1/pi (Karis 2013 eq. 1). The caller multiplies by the diffuse color.
float Fd_Lambert() { return INV_PI; }

// Burley 2012, "Physically-Based Shading at Disney", section 5.3: retro-reflection with
// fd90 = 0.5 + 2 roughness LoH^2, roughness = perceptual roughness as in Disney's model.
// Split as the V terms are: the view's factor is Schlick's weight pow5(1 - NoV), and
// F_Schlick(1, f90, NoV) = 1 + (f90 - 1) pow5(1 - NoV).
float Fd_Burley_View(float NoV) { return pow5(1.0f - NoV); }
float Fd_Burley_ForView(float roughness, float view, float NoL, float LoH) {
  float f90 = 0.5f + 2.0f * roughness * LoH * LoH;
  return F_Schlick(1.0f, f90, NoL) * (1.0f + (f90 - 1.0f) * view) * INV_PI;
}
float Fd_Burley(float roughness, float NoV, float NoL, float LoH) {
  return Fd_Burley_ForView(roughness, Fd_Burley_View(NoV), NoL, LoH);
}

// ---- Metallic workflow (Karis 2013 "Material Model") ----

// f0 = 0.04 for dielectrics (ior 1.5, UE4's Specular = 0.5 times 0.08), base color for metals.
vec3 computeF0(vec3 baseColor, float metallic) { return mix(vec3(0.04f), baseColor, metallic); }
// Metals have no diffuse lobe.
vec3 computeDiffuseColor(vec3 baseColor, float metallic) { return baseColor * (1.0f - metallic); }

// Disney roughness remap (Karis 2013 "Specular G", eq. 4): the alpha used by the Schlick-GGX
// visibility term for analytic lights, ((roughness + 1) / 2)^2, which reduces "hotness" at low
// roughness. Only Schlick-GGX is remapped (see visibility()).
float remappedVisibilityAlpha(float roughness) { return sq(0.5f * (roughness + 1.0f)); }

// The one statement of when that remap applies (Karis 2013 eq. 4 defines it for Schlick-GGX's k
// with analytic lights): the shaders' visibility(), the C++ BRDF (evalV) and the variant key's
// canonical settings all ask this function. v_term is an HV_V_* value.
bool remapAppliesTo(bool remap_roughness, int v_term) {
  return remap_roughness && v_term == HV_V_SCHLICK_GGX;
}

// ---- Surface ----

struct Surface {
  vec3 N;              // unit shading normal
  vec3 diffuse_color;  // baseColor * (1 - metallic)
  vec3 f0;             // specular reflectance at normal incidence
  float roughness;     // perceptual, clamped to >= HV_MIN_ROUGHNESS
  float alpha;         // roughness^2
  float cavity;        // small-scale occlusion of direct light, 1 = none (see lights.glsl)
};

// Karis 2013 "Material Model": builds a Surface from metallic-workflow parameters (BaseColor,
// Metallic, Roughness, Cavity); clamps roughness (HV_MIN_ROUGHNESS).
Surface makeSurface(vec3 N, vec3 baseColor, float metallic, float roughness, float cavity) {
  Surface s;
  s.N = N;
  s.diffuse_color = computeDiffuseColor(baseColor, metallic);
  s.f0 = computeF0(baseColor, metallic);
  s.roughness = clamp(roughness, HV_MIN_ROUGHNESS, 1.0f);
  s.alpha = s.roughness * s.roughness;
  s.cavity = cavity;
  return s;
}

// ---- Dispatchers: the only place the define table is read ----

// Karis 2013 eq. 2 by default; see the define table. sin2_NH = 1 - NoH^2 (|N x H|^2).
float distribution(float alpha, float NoH, float sin2_NH) {
#if HV_BRDF_D == HV_D_GGX
  return D_GGX(alpha, NoH, sin2_NH);
#elif HV_BRDF_D == HV_D_BECKMANN
  return D_Beckmann(alpha, NoH, sin2_NH);
#else
  return D_BlinnPhong(alpha, NoH, sin2_NH);
#endif
}

// The chosen V term's factor of the view alone (its NAME_View; 0 for Cook-Torrance and the
// implicit term, which have none), for a given visibility alpha.
float visibilityView(float alpha, float NoV) {
#if HV_BRDF_V == HV_V_SCHLICK_GGX
  return V_SchlickGGX_View(0.5f * alpha, NoV);  // Karis 2013 eq. 4: k = alpha/2
#elif HV_BRDF_V == HV_V_SMITH_GGX_CORRELATED
  return V_SmithGGXCorrelated_View(alpha, NoV);
#elif HV_BRDF_V == HV_V_SMITH_GGX_CORRELATED_FAST
  return V_SmithGGXCorrelatedFast_View(alpha, NoV);
#elif HV_BRDF_V == HV_V_SMITH_GGX_SEPARABLE
  return V_SmithGGXSeparable_View(alpha, NoV);
#elif HV_BRDF_V == HV_V_SMITH_BECKMANN_SEPARABLE
  return V_SmithBeckmannSeparable_View(alpha, NoV);
#else
  return 0.0f;
#endif
}
// The chosen V term from its view factor (visibilityView of the same alpha and NoV).
float visibilityForView(float view, float alpha, float NoV, float NoL, float NoH, float VoH) {
#if HV_BRDF_V == HV_V_SCHLICK_GGX
  return V_SchlickGGX_ForView(0.5f * alpha, view, NoL);
#elif HV_BRDF_V == HV_V_SMITH_GGX_CORRELATED
  return V_SmithGGXCorrelated_ForView(alpha, view, NoV, NoL);
#elif HV_BRDF_V == HV_V_SMITH_GGX_CORRELATED_FAST
  return V_SmithGGXCorrelatedFast_ForView(alpha, view, NoV, NoL);
#elif HV_BRDF_V == HV_V_SMITH_GGX_SEPARABLE
  return V_SmithGGXSeparable_ForView(alpha, view, NoL);
#elif HV_BRDF_V == HV_V_SMITH_BECKMANN_SEPARABLE
  return V_SmithBeckmannSeparable_ForView(alpha, view, NoV, NoL);
#elif HV_BRDF_V == HV_V_COOK_TORRANCE
  return V_CookTorrance(NoH, NoV, NoL, VoH);
#else
  return V_Implicit();
#endif
}

// The chosen V term for a given visibility alpha (no remap); image-based lighting calls this
// with alpha = roughness^2 (Karis 2013: the remap is for analytic lights only).
float visibilityForAlpha(float alpha, float NoV, float NoL, float NoH, float VoH) {
  return visibilityForView(visibilityView(alpha, NoV), alpha, NoV, NoL, NoH, VoH);
}

// Visibility for analytic lights. Karis 2013 eq. 4 ("Specular G") states the Disney remap
// alpha = ((roughness+1)/2)^2 for Schlick-GGX only: with HV_REMAP_ROUGHNESS and
// HV_BRDF_V == HV_V_SCHLICK_GGX, k = alpha_remapped / 2. Every other V term (Smith exact, its
// approximation, Beckmann, Cook-Torrance, implicit) uses alpha = roughness^2 unchanged.
float visibilityAlpha(float roughness, float alpha) {
  // Both arguments are compile-time constants: the compiler folds the choice.
  return remapAppliesTo(HV_REMAP_ROUGHNESS != 0, HV_BRDF_V) ? remappedVisibilityAlpha(roughness)
                                                            : alpha;
}
float visibility(float roughness, float alpha, float NoV, float NoL, float NoH, float VoH) {
  return visibilityForAlpha(visibilityAlpha(roughness, alpha), NoV, NoL, NoH, VoH);
}

// Karis 2013 eq. 5 area; f90 = 1 except for the UE4 occlusion variant.
vec3 fresnel(vec3 f0, float VoH) {
#if HV_BRDF_F == HV_F_SCHLICK
  return F_Schlick(f0, 1.0f, VoH);
#elif HV_BRDF_F == HV_F_SCHLICK_SG
  return F_SchlickSG(f0, 1.0f, VoH);
#elif HV_BRDF_F == HV_F_EXACT
  return F_ExactDielectric(f0, VoH);
#else
  return F_SchlickF90Occlusion(f0, VoH);
#endif
}

// Diffuse BRDF without the diffuse color: Lambert (Karis 2013 eq. 1) or Burley 2012.
float diffuseLobe(float roughness, float NoV, float NoL, float LoH) {
#if HV_BRDF_FD == HV_FD_BURLEY
  return Fd_Burley(roughness, NoV, NoL, LoH);
#else
  return Fd_Lambert();
#endif
}

// What a pixel's BRDF takes from the view alone, computed once per pixel before the light loop
// (ShadingPoint, lights.glsl; UE4's BxDFContext holds N.V for the same reason): the visibility
// term's view factor (visibilityView) and Burley's view factor. The ForView lobes below finish
// them per light with the arithmetic of the whole terms (specularLobe, diffuseLobe). The
// visibility alpha is not kept: two operations per light recompute it, and a value more per
// pixel held across the light loop spills on llvmpipe (docs/performance.md, "Per-pixel setup").
struct BrdfView {
  float vis;  // visibilityView(visibilityAlpha(roughness, alpha), NoV)
  float fd;   // Fd_Burley_View(NoV) with Burley, else 0 (unused)
};
BrdfView brdfView(Surface s, float NoV) {
  BrdfView v;
  v.vis = visibilityView(visibilityAlpha(s.roughness, s.alpha), NoV);
#if HV_BRDF_FD == HV_FD_BURLEY
  v.fd = Fd_Burley_View(NoV);
#else
  v.fd = 0.0f;
#endif
  return v;
}

float diffuseLobeForView(float roughness, BrdfView v, float NoL, float LoH) {
#if HV_BRDF_FD == HV_FD_BURLEY
  return Fd_Burley_ForView(roughness, v.fd, NoL, LoH);
#else
  return Fd_Lambert();
#endif
}

// Specular BRDF D V F (Karis 2013 eq. 3 with V = G / (4 NoL NoV)). normalization scales D: 1 for
// punctual lights, the energy normalization of Karis 2013 eqs. 14 and 20 for area lights.
// NoV must already be clamped (HV_MIN_NOV), NoL saturated; sin2_NH = |N x H|^2 (see D_GGX).
// v = brdfView(s, NoV).
vec3 specularLobeForView(Surface s, BrdfView v, float NoV, float NoL, float NoH, float sin2_NH,
                         float VoH, float normalization) {
  float D = distribution(s.alpha, NoH, sin2_NH) * normalization;
  float Vis =
      visibilityForView(v.vis, visibilityAlpha(s.roughness, s.alpha), NoV, NoL, NoH, VoH);
  return (D * Vis) * fresnel(s.f0, VoH);
}
vec3 specularLobe(Surface s, float NoV, float NoL, float NoH, float sin2_NH, float VoH,
                  float normalization) {
  return specularLobeForView(s, brdfView(s, NoV), NoV, NoL, NoH, sin2_NH, VoH, normalization);
}

// Full BRDF f(v, l) (not multiplied by NoL) for unit V and L: diffuse_color * Fd + D V F.
// Follows the conventions of the lights: NoV clamped to HV_MIN_NOV, NoL, NoH, VoH saturated.
vec3 evaluateBrdf(Surface s, vec3 V, vec3 L) {
  vec3 H = safeNormalize(V + L);  // V = -L gives H = 0, NoH = VoH = 0, not NaN
  float NoV = max(dot(s.N, V), HV_MIN_NOV);
  float NoL = saturate(dot(s.N, L));
  float NoH = saturate(dot(s.N, H));
  vec3 NxH = cross(s.N, H);
  float VoH = saturate(dot(V, H));
  return s.diffuse_color * diffuseLobe(s.roughness, NoV, NoL, VoH) +
         specularLobe(s, NoV, NoL, NoH, dot(NxH, NxH), VoH, 1.0f);
}

#endif
