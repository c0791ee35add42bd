// An HDR's sun drawn as a directional light (settings.sky_sun: light; docs/ibl.md, "An HDR's sun
// as a light") against the CPU reference, which keeps the sun in the HDR: the sun's glint on glossy
// metal, and the reference's books (the sun under the direct terms, the total unchanged).
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>

#include <unistd.h>

#include "halfvec/ibl/hdr_sun.hpp"
#include "halfvec/ibl/sky_sun.hpp"
#include "halfvec/reference/reference.hpp"
#include "halfvec/shading/shading.hpp"
#include "hdr_file.hpp"
#include "render_fixture.hpp"

namespace fs = std::filesystem;
using namespace hv;

namespace {

constexpr int kSize = 96;
const glm::vec3 kToSun = glm::normalize(glm::vec3(0.5f, 0.6f, -0.6f));

// An HDR file of a sky with a 2 x 2-texel sun (0.6 degrees across at 512 wide), written once per
// run and removed at exit.
fs::path sunHdrPath() {
  return fs::temp_directory_path() / ("hv_hdr_sun_gpu_" + std::to_string(getpid()) + ".hdr");
}
const std::string& sunHdr() {
  static const std::string path = [] {
    test::writeHdrFile(sunHdrPath(), test::skyWithSun(512, kToSun, 20000.0f));
    std::atexit([] {
      std::error_code ec;
      fs::remove(sunHdrPath(), ec);
    });
    return sunHdrPath().string();
  }();
  return path;
}

// A glossy metal sphere seen from the sun's side, a little off its line (the glint near the
// image's middle); the HDR alone, no lights.
Scene glintScene(float roughness) {
  Scene s;
  s.camera.position = 4.0f * glm::normalize(kToSun + glm::vec3(0.0f, 0.15f, 0.0f));
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
  s.environment.kind = EnvironmentKind::HdrFile;
  s.environment.path = sunHdr();
  s.environment.cube_size = 128;
  s.settings.v = VisibilityTerm::SmithGGXCorrelated;  // the reference's exact V
  s.settings.remap_roughness = false;
  s.settings.sphere_specular = SphereSpecular::Ltc;  // the sun's disk on a glossy lobe
  return s;
}

float luminance(glm::vec3 c) {
  return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z;
}

// Over the glint (the reference's brightest pixel and those within `radius` of it): the
// engine's summed luminance over the reference's, the peak's ratio, and the mean |ratio - 1|.
struct Glint {
  double sum_ratio = 0.0, mean_error = 0.0, peak_ratio = 0.0;
};

Glint glintError(const ImageRGBf& engine, const ImageRGBf& ref, int radius) {
  size_t peak = 0;
  for (size_t i = 0; i < ref.px.size(); ++i) {
    if (luminance(ref.px[i]) > luminance(ref.px[peak])) peak = i;
  }
  const int px = int(peak) % kSize, py = int(peak) / kSize;
  Glint g;
  double se = 0.0, sr = 0.0;
  int n = 0;
  for (int y = std::max(py - radius, 0); y <= std::min(py + radius, kSize - 1); ++y) {
    for (int x = std::max(px - radius, 0); x <= std::min(px + radius, kSize - 1); ++x) {
      const size_t i = size_t(y) * kSize + size_t(x);
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

}  // namespace

// The HDR's sun as a light gives the glossy sphere's glint within 10% of the reference's summed
// over the 9x9 pixels around its peak, and the peak within 15%; with the sun in the prefiltered
// cube the glint is several times off (printed).
TEST(HdrSunGpu, GlintOfTheSunAsALightMatchesReference) {
  testContext();
  for (float roughness : {0.1f, 0.2f}) {
    Scene s = glintScene(roughness);
    s.settings.sky_sun = SkySun::Environment;
    const RenderedFrame env = renderFrame(s, kSize, kSize);
    s.settings.sky_sun = SkySun::Light;
    const RenderedFrame light = renderFrame(s, kSize, kSize);
    ASSERT_TRUE(light.key.directional_lights);
    ASSERT_FALSE(env.key.directional_lights);
    ReferenceOptions o;
    o.samples = 256;
    o.visibility = false;
    const ImageRGBf ref = renderReference(s, light.g, o).image;
    const Glint ge = glintError(env.hdr, ref, 4);
    const Glint gl = glintError(light.hdr, ref, 4);
    std::cout << "[ hdr sun ] roughness " << roughness << ", glint 9x9 px: engine/reference "
              << "summed " << ge.sum_ratio << " environment, " << gl.sum_ratio << " light; peak "
              << ge.peak_ratio << " / " << gl.peak_ratio << "; mean |ratio - 1| " << ge.mean_error
              << " / " << gl.mean_error << "\n";
    EXPECT_NEAR(gl.sum_ratio, 1.0, 0.1) << roughness;
    EXPECT_NEAR(gl.peak_ratio, 1.0, 0.15) << roughness;
    EXPECT_LT(gl.mean_error, 0.5 * ge.mean_error) << roughness;
  }
}

// The reference keeps the sun in the HDR whatever sky_sun says: with the sun as a light it books
// the sun's part of each environment sample under the direct terms, as the engine's per-term
// images have it, and the total is the same image (the same samples, summed in two parts).
TEST(HdrSunGpu, ReferenceBooksTheSunUnderDirectTermsWithTheSameTotal) {
  testContext();
  Scene s = glintScene(0.3f);
  s.settings.sky_sun = SkySun::Light;
  const RenderedFrame f = renderFrame(s, 48, 48);
  ReferenceOptions o;
  o.samples = 16;
  o.visibility = false;
  const ReferenceResult split = renderReference(s, f.g, o);
  s.settings.sky_sun = SkySun::Environment;
  const ReferenceResult whole = renderReference(s, f.g, o);
  const auto DD = size_t(ReferenceAov::DirectDiffuse), DS = size_t(ReferenceAov::DirectSpecular);
  double direct_split = 0.0, direct_whole = 0.0, total = 0.0, diff = 0.0;
  for (size_t i = 0; i < split.image.px.size(); ++i) {
    direct_split += luminance(split.aov[DD].px[i] + split.aov[DS].px[i]);
    direct_whole += luminance(whole.aov[DD].px[i] + whole.aov[DS].px[i]);
    total += luminance(whole.image.px[i]);
    diff += std::abs(luminance(split.image.px[i]) - luminance(whole.image.px[i]));
  }
  EXPECT_EQ(direct_whole, 0.0);
  EXPECT_GT(direct_split, 0.01 * total) << "the sun lights the sphere";
  EXPECT_LT(diff, 1e-5 * total);
}
