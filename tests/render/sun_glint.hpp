// The glint of an environment's sun on a glossy metal sphere, engine against the CPU reference,
// with the sun in the prefiltered cube (settings.sky_sun: environment) and drawn as a light
// (light): shared by the procedural sky's test (test_sky_sun_gpu.cpp) and the HDR's
// (test_hdr_sun_gpu.cpp).
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <iostream>
#include <string>

#include "halfvec/ibl/ibl.hpp"
#include "halfvec/reference/reference.hpp"
#include "halfvec/shading/shading.hpp"
#include "render_fixture.hpp"

namespace hv::test {

// A glossy metal sphere of radius 1 at the origin seen from 4 m on the sun's side, a little off
// its line (the glint near the image's middle, the camera not along the glint's axis), the
// reference's exact V and no roughness remap, `ltc` for the sun's disk on the glossy lobe; the
// environment is the caller's.
inline Scene glossySphereFacing(glm::vec3 to_sun, float roughness) {
  Scene s;
  s.camera.position = 4.0f * glm::normalize(to_sun + glm::vec3(0.0f, 0.15f, 0.0f));
  s.camera.target = {0.0f, 0.0f, 0.0f};
  s.camera.fov_y_deg = 20.0f;
  Material m;
  m.base_color = glm::vec3(0.95f, 0.9f, 0.8f);
  m.metallic = 1.0f;
  m.roughness = roughness;
  s.materials.push_back(m);
  s.meshes.push_back(makeSphere(1.0f, 128, 64));
  s.meshes.back().material = 0;
  Object o;
  o.meshes = {0};
  s.objects.push_back(o);
  s.settings.v = VisibilityTerm::SmithGGXCorrelated;  // the reference's exact V
  s.settings.remap_roughness = false;
  s.settings.sphere_specular = SphereSpecular::Ltc;
  return s;
}

// Over the glint (the reference's brightest pixel and the pixels within `radius` of it): the
// engine's summed luminance over the reference's, the peak's ratio, and the mean
// |engine / reference - 1|.
struct Glint {
  double sum_ratio = 0.0, mean_error = 0.0, peak_ratio = 0.0;
};

inline Glint glintError(const ImageRGBf& engine, const ImageRGBf& ref, int radius) {
  const int w = ref.width, h = ref.height;
  size_t peak = 0;
  for (size_t i = 0; i < ref.px.size(); ++i) {
    if (luminance(ref.px[i]) > luminance(ref.px[peak])) peak = i;
  }
  const int px = int(peak) % w, py = int(peak) / w;
  Glint g;
  double se = 0.0, sr = 0.0;
  int n = 0;
  for (int y = std::max(py - radius, 0); y <= std::min(py + radius, h - 1); ++y) {
    for (int x = std::max(px - radius, 0); x <= std::min(px + radius, w - 1); ++x) {
      const size_t i = size_t(y) * size_t(w) + size_t(x);
      const double e = luminance(engine.px[i]), r = luminance(ref.px[i]);
      se += e;
      sr += r;
      g.mean_error += std::abs(e / std::max(r, 1e-6) - 1.0);
      ++n;
    }
  }
  g.sum_ratio = se / sr;
  g.mean_error /= n;
  g.peak_ratio = luminance(engine.px[peak]) / luminance(ref.px[peak]);
  return g;
}

// At roughness 0.1 and 0.2, size x size pixels, 256 reference samples without visibility: the sun
// as a light gives the glint within 10% of the reference's summed over the 9x9 pixels around its
// peak, the peak within 15%, and half the mean error of the sun in the cube (printed, `tag`).
inline void expectSunGlintAsLightMatchesReference(const std::function<Scene(float)>& scene,
                                                  int size, const std::string& tag) {
  testContext();
  for (float roughness : {0.1f, 0.2f}) {
    Scene s = scene(roughness);
    s.settings.sky_sun = SkySun::Environment;
    const RenderedFrame env = renderFrame(s, size, size);
    s.settings.sky_sun = SkySun::Light;
    const RenderedFrame light = renderFrame(s, size, size);
    ASSERT_TRUE(light.key.directional_lights);
    ASSERT_FALSE(env.key.directional_lights);
    ReferenceOptions o;
    o.samples = 256;
    o.visibility = false;
    const ImageRGBf ref = renderReference(s, light.g, o).image;
    const Glint ge = glintError(env.hdr, ref, 4);
    const Glint gl = glintError(light.hdr, ref, 4);
    std::cout << "[ " << tag << " ] roughness " << roughness << ", glint 9x9 px: engine/reference "
              << "summed " << ge.sum_ratio << " environment, " << gl.sum_ratio << " light; peak "
              << ge.peak_ratio << " / " << gl.peak_ratio << "; mean |ratio - 1| " << ge.mean_error
              << " / " << gl.mean_error << "\n";
    EXPECT_NEAR(gl.sum_ratio, 1.0, 0.1) << roughness;
    EXPECT_NEAR(gl.peak_ratio, 1.0, 0.15) << roughness;
    EXPECT_LT(gl.mean_error, 0.5 * ge.mean_error) << roughness;
  }
}

}  // namespace hv::test
