// The orientation of an equirectangular environment, as docs/scene-format.md ("environment")
// states it: top row +Y, the image's center -Z, u = 0.75 +X, the edges +Z; rotation_deg turns
// the environment by the right-handed R_y(rotation_deg).
#include <gtest/gtest.h>

#include "halfvec/ibl/ibl.hpp"

namespace {

void expectDir(glm::vec3 got, glm::vec3 want, const char* what) {
  EXPECT_NEAR(got.x, want.x, 1e-5f) << what;
  EXPECT_NEAR(got.y, want.y, 1e-5f) << what;
  EXPECT_NEAR(got.z, want.z, 1e-5f) << what;
}

// An 8x4 equirectangular image, black but for one marked texel per quadrant of longitude on the
// equator rows: red at the center column (u = 0.5), green at u = 0.75, blue at u = 0.25.
hv::EnvSource markedEnvironment() {
  hv::EnvSource s;
  s.kind = hv::EnvironmentKind::HdrFile;
  s.equirect = hv::makeImageRGBf(8, 4);
  for (int y = 1; y <= 2; ++y) {  // the rows on either side of the equator
    for (int x = 3; x <= 4; ++x) s.equirect.at(x, y) = {1, 0, 0};  // around u = 0.5
    for (int x = 5; x <= 6; ++x) s.equirect.at(x, y) = {0, 1, 0};  // around u = 0.75
    for (int x = 1; x <= 2; ++x) s.equirect.at(x, y) = {0, 0, 1};  // around u = 0.25
  }
  return s;
}

}  // namespace

TEST(EnvOrientation, EquirectAxes) {
  expectDir(hv::equirectDirection({0.5f, 0.5f}), {0, 0, -1}, "center = -Z");
  expectDir(hv::equirectDirection({0.75f, 0.5f}), {1, 0, 0}, "u 0.75 = +X");
  expectDir(hv::equirectDirection({0.25f, 0.5f}), {-1, 0, 0}, "u 0.25 = -X");
  expectDir(hv::equirectDirection({0.0f, 0.5f}), {0, 0, 1}, "left edge = +Z");
  expectDir(hv::equirectDirection({0.3f, 0.0f}), {0, 1, 0}, "top row = +Y");
  expectDir(hv::equirectDirection({0.3f, 1.0f}), {0, -1, 0}, "bottom row = -Y");
  // equirectUV is its inverse.
  const glm::vec2 uv = hv::equirectUV({1, 0, 0});
  EXPECT_NEAR(uv.x, 0.75f, 1e-6f);
  EXPECT_NEAR(uv.y, 0.5f, 1e-6f);
}

TEST(EnvOrientation, RadianceAndRotation) {
  hv::EnvSource s = markedEnvironment();
  const glm::vec3 red(1, 0, 0), green(0, 1, 0), blue(0, 0, 1);
  EXPECT_EQ(s.radiance({0, 0, -1}), red);
  EXPECT_EQ(s.radiance({1, 0, 0}), green);
  EXPECT_EQ(s.radiance({-1, 0, 0}), blue);
  // R_y(90) takes -Z to -X: the image's center is seen towards -X, u = 0.75 towards -Z.
  s.rotation_deg = 90.0f;
  EXPECT_EQ(s.radiance({-1, 0, 0}), red);
  EXPECT_EQ(s.radiance({0, 0, -1}), green);
  s.rotation_deg = 270.0f;
  EXPECT_EQ(s.radiance({1, 0, 0}), red);
  EXPECT_EQ(s.radiance({0, 0, 1}), green);
}
