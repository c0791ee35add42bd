// The shadow lookups' taps (shaders/common/shadows.glsl), run as C++: the rotation walk the GPU
// loops use gives the points of the Vogel disk, the per-tap distance to the receiver's plane with
// the receiver's terms hoisted is the distance along the tap's normalized ray, and PCF's four
// bilinear taps spread as the disk they replace.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "halfvec/shading/shading.hpp"

namespace {

namespace g = hv::glsl;

// Tap i of n from the walk (sqrt((i + 0.5) / n) times the i-th golden-angle rotation of (1, 0))
// against vogelTap's closed form, for the counts the lookups use (PCSS's 8 search gathers and
// 16 filter taps) and 32: within single-precision rounding of the product after 32 steps.
TEST(ShadowTaps, RotationWalkGivesTheVogelDisk) {
  for (const int n : {8, 16, 32}) {
    glm::vec2 rot(1.0f, 0.0f);
    for (int i = 0; i < n; ++i) {
      const glm::vec2 walk = std::sqrt((float(i) + 0.5f) / float(n)) * rot;
      const glm::vec2 closed = g::vogelTap(i, n);
      EXPECT_NEAR(walk.x, closed.x, 2e-5f) << "n " << n << " tap " << i;
      EXPECT_NEAR(walk.y, closed.y, 2e-5f) << "n " << n << " tap " << i;
      EXPECT_NEAR(glm::length(rot), 1.0f, 1e-5f);
      rot = g::vogelNext(rot);
    }
  }
  // The step is the golden angle, pi (3 - sqrt(5)).
  const double golden = 3.14159265358979323846 * (3.0 - std::sqrt(5.0));
  EXPECT_NEAR(g::HV_VOGEL_STEP.x, std::cos(golden), 1e-7);
  EXPECT_NEAR(g::HV_VOGEL_STEP.y, std::sin(golden), 1e-7);
}

// shadowTapDistance (the plane's coefficients once per receiver, the tap's ray not normalized)
// against receiverPlaneDistance along the normalized ray of the same tap, for receivers around
// a light at the origin, lit and unlit normals, offsets up to the widest filter (0.35 rad):
// the same distance within 2e-5 relative, and `far` for the same rays.
TEST(ShadowTaps, HoistedTapDistanceIsTheReceiverPlaneDistance) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u11(-1.0f, 1.0f);
  const float far = 12.0f;
  int misses = 0, clamped = 0, checked = 0;
  for (int k = 0; k < 2000; ++k) {
    const glm::vec3 toP = glm::vec3(u11(rng), u11(rng), u11(rng)) * 6.0f;
    const glm::vec3 N = glm::normalize(glm::vec3(u11(rng), u11(rng), u11(rng)));
    const float d = glm::length(toP);
    if (d < 0.1f) continue;
    const glm::vec3 D = toP / d;
    glm::vec3 u, v;
    g::tangentFrame(D, u, v);
    const glm::vec4 plane(glm::dot(toP, N), glm::dot(D, N), glm::dot(u, N), glm::dot(v, N));
    const glm::vec2 o = glm::vec2(u11(rng), u11(rng)) * 0.35f;
    const float hoisted = g::shadowTapDistance(plane, o, 0.5f * d, far);
    const float direct =
        g::receiverPlaneDistance(toP, N, glm::normalize(D + u * o.x + v * o.y), far);
    EXPECT_NEAR(hoisted, direct, 2e-5f * direct) << "receiver " << k;
    misses += direct == far;
    clamped += direct == 0.5f * d;
    ++checked;
  }
  // Both branches of the comparison were exercised: rays that miss the plane, and plane hits
  // clamped to half the receiver's distance.
  EXPECT_GT(checked, 1900);
  EXPECT_GT(misses, 100);
  EXPECT_GT(clamped, 10);
}

// PCF's four taps: centered, and per axis the spread of the uniform disk of radius R they
// replace, R^2 / 4 (in units of R: 1 / 4), with no spread across the axes.
TEST(ShadowTaps, FourPcfTapsSpreadAsThePcfDisk) {
  glm::vec2 mean(0.0f), sq(0.0f);
  float xy = 0.0f;
  for (int i = 0; i < 4; ++i) {
    const glm::vec2 t = g::pcfTap(i);
    mean += 0.25f * t;
    sq += 0.25f * t * t;
    xy += 0.25f * t.x * t.y;
  }
  EXPECT_FLOAT_EQ(mean.x, 0.0f);
  EXPECT_FLOAT_EQ(mean.y, 0.0f);
  EXPECT_FLOAT_EQ(sq.x, 0.25f);
  EXPECT_FLOAT_EQ(sq.y, 0.25f);
  EXPECT_FLOAT_EQ(xy, 0.0f);
  // The disk's 16-tap Vogel pattern (the filter before) has the same mean squared radius, 1 / 2.
  float disk = 0.0f;
  for (int i = 0; i < 16; ++i) disk += glm::dot(g::vogelTap(i, 16), g::vogelTap(i, 16)) / 16.0f;
  EXPECT_NEAR(disk, sq.x + sq.y, 1e-5f);
}

}  // namespace
