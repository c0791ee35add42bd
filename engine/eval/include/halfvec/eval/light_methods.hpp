// Cost of the light methods: the light pass of one scene rendered once per
// method (RenderSettings of the sphere / tube modes), frames interleaved so that load from other
// processes hits every method alike, median light-pass GPU ms and light-pixel evaluations per
// second. `halfvec bench --methods` prints it per light type. Needs a current GL context.
#pragma once

#include <string>
#include <vector>

#include "halfvec/scene/scene.hpp"

namespace hv::eval {

struct MethodTiming {
  std::string name;
  double light_ms = 0.0;      // median over the frames
  size_t evaluations = 0;     // light-pixel evaluations per frame (sum over lit pixels)
  double mevals_per_s = 0.0;  // evaluations / light_ms, in millions per second
};

// One method: a name and the scene settings it renders with; `fetch_only` renders the light pass's
// FetchOnly probe instead (render::LightPassProbe: the same lists and light fetches,
// no shading), whose time subtracted from a method's is that method's shading arithmetic.
struct TimedMethod {
  std::string name;
  RenderSettings settings;
  bool fetch_only = false;
};

// The methods compared for a light type, on top of `base`: the FetchOnly probe first, then the
// default representative point and the LTC modes (sphere: ltc specular; tube: ltc specular, then
// ltc specular and diffuse). Empty for point lights.
std::vector<TimedMethod> lightMethodsFor(LightType type, const RenderSettings& base);

// `frames` rounds of one frame per method (after one warm-up frame each).
std::vector<MethodTiming> timeLightMethods(const Scene& scene,
                                           const std::vector<TimedMethod>& methods, int width,
                                           int height, int frames);

}  // namespace hv::eval
