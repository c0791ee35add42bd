// An HDR's sun (halfvec/ibl/hdr_sun.hpp): found where an equirect has one, nowhere else, taken
// out of the image without losing or adding light, and drawn as the last rendered light.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include <unistd.h>

#include "halfvec/ibl/hdr_sun.hpp"
#include "halfvec/ibl/ibl.hpp"
#include "halfvec/ibl/sky_sun.hpp"
#include "hdr_file.hpp"
#include "shared_assets.hpp"

namespace fs = std::filesystem;
using namespace hv;

namespace {

constexpr float kPi = 3.14159265f;

// Sum over the texels of radiance x solid angle (the image's power per channel).
glm::dvec3 power(const ImageRGBf& img) {
  glm::dvec3 p(0.0);
  for (int y = 0; y < img.height; ++y) {
    const double dw =
        (2.0 * kPi / img.width) * (kPi / img.height) * std::sin(kPi * (y + 0.5) / img.height);
    for (int x = 0; x < img.width; ++x) p += glm::dvec3(img.at(x, y)) * dw;
  }
  return p;
}

const glm::vec3 kToSun = glm::normalize(glm::vec3(0.5f, 0.6f, -0.6f));

}  // namespace

// A 2 x 2-texel sun of 20,000 over a sky of about 0.5: found, its direction the block's centre
// (within a texel: 0.7 degrees at 512 wide), its solid angle the four texels', and the image
// without it plus the light's illuminance is the image with it, per channel.
TEST(HdrSun, FindsASmallBrightSunAndKeepsTheLight) {
  ImageRGBf img = test::skyWithSun(512, kToSun, 20000.0f);
  const HdrSun sun = findHdrSun(img);
  ASSERT_TRUE(sun.found);
  EXPECT_EQ(sun.texels.size(), 4u);
  const float texel = 2.0f * kPi / 512.0f;
  EXPECT_LT(std::acos(std::min(glm::dot(sun.direction, kToSun), 1.0f)), texel);
  EXPECT_NEAR(sun.solid_angle,
              4.0f * texel * (kPi / 256.0f) * std::sqrt(1.0f - kToSun.y * kToSun.y),
              0.02f * sun.solid_angle);
  EXPECT_NEAR(sun.fill.x, 0.4f, 1e-3f);  // the sky around it
  const glm::dvec3 before = power(img);
  removeHdrSun(img, sun);
  const glm::dvec3 after = power(img);
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(after[c] + sun.illuminance[c], before[c], 1e-4 * before[c]) << c;
  }
  EXPECT_FALSE(findHdrSun(img).found) << "a sun found twice";
  // The light: travelling away from the sun, its illuminance's luminance and colour, the disk of
  // the same solid angle.
  Environment env;
  env.kind = EnvironmentKind::HdrFile;
  env.intensity = 2.0f;
  const Light l = hdrSunLight(env, sun);
  EXPECT_EQ(l.type, LightType::Directional);
  EXPECT_GT(glm::dot(l.direction, -kToSun), 0.9999f);
  const float e =
      0.2126f * sun.illuminance.x + 0.7152f * sun.illuminance.y + 0.0722f * sun.illuminance.z;
  EXPECT_NEAR(l.intensity, 2.0f * e, 1e-3f * e);
  EXPECT_NEAR(2.0f * kPi * (1.0f - std::cos(0.5f * l.angular_diameter)), sun.solid_angle,
              1e-3f * sun.solid_angle);
  // Turned with the environment: 90 degrees about +Y.
  env.rotation_deg = 90.0f;
  const glm::vec3 turned(kToSun.z, kToSun.y, -kToSun.x);
  EXPECT_GT(glm::dot(hdrSunLight(env, sun).direction, -turned), 0.9999f);
}

// No sun: a uniform sky; a bright area too large for a sun (an 8 x 6-texel window, 7e-3 sr, 1,500
// times the mean); a sun not far enough above the mean (about 140x).
TEST(HdrSun, NoSunInAnImageWithoutOne) {
  EXPECT_FALSE(findHdrSun(makeImageRGBf(256, 128, glm::vec3(0.7f))).found);
  ImageRGBf window = makeImageRGBf(512, 256, glm::vec3(0.5f));
  for (int y = 100; y < 106; ++y)
    for (int x = 200; x < 208; ++x) window.at(x, y) = glm::vec3(5000.0f);
  EXPECT_FALSE(findHdrSun(window).found);
  EXPECT_FALSE(findHdrSun(test::skyWithSun(512, kToSun, 50.0f)).found);
}

// The shared HDRs: venice_sunset's sun is found (a few texels low over the horizon); the studio's
// softboxes and the warehouse's windows are area sources, not a sun.
TEST(HdrSun, SharedHdrs) {
  const fs::path dir = test::assetsDir();
  if (dir.empty()) GTEST_SKIP() << "HV_ASSETS_DIR not set (configure with -DHV_ASSETS_DIR=...)";
  for (const char* name :
       {"venice_sunset_1k.hdr", "studio_small_03_1k.hdr", "empty_warehouse_01_1k.hdr"}) {
    const fs::path p = dir / "env" / name;
    if (!fs::exists(p)) GTEST_SKIP() << "missing asset " << p;
    const HdrSun sun = findHdrSun(loadHdr(p.string()));
    std::cout << "[ hdr sun ] " << name << ": found " << sun.found << ", " << sun.texels.size()
              << " texels, " << sun.solid_angle << " sr, illuminance " << sun.illuminance.x << " "
              << sun.illuminance.y << " " << sun.illuminance.z << ", elevation "
              << glm::degrees(std::asin(sun.direction.y)) << " deg\n";
    const bool venice = std::string(name).rfind("venice", 0) == 0;
    EXPECT_EQ(sun.found, venice) << name;
    if (venice) {
      EXPECT_LT(sun.solid_angle, 1e-3f);
      EXPECT_GT(sun.direction.y, 0.0f) << "above the horizon";
      EXPECT_LT(sun.direction.y, std::sin(glm::radians(20.0f))) << "a sunset's sun is low";
    }
  }
}

// With sky_sun light an HDR file with a sun adds it as the last rendered light (shadowed with
// shadowed_light); sky_sun environment, or a file without a sun, leaves the lights as they are.
TEST(HdrSun, IsTheLastRenderedLight) {
  const fs::path file = fs::temp_directory_path() / ("hv_hdr_sun_" + std::to_string(getpid()));
  const fs::path with = file.string() + "_sun.hdr", without = file.string() + "_plain.hdr";
  test::writeHdrFile(with, test::skyWithSun(512, kToSun, 20000.0f));
  test::writeHdrFile(without, makeImageRGBf(512, 256, glm::vec3(0.5f)));
  Scene s;
  s.environment.kind = EnvironmentKind::HdrFile;
  s.environment.path = with.string();
  Light point;
  s.lights = {point};
  s.settings.sky_sun = SkySun::Light;
  EXPECT_TRUE(environmentHasSun(s.environment));
  ASSERT_TRUE(skySunIsLight(s));
  ASSERT_EQ(renderedLights(s).size(), 2u);
  EXPECT_EQ(renderedLights(s).back().type, LightType::Directional);
  EXPECT_FALSE(renderedLights(s).back().shadows);
  s.settings.sky_sun = SkySun::ShadowedLight;
  EXPECT_TRUE(renderedLights(s).back().shadows);
  s.settings.sky_sun = SkySun::Environment;
  EXPECT_EQ(renderedLights(s).size(), 1u);
  s.settings.sky_sun = SkySun::Light;
  s.environment.path = without.string();
  EXPECT_FALSE(environmentHasSun(s.environment));
  EXPECT_EQ(renderedLights(s).size(), 1u);
  s.environment.path = "/nonexistent/sky.hdr";
  EXPECT_FALSE(environmentHasSun(s.environment)) << "the bake reports the missing file";
  // The environment source the engine bakes goes without the sun; the reference's keeps it.
  s.environment.path = with.string();
  SkyParams no_disk;
  no_disk.sun_disk = false;
  const EnvSource full = makeEnvSource(s.environment), bare = makeEnvSource(s.environment, no_disk);
  EXPECT_GT(full.radiance(kToSun).y, 1000.0f);
  EXPECT_LT(bare.radiance(kToSun).y, 1.0f);
  fs::remove(with);
  fs::remove(without);
}
