// The bench's measurement layer (halfvec/eval/bench.hpp): the median interval's order statistics
// and the frame-cost table's structure on a tiny scene.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>

#include "halfvec/eval/bench.hpp"
#include "halfvec/platform/context.hpp"
#include "halfvec/scene/primitives.hpp"

namespace {
std::vector<double> oneToN(int n) {
  std::vector<double> v(static_cast<size_t>(n));
  std::iota(v.begin(), v.end(), 1.0);
  std::reverse(v.begin(), v.end());  // order of the input must not matter
  return v;
}
}  // namespace

// Binomial(n, 1/2) order statistics, worked by hand: n = 5 gives [min, max] with coverage
// 1 - 2/32; n = 20 gives [x_6, x_15] (P(B <= 5) = 0.0207, so coverage 0.9586; x_7..x_14 would
// cover only 0.885); n = 1 is the value itself.
TEST(Bench, MedianIntervalIsTheBinomialOrderStatistic) {
  const auto five = hv::eval::medianInterval(oneToN(5));
  EXPECT_EQ(five.median, 3.0);
  EXPECT_EQ(five.lo, 1.0);
  EXPECT_EQ(five.hi, 5.0);
  EXPECT_NEAR(five.coverage, 1.0 - 2.0 / 32.0, 1e-12);
  const auto twenty = hv::eval::medianInterval(oneToN(20));
  EXPECT_EQ(twenty.median, 10.5);
  EXPECT_EQ(twenty.lo, 6.0);
  EXPECT_EQ(twenty.hi, 15.0);
  EXPECT_NEAR(twenty.coverage, 0.9586, 1e-4);
  EXPECT_TRUE(twenty.contains(10.0));
  EXPECT_FALSE(twenty.contains(16.0));
  const auto one = hv::eval::medianInterval({4.0});
  EXPECT_EQ(one.lo, 4.0);
  EXPECT_EQ(one.hi, 4.0);
  EXPECT_EQ(hv::eval::medianInterval({}).n, 0u);
}

// Every pass of the frame is reported with its ratio to the floor pass of the same frames; the
// floor itself is not among the passes. (No timing is asserted: times are the bench's business.)
TEST(Bench, FrameCostReportsEveryPassAgainstTheFloor) {
  auto ctx = hv::createHeadlessContext();
  hv::Scene s;
  s.camera.position = {0.0f, 1.5f, 3.0f};
  s.camera.target = {0.0f, 0.4f, 0.0f};
  hv::Material m;
  hv::addMeshObject(s, hv::makePlane(6.0f, 6.0f), m, glm::vec3(0.0f));
  hv::Light l;
  l.position = {0.0f, 1.0f, 0.0f};
  s.lights.push_back(l);
  s.settings.culling = hv::Culling::Tiled;  // `auto` would skip the culling pass for one light
  const hv::eval::FrameCost c = hv::eval::measureFrameCost(s, "tiny", 64, 48, 3);
  EXPECT_EQ(c.frames, 3);
  EXPECT_GT(c.floor_ms, 0.0);
  std::vector<std::string> names;
  double sum = 0.0;
  for (const auto& p : c.passes) {
    names.push_back(p.pass);
    EXPECT_GT(p.floor_ratio.median, 0.0) << p.pass;
    EXPECT_LE(p.floor_ratio.lo, p.floor_ratio.hi) << p.pass;
    sum += p.ms;
  }
  EXPECT_EQ(names,
            (std::vector<std::string>{"gbuffer", "light_cull", "light", "ambient", "tonemap"}));
  EXPECT_EQ(c.frame.pass, "frame");
  EXPECT_GT(c.frame.ms, 0.0);
  EXPECT_GT(sum, 0.0);
}

// bench --frame --vs-brute: both renderers run every round (one ratio per round), whatever the
// scene's own culling setting.
TEST(Bench, TiledVsBruteForcePairsEveryRound) {
  auto ctx = hv::createHeadlessContext();
  hv::Scene s;
  s.camera.position = {0.0f, 1.5f, 3.0f};
  s.camera.target = {0.0f, 0.4f, 0.0f};
  hv::Material m;
  hv::addMeshObject(s, hv::makePlane(6.0f, 6.0f), m, glm::vec3(0.0f));
  for (int i = 0; i < 4; ++i) {
    hv::Light l;
    l.position = {float(i) - 1.5f, 1.0f, 0.0f};
    s.lights.push_back(l);
  }
  s.settings.culling = hv::Culling::BruteForce;
  const hv::eval::TiledVsBrute r = hv::eval::measureTiledVsBruteForce(s, "four", 64, 48, 3);
  EXPECT_EQ(r.scene, "four");
  EXPECT_EQ(r.frames, 3);
  EXPECT_EQ(r.ratio.n, 3u);
  EXPECT_GT(r.tiled_ms, 0.0);
  EXPECT_GT(r.brute_ms, 0.0);
  EXPECT_GT(r.ratio.median, 0.0);
  EXPECT_LE(r.ratio.lo, r.ratio.median);
  EXPECT_GE(r.ratio.hi, r.ratio.median);
}
