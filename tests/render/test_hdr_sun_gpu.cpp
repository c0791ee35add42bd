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
#include "sun_glint.hpp"

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

// A glossy metal sphere seen from the sun's side (sun_glint.hpp), the HDR alone.
Scene glintScene(float roughness) {
  Scene s = test::glossySphereFacing(kToSun, roughness);
  s.environment.kind = EnvironmentKind::HdrFile;
  s.environment.path = sunHdr();
  s.environment.cube_size = 128;
  return s;
}

}  // namespace

// The HDR's sun as a light gives the glossy sphere's glint within 10% of the reference's summed
// over the 9x9 pixels around its peak, and the peak within 15%; with the sun in the prefiltered
// cube the glint is several times off (printed).
TEST(HdrSunGpu, GlintOfTheSunAsALightMatchesReference) {
  test::expectSunGlintAsLightMatchesReference(glintScene, kSize, "hdr sun");
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
