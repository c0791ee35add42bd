// Private to engine/reference (src/): the per-pixel estimator of renderReference, and what it
// shares over the image.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "halfvec/ibl/ibl.hpp"
#include "halfvec/reference/env_sampling.hpp"
#include "halfvec/reference/reference.hpp"
#include "halfvec/reference/visibility.hpp"
#include "halfvec/shading/brdf.hpp"

namespace hv::reference_detail {

// Everything constant over the image.
struct Context {
  const Scene* scene;
  const GBufferReadback* gb;
  const ReferenceOptions* opt;
  BrdfConfig brdf;
  glm::mat4 inv_view_proj;
  bool has_env = false;
  EnvSource env;
  // Luminance sampling of a non-uniform environment (null for uniform: cosine + VNDF suffice).
  std::unique_ptr<EnvDistribution> env_dist;
  // EnvironmentKind::Sky: the sun's cone (world direction, cos of its angular radius, 1/omega)
  // for a third, sun-sampling strategy; the other two almost never hit a 0.27 degree sun.
  bool has_sun = false;
  glm::vec3 sun_dir{0.0f, 1.0f, 0.0f};
  float sun_cos = 1.0f, sun_pdf = 0.0f;
  // The engine draws the sky's sun as a directional light (skySunIsLight): the sun's cone of the
  // environment integral is booked under the direct terms, as the engine's per-term images have
  // it (the sum is unchanged).
  bool sun_is_direct = false;
  // The engine draws an HDR's sun as a directional light (skySunIsLight, hdr_sun.hpp): the same
  // environment without the sun, whose radiance is booked under the ambient terms and the rest
  // (the sun's excess over its surroundings) under the direct terms (the sum is unchanged).
  bool hdr_sun_split = false;
  EnvSource env_without_sun;
  std::vector<const Light*> point_lights, area_lights;
  // Per entry of point_lights / area_lights: the spot's cone as the light pass reads it
  // (packLight's axis_length, spot.glsl), or (0, 0, 0, 1), whose attenuation is exactly 1.
  std::vector<glm::vec4> point_cones, area_cones;
  // The spots as their shapes (lightShape: a point or a sphere light), which the lists point to.
  std::vector<Light> spot_shapes;
  // ReferenceOptions::visibility: the scene's triangles (null without visibility).
  std::unique_ptr<SceneVisibility> vis;
};

struct PixelOut {
  glm::dvec3 aov[kReferenceAovCount];
  glm::dvec3 aov_se[kReferenceAovCount];
  glm::dvec3 se;
  double rel_error = 0.0;
  int samples = 0;
  double ao = 1.0, ao_se = 0.0;
  uint64_t rays = 0;
};

inline double luminance(const glm::dvec3& c) {
  return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z;
}

// The lit G-buffer pixel (x, y), index = y * width + x.
PixelOut shadePixel(const Context& ctx, size_t index, int x, int y);

}  // namespace hv::reference_detail
