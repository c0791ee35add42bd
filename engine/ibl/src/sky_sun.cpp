#include "halfvec/ibl/sky_sun.hpp"

#include "halfvec/ibl/hdr_sun.hpp"
#include "halfvec/ibl/ibl.hpp"

namespace hv {

bool environmentHasSun(const Environment& env) {
  return env.kind == EnvironmentKind::Sky ||
         (env.kind == EnvironmentKind::HdrFile && hdrSunOf(env).found);
}

bool skySunIsLight(const Scene& scene) {
  if (scene.settings.sky_sun == SkySun::Environment || !environmentHasSun(scene.environment)) {
    return false;
  }
  // The frame's list of directional lights has kMaxDirectionalLights places: where the scene
  // fills them, the sun stays in the environment.
  size_t directional = 0;
  for (const Light& l : scene.lights) directional += l.type == LightType::Directional;
  return directional < kMaxDirectionalLights;
}

std::vector<Light> renderedLights(const Scene& scene) {
  std::vector<Light> lights = scene.lights;
  if (skySunIsLight(scene)) {
    const Environment& env = scene.environment;
    lights.push_back(env.kind == EnvironmentKind::Sky ? skySunLight(env)
                                                      : hdrSunLight(env, hdrSunOf(env)));
    lights.back().shadows = scene.settings.sky_sun == SkySun::ShadowedLight;
  }
  return lights;
}

}  // namespace hv
