// The tone curves of shaders/common/tonemap.glsl (compiled as C++): Reinhard, Khronos PBR Neutral
// and the ACES fit map 0 to 0, never decrease along a ray of colors, stay finite (and in [0, 1]
// after the output clamp) at 1e6; plus the FXAA decisions and the emitter radiance shared with
// the GPU passes.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "halfvec/shading/shading.hpp"

using namespace hv;

namespace {

struct Curve {
  std::string name;
  std::function<glsl::vec3(glsl::vec3)> f;
};

std::vector<Curve> curves() {
  return {{"reinhard", [](glsl::vec3 c) { return glsl::reinhard(c); }},
          {"reinhard_luminance", [](glsl::vec3 c) { return glsl::reinhardLuminance(c); }},
          {"pbr_neutral", [](glsl::vec3 c) { return glsl::pbrNeutral(c); }},
          {"aces", [](glsl::vec3 c) { return glsl::acesFitted(c); }}};
}

bool finite(glsl::vec3 v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

}  // namespace

TEST(ToneMap, ZeroMapsToZero) {
  for (const Curve& c : curves()) {
    const glsl::vec3 y = c.f(glsl::vec3(0.0f));
    EXPECT_NEAR(y.x, 0.0f, 1e-7f) << c.name;
    EXPECT_NEAR(y.y, 0.0f, 1e-7f) << c.name;
    EXPECT_NEAR(y.z, 0.0f, 1e-7f) << c.name;
  }
}

// Along rays k * color (k from 1e-4 to 1e6, 400 log steps) every channel is non-decreasing,
// for grey and for saturated and mixed colors.
TEST(ToneMap, MonotonicAlongEveryRay) {
  const std::vector<glsl::vec3> colors = {{1, 1, 1},        {1, 0, 0},       {0, 1, 0},
                                          {0, 0, 1},        {1, 0.5f, 0.1f}, {0.2f, 0.9f, 0.6f},
                                          {0.05f, 0.05f, 1}};
  for (const Curve& c : curves()) {
    for (const glsl::vec3& col : colors) {
      glsl::vec3 prev = c.f(glsl::vec3(0.0f));
      for (int i = 0; i <= 400; ++i) {
        const float k = std::pow(10.0f, -4.0f + 10.0f * float(i) / 400.0f);
        const glsl::vec3 y = c.f(col * k);
        for (int ch = 0; ch < 3; ++ch) {
          ASSERT_GE(y[ch], prev[ch] - 1e-6f) << c.name << " color " << col.x << "," << col.y << ","
                                             << col.z << " k=" << k << " channel " << ch;
        }
        prev = y;
      }
    }
  }
}

TEST(ToneMap, FiniteAndInRangeAtAMillion) {
  for (const Curve& c : curves()) {
    for (const glsl::vec3 x :
         {glsl::vec3(1e6f), glsl::vec3(1e6f, 0.0f, 0.0f), glsl::vec3(1e6f, 1.0f, 1e-3f)}) {
      const glsl::vec3 y = c.f(x);
      EXPECT_TRUE(finite(y)) << c.name;
      const glsl::vec3 out = glsl::outputTransform(x);
      EXPECT_TRUE(finite(out)) << c.name;
      EXPECT_LE(glsl::saturate(y).x, 1.0f);
    }
  }
}

TEST(ToneMap, PbrNeutralKeepsBaseColorsAndCompressesHighlights) {
  // Below the compression start a color only loses the black offset (0.04 above 0.08).
  const glsl::vec3 c(0.5f, 0.3f, 0.2f);
  const glsl::vec3 y = glsl::pbrNeutral(c);
  EXPECT_NEAR(y.x, 0.46f, 1e-6f);
  EXPECT_NEAR(y.z, 0.16f, 1e-6f);
  // Far above it the peak tends to 1 and the color desaturates towards white.
  const glsl::vec3 hi = glsl::pbrNeutral(glsl::vec3(100.0f, 10.0f, 1.0f));
  EXPECT_NEAR(hi.x, 1.0f, 1e-3f);
  EXPECT_GT(hi.z / hi.x, 1.0f / 100.0f);
}

TEST(ToneMap, AcesFitPreExposedAsPublished) {
  // Narkowicz 2016: "1 on input maps to ~0.8 on output".
  EXPECT_NEAR(glsl::acesFitted(glsl::vec3(1.0f)).x, 0.8f, 0.01f);
  EXPECT_GT(glsl::acesFitted(glsl::vec3(7.3f)).x, 1.0f);  // reaches 1 at 7.24, clamped after
}

TEST(Fxaa, FlatNeighborhoodIsNoEdgeAndDitherNeverIs) {
  EXPECT_FALSE(glsl::fxaaIsEdge(0.5f, 0.5f));
  EXPECT_FALSE(glsl::fxaaIsEdge(0.0f, 2.0f / 255.0f));  // dither spans +-1 code
  EXPECT_TRUE(glsl::fxaaIsEdge(0.1f, 0.9f));
}

TEST(Fxaa, DirectionRunsAlongTheEdge) {
  // North bright, south dark: a horizontal edge; the direction must be horizontal.
  glsl::vec2 d = glsl::fxaaDirection(1.0f, 1.0f, 0.0f, 0.0f);
  EXPECT_GT(std::abs(d.x), 1.0f);
  EXPECT_NEAR(d.y, 0.0f, 1e-6f);
  // West bright, east dark: a vertical edge.
  d = glsl::fxaaDirection(1.0f, 0.0f, 1.0f, 0.0f);
  EXPECT_NEAR(d.x, 0.0f, 1e-6f);
  EXPECT_GT(std::abs(d.y), 1.0f);
  // Only the north-west corner bright: an edge along the north-east diagonal (x and y of the same
  // sign), perpendicular to the gradient towards the north-west.
  d = glsl::fxaaDirection(1.0f, 0.0f, 0.0f, 0.0f);
  EXPECT_GT(d.x * d.y, 0.0f);
}

TEST(Emitter, RadianceTimesAreaGivesThePowerOfTheLight) {
  // Power of a Lambertian emitter: L pi A. Must equal 4 pi I (docs/lights.md).
  const float I = 7.0f, r = 0.2f;
  for (float len : {0.0f, 0.5f, 3.0f}) {
    const float L = glsl::emitterRadiance(glsl::vec3(I), r, len).x;
    const float area = 4.0f * glsl::PI * r * r + 2.0f * glsl::PI * r * len;
    EXPECT_NEAR(L * glsl::PI * area, 4.0f * glsl::PI * I, 1e-3f) << len;
  }
  EXPECT_EQ(glsl::emitterRadiance(glsl::vec3(I), 0.0f, 1.0f).x, 0.0f);
}
