// Clear coat (KHR_materials_clearcoat; Filament's PBR document, section 4.9 "Clear coat model";
// Karis 2013 names it among UE4's shading models): a thin dielectric layer of weight c over the
// base material, with its own normal Nc and roughness. Shared by GLSL and C++ (the reference
// integrates the same BRDF): the light, ambient and forward passes shade a clear_coat pixel as
//   f = f_base (1 - c F_c) + c f_coat,
// f_coat the engine's specular lobe (brdf.glsl, the same D, V and F options) with F0 = 0.04 (an
// index of refraction of 1.5, the extension's) on Nc, and F_c = F_Schlick(0.04, 1, Nc.V) the
// light the coat reflects away from the base: the extension's fresnel_mix with the Fresnel term
// taken at the view, one factor for every light and the environment, as the Khronos glTF Sample
// Viewer evaluates it. The coat's lobe is a Surface of its own (makeCoatSurface): every light
// type and method (representative point, LTC from the same table) and the split-sum ambient
// serve it unchanged. The base is not darkened further for the coat's absorption (the extension
// has no coat color) nor its roughness changed (Filament's option): both are left out.
#ifndef HV_CLEAR_COAT_GLSL
#define HV_CLEAR_COAT_GLSL

#include "brdf.glsl"

// KHR_materials_clearcoat: the coat is a dielectric of IOR 1.5, ((1.5 - 1) / (1.5 + 1))^2 = 0.04.
const float HV_COAT_F0 = 0.04f;

// The coat's specular lobe as a Surface: no diffuse, F0 0.04, the coat's normal and roughness
// (clamped to HV_MIN_ROUGHNESS as the base's), the pixel's cavity (which shadows all direct
// light).
Surface makeCoatSurface(vec3 nc, float coat_roughness, float cavity) {
  Surface s = makeSurface(nc, vec3(0.0f), 0.0f, coat_roughness, cavity);
  s.f0 = vec3(HV_COAT_F0);
  return s;
}

// What the coat leaves of the base: 1 - c F_Schlick(0.04, 1, Nc.V) (glTF KHR_materials_clearcoat,
// "Layering": fresnel_mix; Filament section 4.9.2, the base times 1 - Fc).
float coatBaseScale(float clearcoat, vec3 nc, vec3 V) {
  return 1.0f - clearcoat * F_Schlick(HV_COAT_F0, 1.0f, saturate(dot(nc, V)));
}

#endif
