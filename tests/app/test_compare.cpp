// `halfvec compare` as a regression test: exit 0 within the tolerances, 1 outside, 2 for bad
// input; PNG and PFM; outputs whole or not at all.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/cli.hpp"
#include "halfvec/image/image.hpp"
#include "halfvec/image/metrics.hpp"

namespace fs = std::filesystem;

namespace {

fs::path tmp(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("hv_compare_test_" + std::to_string(getpid()));
  fs::create_directories(d);
  return d / name;
}

int compare(std::vector<std::string> args) {
  args.insert(args.begin(), "compare");
  testing::internal::CaptureStdout();
  testing::internal::CaptureStderr();
  const int rc = hv::app::runCli(args);
  testing::internal::GetCapturedStdout();
  testing::internal::GetCapturedStderr();
  return rc;
}

// A reference of 100 pixels at 0.5 and a test equal to it except `n` pixels at 0.5 + delta.
void writePair(const std::string& ext, int n, float delta) {
  hv::ImageRGBf ref = hv::makeImageRGBf(10, 10, glm::vec3(0.5f)), test = ref;
  for (int i = 0; i < n; ++i) test.px[size_t(i)] += glm::vec3(delta);
  if (ext == "pfm") {
    hv::writePfm(tmp("ref.pfm").string(), ref);
    hv::writePfm(tmp("test.pfm").string(), test);
  } else {
    hv::writePng(tmp("ref.png").string(), hv::toSrgb8(ref));
    hv::writePng(tmp("test.png").string(), hv::toSrgb8(test));
  }
}

}  // namespace

TEST(Compare, ExitStatusFollowsEachTolerance) {
  writePair("pfm", 2, 0.25f);  // 2 of 100 pixels off by 0.25 (relative 0.5)
  const std::string t = tmp("test.pfm").string(), r = tmp("ref.pfm").string();
  EXPECT_EQ(compare({t, r}), 0);  // no tolerance: metrics only
  EXPECT_EQ(compare({t, r, "--max-abs", "0.3"}), 0);
  EXPECT_EQ(compare({t, r, "--max-abs", "0.2"}), 1);
  // rel RMSE = sqrt(2 * 0.25^2 / 100) / 0.5 = 0.0707
  EXPECT_EQ(compare({t, r, "--max-rel-rmse", "0.08"}), 0);
  EXPECT_EQ(compare({t, r, "--max-rel-rmse", "0.06"}), 1);
  // 2% of the pixels are off: the 99th percentile sees one of them (relative error ~0.49)
  EXPECT_EQ(compare({t, r, "--max-p99", "0.5"}), 0);
  EXPECT_EQ(compare({t, r, "--max-p99", "0.4"}), 1);
  // Any subset: every given one must hold.
  EXPECT_EQ(compare({t, r, "--max-abs", "1", "--max-rel-rmse", "0.06"}), 1);
  EXPECT_EQ(compare({t, r, "--max-abs", "1", "--max-rel-rmse", "0.08", "--max-p99", "0.5"}), 0);
}

TEST(Compare, ReadsPng) {
  writePair("png", 1, 0.4f);
  const std::string t = tmp("test.png").string(), r = tmp("ref.png").string();
  EXPECT_EQ(compare({r, r, "--max-abs", "0"}), 0);
  EXPECT_EQ(compare({t, r, "--max-abs", "0.1"}), 1);
  EXPECT_EQ(compare({t, r, "--max-abs", "0.3"}), 0);  // 8-bit values / 255: sRGB 0.74 vs 0.91
}

TEST(Compare, BadInputIsStatus2) {
  writePair("pfm", 0, 0.0f);
  const std::string r = tmp("ref.pfm").string();
  EXPECT_EQ(compare({tmp("missing.pfm").string(), r}), 2);
  { std::ofstream(tmp("garbage.pfm")) << "not an image"; }
  EXPECT_EQ(compare({tmp("garbage.pfm").string(), r}), 2);
  hv::writePfm(tmp("small.pfm").string(), hv::makeImageRGBf(5, 10));
  EXPECT_EQ(compare({tmp("small.pfm").string(), r, "--max-abs", "1"}), 2);  // size mismatch
  writePair("png", 0, 0.0f);
  EXPECT_EQ(compare({tmp("ref.png").string(), r}), 2);  // PNG against PFM
  EXPECT_EQ(compare({r, r, "--max-abs", "-1"}), 2);
  EXPECT_EQ(compare({r}), 2);
  EXPECT_EQ(compare({r, r, "--heatmap", "/nonexistent/dir/h.png"}), 2);
}

TEST(Compare, NanInTheTestImageFailsAnyTolerance) {
  hv::ImageRGBf ref = hv::makeImageRGBf(4, 4, glm::vec3(0.5f)), test = ref;
  test.px[3].y = std::numeric_limits<float>::quiet_NaN();
  hv::writePfm(tmp("nan.pfm").string(), test);
  hv::writePfm(tmp("ref4.pfm").string(), ref);
  EXPECT_EQ(compare({tmp("nan.pfm").string(), tmp("ref4.pfm").string(), "--max-abs", "10"}), 1);
}

TEST(Compare, FailedRunWritesNoOutputs) {
  writePair("pfm", 0, 0.0f);
  const fs::path json = tmp("out.json"), heat = tmp("heat.png");
  fs::remove(json);
  fs::remove(heat);
  EXPECT_EQ(compare({tmp("missing.pfm").string(), tmp("ref.pfm").string(), "--json", json.string(),
                     "--heatmap", heat.string()}),
            2);
  EXPECT_FALSE(fs::exists(json));
  EXPECT_FALSE(fs::exists(heat));
  EXPECT_EQ(compare({tmp("ref.pfm").string(), tmp("ref.pfm").string(), "--json", json.string()}),
            0);
  nlohmann::json j;
  std::ifstream(json) >> j;
  EXPECT_TRUE(j["pass"].get<bool>());
}

TEST(Compare, ToleranceViolationsNameTheMetric) {
  hv::ErrorMetrics m;
  m.rel_rmse = 0.5;
  hv::Tolerances t;
  t.max_rel_rmse = 0.1;
  const auto v = hv::toleranceViolations(m, t);
  ASSERT_EQ(v.size(), 1u);
  EXPECT_NE(v[0].find("rel_rmse"), std::string::npos);
  EXPECT_TRUE(hv::toleranceViolations(m, {}).empty());
}
