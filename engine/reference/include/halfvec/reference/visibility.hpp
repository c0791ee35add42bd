// Internal to engine/reference: visibility between a shading point and a light sample or an
// environment direction, traced against the scene's triangles with Embree 3 (docs/reference.md,
// "Visibility"). The header does not include Embree: it is a private dependency of the module.
#pragma once

#include <cstddef>
#include <limits>
#include <memory>

#include <glm/glm.hpp>

#include "halfvec/scene/scene.hpp"

namespace hv::reference_detail {

// The triangles the G-buffer pass draws (every mesh of every object, in world space through the
// object's transform; scene primitives are already triangle meshes in Scene::meshes), as one
// Embree scene. Both faces of every triangle occlude (a shadow ray meets the back of a
// single-sided surface as surely as its front). Alpha-masked materials (AlphaMode::Mask) let a
// ray through where base_alpha x the base-color texture's alpha at the hit's UV is below
// alpha_cutoff, as the G-buffer pass discards there; blended materials occlude as opaque ones,
// as the engine draws them opaque. Emitters are not triangles: they never occlude.
class SceneVisibility {
 public:
  // Throws std::runtime_error when Embree fails (the message names the call).
  explicit SceneVisibility(const Scene& scene);
  ~SceneVisibility();
  SceneVisibility(const SceneVisibility&) = delete;
  SceneVisibility& operator=(const SceneVisibility&) = delete;

  // True when the open segment origin + t dir, 0 < t < tfar, meets a triangle (dir unit length;
  // tfar may be infinite). Thread-safe.
  bool occluded(const glm::vec3& origin, const glm::vec3& dir,
                float tfar = std::numeric_limits<float>::infinity()) const;

  size_t triangles() const;        // triangles in the Embree scene
  size_t maskedTriangles() const;  // of which alpha-tested by the filter function

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Origin of the visibility rays that leave the point P reconstructed from the G-buffer, offset
// along its normal N (unit; the side the shading happens on) by kRayOffset times the larger of
// |P| and |P - eye| (eye: the camera). Why: P is rebuilt from a 32-bit depth through the inverse
// view-projection, so its error is a few ulps of the magnitudes in that product (the position
// itself and its distance from the camera), and a ray leaving from below the true surface hits
// the surface's own triangle. An offset relative to those magnitudes stays above that error
// anywhere in the scene and is far smaller than any contact gap that matters (docs/reference.md).
constexpr float kRayOffset = 1e-4f;
glm::vec3 rayOrigin(const glm::vec3& P, const glm::vec3& N, const glm::vec3& eye);

}  // namespace hv::reference_detail
