// The shadow lookups' tap pattern (shaders/common/shadows.glsl), run as C++: the rotation walk
// the GPU loops use gives the points of the Vogel disk.
#include <gtest/gtest.h>

#include <cmath>

#include "halfvec/shading/shading.hpp"

namespace {

namespace g = hv::glsl;

// Tap i of n from the walk (sqrt((i + 0.5) / n) times the i-th golden-angle rotation of (1, 0))
// against vogelTap's closed form, for the counts the lookups use (16 per receiver, up to 32
// shared): within single-precision rounding of the product after 32 steps.
TEST(ShadowTaps, RotationWalkGivesTheVogelDisk) {
  for (const int n : {16, 32}) {
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

}  // namespace
