// The lights the engine shades: the scene's, plus the environment's sun (the procedural sky's, or
// an HDR's: hdr_sun.hpp) where settings.sky_sun draws it as a directional light (docs/ibl.md,
// "The sky's sun as a light", "An HDR's sun as a light").
// Everything in the renderer that uploads, counts or indexes lights for the GPU goes through
// renderedLights, so the sun is the last light of the GPU list. The CPU reference keeps the sun in
// the sky (the truth does not depend on the method) and books it under the direct terms where
// skySunIsLight, as the engine's per-term images do.
#pragma once

#include <vector>

#include "halfvec/scene/scene.hpp"

namespace hv {

// The environment has a sun to draw as a light: the procedural sky, or an HDR file in which
// findHdrSun finds one.
bool environmentHasSun(const Environment& env);

// settings.sky_sun is `light` or `shadowed_light`, the environment has a sun
// (environmentHasSun) and the scene has fewer than kMaxDirectionalLights directional lights
// (else the sun stays in the environment).
bool skySunIsLight(const Scene& scene);

// scene.lights, then the sun (skySunLight or hdrSunLight) where skySunIsLight, casting shadows (an
// orthographic map, docs/lights.md) with `shadowed_light`.
std::vector<Light> renderedLights(const Scene& scene);

}  // namespace hv
