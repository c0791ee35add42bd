// The sun of an HDR environment: a small, very bright group of texels (a clear sky's sun in an
// equirectangular photograph covers a few texels at 1k and carries its glints), found in the
// image, taken out of it and drawn as a directional light of the same power, direction and solid
// angle, as the procedural sky's sun is with settings.sky_sun (docs/ibl.md, "An HDR's sun as a
// light"). The CPU reference keeps the sun in the environment and books the part of each sample
// that the engine draws as the light under the direct terms (hdrSunRemoved gives it the same
// environment without the sun).
#pragma once

#include <vector>

#include "halfvec/image/image.hpp"
#include "halfvec/scene/scene.hpp"

namespace hv {

// What findHdrSun accepts as a sun (docs/ibl.md says why these values):
// - the brightest texel's luminance at least kHdrSunPeakOverMean times the environment's mean
//   radiance (luminance, over the sphere);
// - the sun's texels: those connected to the brightest (8-neighbours, longitude wrapping) with at
//   least 1 / kHdrSunRegionFraction of its luminance;
// - their solid angle at most kHdrSunMaxSolidAngle (a disk of about 1.5 degrees radius): larger
//   bright areas (a studio's softboxes, a window) are area light sources, not a sun, and stay in
//   the environment.
constexpr float kHdrSunPeakOverMean = 1000.0f;
constexpr float kHdrSunRegionFraction = 100.0f;
constexpr float kHdrSunMaxSolidAngle = 2.2e-3f;

struct HdrSun {
  bool found = false;
  // Towards the sun in the image's own frame (equirectDirection; the environment's rotation not
  // applied): the centroid of the texels' excess radiance, weighted by luminance x solid angle.
  glm::vec3 direction{0.0f, 1.0f, 0.0f};
  // The light taken out: sum over the sun's texels of (radiance - fill) x solid angle, per
  // channel (at least 0): the illuminance the sun gives at normal incidence.
  glm::vec3 illuminance{0.0f};
  float solid_angle = 0.0f;  // of the sun's texels, sr
  glm::vec3 fill{0.0f};      // the radiance the sun's texels get instead: their border's mean
  std::vector<int> texels;   // y * width + x
};

// The image's sun, or found = false (no texel passes the rules above).
HdrSun findHdrSun(const ImageRGBf& equirect);
// The sun's texels set to its fill radiance (what the engine's environment holds where the sun
// is a light).
void removeHdrSun(ImageRGBf& equirect, const HdrSun& sun);

// The sun of the environment's HDR file (kind HdrFile), found once per file (path, size and
// modification time) and remembered; found = false for another kind or a file that does not load
// (loading it for the bake reports that error).
const HdrSun& hdrSunOf(const Environment& env);

// The HDR's sun as a directional light: travelling away from the sun's direction turned with the
// environment's rotation, angular diameter that of a disk of the sun's solid angle, illuminance
// at normal incidence the luminance of the sun's illuminance (times the environment's
// intensity), its colour the rest. No shadows (renderedLights sets them).
Light hdrSunLight(const Environment& env, const HdrSun& sun);

}  // namespace hv
