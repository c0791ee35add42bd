// The trade report (halfvec/eval/trade.hpp) on a tiny scene: which rows it plans, that its rows
// are internally consistent (finite images, the exact configuration lowest within noise, the
// Pareto marks, the named picks satisfy their bounds), the reference cache, and the files.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "halfvec/eval/trade.hpp"
#include "halfvec/image/image.hpp"
#include "halfvec/platform/context.hpp"
#include "halfvec/scene/presets.hpp"
#include "halfvec/scene/primitives.hpp"

namespace fs = std::filesystem;

namespace {

// A glossy, glowing sphere on a rough floor, a point and a sphere light, a dim uniform
// environment.
hv::Scene tinyScene() {
  hv::Scene s;
  s.camera.position = {0.0f, 1.5f, 3.0f};
  s.camera.target = {0.0f, 0.4f, 0.0f};
  hv::Material floor;
  floor.base_color = glm::vec3(0.6f);
  floor.roughness = 0.8f;
  hv::Material ball;
  ball.base_color = glm::vec3(0.9f, 0.6f, 0.3f);
  ball.metallic = 1.0f;
  ball.roughness = 0.6f;
  ball.emissive = glm::vec3(0.4f, 0.1f, 0.0f);  // the reference is given the engine's
  hv::addMeshObject(s, hv::makePlane(6.0f, 6.0f), floor, glm::vec3(0.0f));
  hv::addMeshObject(s, hv::makeSphere(0.5f, 32, 16), ball, {0.0f, 0.5f, 0.0f});
  hv::Light point;
  point.position = {1.0f, 2.0f, 1.0f};
  point.intensity = 4.0f;
  point.range = 8.0f;
  hv::Light sphere = point;
  sphere.type = hv::LightType::Sphere;
  sphere.position = {-1.2f, 1.2f, 0.8f};
  sphere.radius = 0.2f;
  s.lights = {point, sphere};
  s.environment.kind = hv::EnvironmentKind::Uniform;
  s.environment.color = glm::vec3(0.05f);
  // Tiled, so that the culling row (brute force) compares two ways of running the light pass;
  // `auto` would pick brute force for two lights.
  s.settings.culling = hv::Culling::Tiled;
  return s;
}

const hv::eval::TradeRow* find(const hv::eval::TradeReport& r, const std::string& name) {
  for (const auto& row : r.rows) {
    if (row.config.name == name) return &row;
    for (const auto& a : row.config.aliases)
      if (a == name) return &row;
  }
  return nullptr;
}

bool hasRow(const hv::eval::TradePlan& p, const std::string& prefix) {
  return std::any_of(p.configs.begin(), p.configs.end(),
                     [&](const hv::eval::TradeConfig& c) { return c.name.rfind(prefix, 0) == 0; });
}

struct TempDir {
  fs::path path;
  TempDir() {
    path = fs::temp_directory_path() /
           ("hv_trade_test_" + std::to_string(std::hash<std::string>{}(
                                   std::to_string(reinterpret_cast<uintptr_t>(this)))));
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~TempDir() { fs::remove_all(path); }
};

}  // namespace

TEST(TradePlan, SkipsOptionsThatDoNotApply) {
  hv::Scene s = tinyScene();
  hv::eval::TradePlan p = hv::eval::tradePlan(s);
  ASSERT_FALSE(p.configs.empty());
  EXPECT_EQ(p.configs.front().name, "scene");
  EXPECT_TRUE(hasRow(p, "sphere_diffuse="));
  EXPECT_FALSE(hasRow(p, "tube_"));                          // no tube lights
  EXPECT_FALSE(hasRow(p, "environment.prefilter_samples"));  // uniform environment
  EXPECT_TRUE(hasRow(p, "culling=brute_force"));             // 2 lights: cheap
  EXPECT_TRUE(hasRow(p, "preset=accurate") ||
              std::any_of(p.configs.begin(), p.configs.end(), [](const auto& c) {
                return std::find(c.aliases.begin(), c.aliases.end(), "preset=accurate") !=
                       c.aliases.end();
              }));

  s.environment.kind = hv::EnvironmentKind::None;
  s.lights.assign(100, s.lights[0]);  // point lights only
  p = hv::eval::tradePlan(s, 64);
  EXPECT_FALSE(hasRow(p, "env_brdf"));
  EXPECT_FALSE(hasRow(p, "irradiance"));
  EXPECT_FALSE(hasRow(p, "culling"));  // 100 lights > 64
  EXPECT_FALSE(hasRow(p, "sphere_"));
  EXPECT_GE(p.skipped.size(), 3u);

  // Identical configurations are merged: no two rows share settings and prefilter count.
  for (size_t i = 0; i < p.configs.size(); ++i)
    for (size_t j = i + 1; j < p.configs.size(); ++j)
      EXPECT_FALSE(p.configs[i].prefilter_samples == p.configs[j].prefilter_samples &&
                   p.configs[i].settings == p.configs[j].settings)
          << p.configs[i].name << " / " << p.configs[j].name;
}

TEST(TradePlan, TruthReplacesApproximationsOnly) {
  hv::RenderSettings s;
  s.f = hv::FresnelTerm::SchlickSG;
  s.diffuse = hv::DiffuseTerm::Burley;
  s.energy_compensation = true;
  const hv::RenderSettings t = hv::eval::truthSettings(s);
  EXPECT_EQ(t.v, hv::VisibilityTerm::SmithGGXCorrelated);
  EXPECT_EQ(t.f, hv::FresnelTerm::SchlickPow5);
  EXPECT_FALSE(t.remap_roughness);
  EXPECT_FALSE(t.falloff_plus_one);
  EXPECT_EQ(t.d, s.d);
  EXPECT_EQ(t.diffuse, hv::DiffuseTerm::Burley);  // material model: kept
  EXPECT_TRUE(t.energy_compensation);
}

TEST(Trade, TinySceneRowsAreConsistent) {
  auto ctx = hv::createHeadlessContext();
  TempDir dir;
  hv::Scene scene = tinyScene();
  hv::eval::TradeOptions o;
  o.width = 64;
  o.height = 48;
  o.frames = 1;
  o.rounds = 1;
  o.samples = 128;
  o.threads = 2;
  o.cache_dir = (dir.path / "cache").string();
  o.report_dir = (dir.path / "report").string();
  o.heatmaps = hv::eval::TradeOptions::Heatmaps::Presets;
  const hv::eval::TradeReport r = hv::eval::runTrade(scene, o);

  ASSERT_GE(r.rows.size(), 10u);
  EXPECT_FALSE(r.reference_cached);
  EXPECT_GT(r.lit_pixels, 64u * 48u / 4);
  EXPECT_GT(r.noise_rel_rmse, 0.0);  // the sphere light is sampled
  for (const auto& row : r.rows) {
    EXPECT_EQ(row.nonfinite, 0) << row.config.name;
    EXPECT_TRUE(std::isfinite(row.error.rel_rmse)) << row.config.name;
    EXPECT_EQ(row.error.compared_pixels, int64_t(r.lit_pixels)) << row.config.name;
    EXPECT_GT(row.total_ms, 0.0) << row.config.name;
    EXPECT_LE(row.bias_rel_rmse, row.error.rel_rmse + 1e-12) << row.config.name;
    // The cost axis: frame by frame against the scene row, with an interval around the median.
    EXPECT_GT(row.cost_lo, 0.0) << row.config.name;
    EXPECT_LE(row.cost_lo, row.cost_ratio) << row.config.name;
    EXPECT_LE(row.cost_ratio, row.cost_hi) << row.config.name;
    EXPECT_EQ(row.same_cost, row.cost_lo <= 1.0 && 1.0 <= row.cost_hi) << row.config.name;
    // One round of one frame: the one ratio is the rows' frame times' ratio.
    EXPECT_NEAR(row.cost_ratio, row.total_ms / r.rows.front().total_ms, 1e-9) << row.config.name;
  }
  // The per-pass cost axis: each option timed on the passes it changes. One frame: the ratio of
  // those passes' times (their sum for culling); presets and exact: the frame's.
  auto passMs = [](const hv::eval::TradeRow& row, const std::string& p) {
    for (const auto& [name, ms] : row.pass_ms)
      if (name == p) return ms;
    return 0.0;  // not run (brute force has no culling pass)
  };
  const auto& scene_row = r.rows.front();
  bool saw_light = false, saw_ambient = false, saw_culling = false, saw_frame = false;
  for (size_t k = 1; k < r.rows.size(); ++k) {
    const auto& row = r.rows[k];
    const std::string& g = row.config.group;
    EXPECT_EQ(row.cost_passes, hv::eval::costPasses(g)) << row.config.name;
    EXPECT_EQ(row.pass_same_cost, row.pass_cost_lo <= 1.0 && 1.0 <= row.pass_cost_hi);
    double mine = 0.0, theirs = 0.0;
    for (const std::string& p : row.cost_passes) {
      mine += passMs(row, p);
      theirs += passMs(scene_row, p);
    }
    if (row.cost_passes.empty()) {
      saw_frame = true;
      EXPECT_EQ(row.pass_cost_ratio, row.cost_ratio) << row.config.name;
    } else {
      EXPECT_NEAR(row.pass_cost_ratio, mine / theirs, 1e-9) << row.config.name;
    }
    saw_light |= g == "brdf" || g == "lights";
    saw_ambient |= g == "environment";
    saw_culling |= g == "culling";
  }
  EXPECT_TRUE(saw_light && saw_ambient && saw_culling && saw_frame);
  EXPECT_EQ(hv::eval::costPasses("lights"), std::vector<std::string>{"light"});
  EXPECT_EQ(hv::eval::costPasses("environment"), std::vector<std::string>{"ambient"});
  EXPECT_EQ(hv::eval::costPasses("culling"), (std::vector<std::string>{"light_cull", "light"}));
  EXPECT_TRUE(hv::eval::costPasses("preset").empty());

  // The scene row against itself: exactly 1 in every frame.
  EXPECT_EQ(r.rows.front().cost_ratio, 1.0);
  EXPECT_EQ(r.rows.front().cost_lo, 1.0);
  EXPECT_EQ(r.rows.front().cost_hi, 1.0);
  EXPECT_TRUE(r.rows.front().same_cost);

  // The exact configuration has the lowest error, within the reference's noise.
  ASSERT_GE(r.exact_row, 0);
  const auto& exact = r.rows[size_t(r.exact_row)];
  double lowest = 1e30;
  for (const auto& row : r.rows) lowest = std::min(lowest, row.error.rel_rmse);
  EXPECT_LE(exact.error.rel_rmse, lowest + hv::eval::kNoiseFactor * r.noise_rel_rmse);
  // ... and the scene's own settings (falloff +1, remap, Schlick V) are measurably worse.
  EXPECT_GT(r.rows.front().error.rel_rmse, exact.error.rel_rmse + r.noise_rel_rmse);
  // Culling changes the speed, not the image.
  const auto* brute = find(r, "culling=brute_force");
  ASSERT_NE(brute, nullptr);
  EXPECT_NEAR(brute->error.rel_rmse, r.rows.front().error.rel_rmse, 1e-3);

  // The ball's emissive is in the engine's image and added to the reference: the exact row's
  // headline error is that of its shading, below 10%.
  EXPECT_GT(r.emissive_pixels, 64u * 48u / 20);
  EXPECT_LT(hv::eval::headlineError(exact), 0.1);
  for (const auto& row : r.rows) {
    EXPECT_GE(row.error.top_share, 0.0) << row.config.name;
    EXPECT_LE(row.error.top_share, 1.0) << row.config.name;
  }

  // Pareto marks (time and the headline error): a marked row is dominated by none, an unmarked
  // one by some row.
  using hv::eval::headlineError;
  for (const auto& row : r.rows) {
    bool dominated = false;
    for (const auto& o2 : r.rows) {
      dominated |= &o2 != &row && o2.total_ms <= row.total_ms &&
                   headlineError(o2) <= headlineError(row) &&
                   (o2.total_ms < row.total_ms || headlineError(o2) < headlineError(row));
    }
    EXPECT_EQ(row.pareto, !dominated) << row.config.name;
  }

  // The picks satisfy their bounds and are the best under them.
  EXPECT_EQ(r.max_ms, r.rows.front().total_ms);  // default: the scene's own time
  ASSERT_GE(r.most_accurate_within_ms, 0);
  const auto& acc = r.rows[size_t(r.most_accurate_within_ms)];
  EXPECT_LE(acc.total_ms, r.max_ms);
  if (r.cheapest_within_error >= 0) {
    EXPECT_LE(headlineError(r.rows[size_t(r.cheapest_within_error)]), r.max_error);
  }
  for (const auto& row : r.rows) {
    if (row.total_ms <= r.max_ms) {
      EXPECT_GE(headlineError(row), headlineError(acc));
    }
    if (r.cheapest_within_error >= 0 && headlineError(row) <= r.max_error) {
      EXPECT_GE(row.total_ms, r.rows[size_t(r.cheapest_within_error)].total_ms);
    }
  }
  hv::eval::TradeReport tight = r;  // a bound nothing meets names nothing
  tight.max_error = 1e-9;
  tight.max_ms = 1e-9;
  hv::eval::pickConfigurations(tight);
  EXPECT_EQ(tight.cheapest_within_error, -1);
  EXPECT_EQ(tight.most_accurate_within_ms, -1);

  // Heat maps (the report's formats: tests/app/test_trade_report.cpp).
  EXPECT_TRUE(fs::exists(fs::path(o.report_dir) / "heatmaps" / "scene.png"));
  EXPECT_FALSE(fs::exists(fs::path(o.report_dir) / "heatmaps" / "culling-brute_force.png"));

  // Second run: the reference comes from the cache, bit for bit.
  hv::eval::TradeOptions o2 = o;
  o2.report_dir.clear();
  const hv::eval::TradeReport again = hv::eval::runTrade(scene, o2);
  EXPECT_TRUE(again.reference_cached);
  EXPECT_EQ(again.noise_rmse, r.noise_rmse);
  EXPECT_NEAR(again.rows.front().error.rel_rmse, r.rows.front().error.rel_rmse, 1e-6);
}
