// Internal to engine/reference: random numbers, the distance falloff and the emitters of the
// area lights (what a sample of a sphere or tube light returns). The emitter radiance follows
// docs/lights.md; the falloff is lights.glsl's distanceFalloff with the +1 chosen at run time.
#pragma once

#include <cstdint>

#include <glm/glm.hpp>

#include "halfvec/scene/scene.hpp"

namespace hv::reference_detail {

// PCG32 (O'Neill 2014, pcg32_random_r), one stream per pixel: the image does not depend on the
// thread count. uniform() is in [0, 1) with 24 random bits.
class Rng {
 public:
  Rng(uint64_t seed, uint64_t stream);
  uint32_t next();
  float uniform() { return float(next() >> 8u) * 5.9604644775390625e-8f; }

 private:
  uint64_t state_ = 0, inc_ = 0;
};

// Karis 2013 eq. 9 as lights.glsl distanceFalloff: saturate(1 - (d/R)^4)^2 / (d^2 + 1), or
// / d^2 when !settings.falloff_plus_one; d^2 clamped to >= max(radius^2, 1e-4).
float falloff(const RenderSettings& settings, float d2, float radius, float range);

// One direction toward an area light: unit L, the radiance arriving along it (emitter radiance
// times the falloff scaling of docs/lights.md) and the solid-angle pdf of L; pdf = 0 means the
// sample missed the visible emitter (it contributes 0 but still counts as a sample). distance:
// from P along L to the emitter point the sample stands for (where a visibility ray stops).
struct LightSample {
  glm::vec3 L{0.0f, 0.0f, 1.0f};
  glm::vec3 radiance{0.0f};
  float pdf = 0.0f;
  float distance = 0.0f;
};

// Sphere: uniform in the cone the sphere subtends from P (pdf 1 / solid angle); inside the sphere,
// uniform over all directions. Tube (capsule): uniform over the capsule's area, converted to
// solid angle (pdf = dist^2 / (area cos_emitter)); back-facing points return pdf = 0.
LightSample sampleLight(const Light& light, const RenderSettings& settings, const glm::vec3& P,
                        glm::vec2 u);

// The radiance a sphere or tube light sends to P from any visible point of its surface
// (emitterRadiance of docs/lights.md: L_e times the window times the +1 factor); 0 for points.
glm::vec3 emitterRadianceAt(const Light& light, const RenderSettings& settings, const glm::vec3& P);

// The density (solid angle) with which sampleLight produces the unit direction L from P, i.e. the
// pdf to combine a direction drawn by another strategy (BRDF sampling) with the light's own by
// multiple importance sampling: 0 when the ray from P along L misses the emitter (or, for the
// capsule, first meets it on a back face, which sampleLight never returns as a hit). Sphere: the
// cone pdf when L is inside the subtended cone (every L inside the sphere). Capsule: first hit of
// the ray on the capsule (union of the cylinder and the two end spheres), dist^2 / (A cos_e).
float lightPdf(const Light& light, const glm::vec3& P, const glm::vec3& L);

// The light strategy's side of a direction L drawn by another strategy (multiple importance
// sampling): the radiance arriving along L and sampleLight's solid-angle pdf of L, or pdf = 0
// and no radiance when L misses the emitter (tube: the capsule's front hit along the ray).
LightSample evalLight(const Light& light, const RenderSettings& settings, const glm::vec3& P,
                      const glm::vec3& L);

// Squared distance from P to the light's window point (sphere: center; tube: closest point of
// the segment); beyond light.range the light contributes exactly 0.
float windowDistance2(const Light& light, const glm::vec3& P);

}  // namespace hv::reference_detail
