// Internal to engine/reference: importance sampling of the environment by its luminance (a
// piecewise-constant density over the equirectangular parameterization, Pharr et al., "Physically
// Based Rendering" 3rd ed., section 14.2.4), the third strategy of the reference's environment
// estimator next to cosine and GGX-VNDF sampling. Without it, small bright sources (the sky's
// sun, the lamps and windows of an HDR) are found only by chance and the estimate converges
// slowly and from below.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "halfvec/ibl/ibl.hpp"

namespace hv::reference_detail {

class EnvDistribution {
 public:
  // Tabulates luminance(env.radiance) * sin(theta) over width x height equirectangular texels
  // (equirectUV / equirectDirection, world space: the environment's rotation is in
  // EnvSource::radiance), the largest of 4x4 sub-samples per texel so a source smaller than a
  // texel is still seen. Every texel keeps a small floor (1e-3 of the mean), so the density is
  // positive wherever sin(theta) > 0.
  EnvDistribution(const EnvSource& env, int width = 1024, int height = 512);

  // A unit direction with density pdf (solid angle) from two uniforms.
  glm::vec3 sample(glm::vec2 u, float& pdf) const;
  // The density (solid angle) with which sample() returns the unit direction dir.
  float pdf(const glm::vec3& dir) const;

 private:
  int width_, height_;
  std::vector<float> row_cdf_;  // height_ + 1 entries, normalized
  std::vector<float> col_cdf_;  // height_ rows of width_ + 1 entries, normalized per row
  std::vector<float> texel_p_;  // probability of each texel
};

}  // namespace hv::reference_detail
