// Run-time choice of BRDF terms for C++ (tests, the CPU reference renderer). The GLSL picks terms
// at compile time through the define table of shaders/common/brdf.glsl; here BrdfConfig picks at
// run time and every eval* switches over the very same hv::glsl term functions (no term math is
// written twice). The settings table (halfvec/scene/render_settings.hpp) maps RenderSettings to
// shader defines; brdfDefines() gives the light pass's.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "halfvec/scene/scene.hpp"
#include "halfvec/shading/shading.hpp"

namespace hv {

struct BrdfConfig {
  DistributionTerm d = DistributionTerm::GGX;
  VisibilityTerm v = VisibilityTerm::SchlickGGX;
  FresnelTerm f = FresnelTerm::SchlickPow5;
  DiffuseTerm diffuse = DiffuseTerm::Lambert;
  bool remap_roughness = true;  // Disney remap of the V alpha (analytic lights, Karis 2013)

  static BrdfConfig fromSettings(const RenderSettings& s);
};

// D(h): hv::glsl::D_GGX / D_Beckmann / D_BlinnPhong. sin2_NH = 1 - NoH^2, best |N x H|^2 (exact
// near the mirror direction, see D_GGX); without it, (1 - NoH)(1 + NoH).
float evalD(const BrdfConfig& c, float alpha, float NoH, float sin2_NH);
float evalD(const BrdfConfig& c, float alpha, float NoH);
// V for a given alpha, no remap (= glsl visibilityForAlpha); used by image-based lighting.
float evalVForAlpha(const BrdfConfig& c, float alpha, float NoV, float NoL, float NoH, float VoH);
// V for analytic lights (= glsl visibility): alpha remapped when c.remap_roughness and c.v is
// SchlickGGX (Karis 2013 eq. 4 states the Disney remap for Schlick-GGX only).
float evalV(const BrdfConfig& c, float roughness, float alpha, float NoV, float NoL, float NoH,
            float VoH);
// F (= glsl fresnel).
glm::vec3 evalF(const BrdfConfig& c, const glm::vec3& f0, float VoH);
// Diffuse lobe without the diffuse color (= glsl diffuseLobe).
float evalFd(const BrdfConfig& c, float roughness, float NoV, float NoL, float LoH);
// The two below take glsl::Surface, a type of the headers' anonymous namespace (internal
// linkage), so they are defined here, inline, and not in brdf.cpp.

// D V F with D scaled by normalization (= glsl specularLobe); sin2_NH = 1 - NoH^2 from NoH.
inline glm::vec3 evalSpecular(const BrdfConfig& c, const glsl::Surface& s, float NoV, float NoL,
                              float NoH, float VoH, float normalization = 1.0f) {
  float D = evalD(c, s.alpha, NoH) * normalization;
  float Vis = evalV(c, s.roughness, s.alpha, NoV, NoL, NoH, VoH);
  return (D * Vis) * evalF(c, s.f0, VoH);
}

// Full BRDF f(v, l), not multiplied by NoL (= glsl evaluateBrdf), with the same clamps.
inline glm::vec3 evalBrdf(const BrdfConfig& c, const glsl::Surface& s, const glm::vec3& V,
                          const glm::vec3& L) {
  glm::vec3 H = glsl::safeNormalize(V + L);
  float NoV = glm::max(glm::dot(s.N, V), glsl::HV_MIN_NOV);
  float NoL = glsl::saturate(glm::dot(s.N, L));
  float NoH = glsl::saturate(glm::dot(s.N, H));
  float VoH = glsl::saturate(glm::dot(V, H));
  const glm::vec3 NxH = glm::cross(s.N, H);
  float D = evalD(c, s.alpha, NoH, glm::dot(NxH, NxH));
  float Vis = evalV(c, s.roughness, s.alpha, NoV, NoL, NoH, VoH);
  return s.diffuse_color * evalFd(c, s.roughness, NoV, NoL, VoH) + (D * Vis) * evalF(c, s.f0, VoH);
}

// Shader defines for the BRDF and light options of settings, e.g. {"HV_BRDF_D", "0"}; see
// docs/brdf.md and docs/lights.md. Light-type presence defines come from lightTypeDefines()
// (light_gpu.hpp) since they depend on the scene, not the settings.
std::vector<std::pair<std::string, std::string>> brdfDefines(const RenderSettings& s);

}  // namespace hv
