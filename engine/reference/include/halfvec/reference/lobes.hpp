// Internal to engine/reference: the engine's BRDF split into its diffuse and specular parts, with
// the clamps of glsl::evaluateBrdf. Inline (glsl::Surface has internal linkage).
#pragma once

#include <glm/glm.hpp>

#include "halfvec/shading/brdf.hpp"

namespace hv::reference_detail {

// Diffuse and specular parts of f(v, l) (not times NoL), with the clamps of glsl::evaluateBrdf.
// analytic: the V term of analytic lights (Disney remap when brdf.remap_roughness, as the light
// pass); otherwise V at alpha (as the environment BRDF of the ambient pass, Karis 2013).
struct Lobes {
  glm::vec3 diffuse{0.0f}, specular{0.0f};
};
inline Lobes brdfLobes(const BrdfConfig& c, const glsl::Surface& s, const glm::vec3& V,
                       const glm::vec3& L, bool analytic) {
  glm::vec3 H = glsl::safeNormalize(V + L);
  float NoV = glm::max(glm::dot(s.N, V), glsl::HV_MIN_NOV);
  float NoL = glsl::saturate(glm::dot(s.N, L));
  float NoH = glsl::saturate(glm::dot(s.N, H));
  float VoH = glsl::saturate(glm::dot(V, H));
  Lobes r;
  r.diffuse = s.diffuse_color * evalFd(c, s.roughness, NoV, NoL, VoH);
  const glm::vec3 NxH = glm::cross(s.N, H);  // 1 - NoH^2 without cancellation (see D_GGX)
  float D = evalD(c, s.alpha, NoH, glm::dot(NxH, NxH));
  float Vis = analytic ? evalV(c, s.roughness, s.alpha, NoV, NoL, NoH, VoH)
                       : evalVForAlpha(c, s.alpha, NoV, NoL, NoH, VoH);
  r.specular = (D * Vis) * evalF(c, s.f0, VoH);
  return r;
}

}  // namespace hv::reference_detail
