// End-to-end tests of the halfvec command through runCli (no subprocess).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>

#include <nlohmann/json.hpp>

#include "app/cli.hpp"
#include "halfvec/image/image.hpp"

namespace fs = std::filesystem;

namespace {
std::string samples() {
  return HV_SAMPLES_DIR;
}
fs::path tmp(const std::string& name) {
  fs::path d = fs::temp_directory_path() / "hv_cli_test";
  fs::create_directories(d);
  return d / name;
}
}  // namespace

TEST(Cli, HelpDocumentsEveryRenderFlag) {
  testing::internal::CaptureStdout();
  EXPECT_EQ(hv::app::runCli({"render", "--help"}), 0);
  const std::string out = testing::internal::GetCapturedStdout();
  for (const char* flag : {"--size", "--out", "--hdr", "--stats", "--set", "--view"}) {
    EXPECT_NE(out.find(flag), std::string::npos) << flag;
  }
}

TEST(Cli, UnknownOptionIsAUsageError) {
  EXPECT_EQ(hv::app::runCli({"render", samples() + "/default.json", "--bogus"}), 2);
  EXPECT_EQ(hv::app::runCli({"nonsense"}), 2);
}

// `accuracy --only SECTION` measures one section, which is not the whole report: without --out
// it is a usage error before anything is measured, not a run that replaces docs/accuracy.md.
TEST(Cli, AccuracyOnlyNeedsItsOwnOutput) {
  for (const char* section : {"shadows", "occlusion"}) {
    testing::internal::CaptureStderr();
    EXPECT_EQ(hv::app::runCli({"accuracy", "--only", section}), 2) << section;
    const std::string err = testing::internal::GetCapturedStderr();
    EXPECT_NE(err.find("--out"), std::string::npos) << err;
  }
  EXPECT_EQ(hv::app::runCli({"accuracy", "--out", ""}), 2);
}

// The sphere and tube sections alone (--quick: small grids, seconds) carry the straddling goals:
// the spheres' and the capsules' counts within 10% and 15% bias, each over a table of its own.
TEST(Cli, AccuracySpheresAndTubesReportTheStraddlingGoals) {
  for (const char* section : {"spheres", "tubes"}) {
    const fs::path out = tmp(std::string("accuracy_") + section + ".md");
    fs::remove(out);
    ASSERT_EQ(hv::app::runCli({"accuracy", "--only", section, "--quick", "--out", out.string()}), 0)
        << section;
    std::ifstream f(out);
    const std::string md((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
    const std::string light = std::string(section) == "spheres" ? "sphere" : "tube";
    for (const char* tol : {"within 10% (bias)", "within 15% (bias)"}) {
      EXPECT_NE(md.find(light + " `ltc` specular straddling the horizon, " + tol),
                std::string::npos)
          << section << ": " << tol;
    }
    EXPECT_NE(md.find(std::string(section) == "spheres" ? "Specular of spheres straddling"
                                                        : "Specular of capsules straddling"),
              std::string::npos)
        << section;
  }
}

TEST(Cli, BadSceneFailsAndWritesNothing) {
  const fs::path scene = tmp("bad.json");
  std::ofstream(scene) << R"({"camera": {"fov_y_deg": "wide"}})";
  const fs::path out = tmp("bad.png");
  fs::remove(out);
  testing::internal::CaptureStderr();
  EXPECT_EQ(hv::app::runCli({"render", scene.string(), "--out", out.string()}), 1);
  const std::string err = testing::internal::GetCapturedStderr();
  EXPECT_NE(err.find("bad.json"), std::string::npos) << err;
  EXPECT_NE(err.find("/camera/fov_y_deg"), std::string::npos) << err;
  EXPECT_FALSE(fs::exists(out));
}

// A scene with a clear_coat material reports the G-buffer's coat target: 24 bytes per pixel.
TEST(Cli, ClearCoatSceneReportsItsGBufferBytes) {
  const fs::path png = tmp("coat.png"), stats = tmp("coat.json");
  ASSERT_EQ(hv::app::runCli({"render", samples() + "/clear_coat.json", "--size", "96x54", "--out",
                             png.string(), "--stats", stats.string()}),
            0);
  nlohmann::json j;
  std::ifstream(stats) >> j;
  EXPECT_EQ(j["gbuffer_bytes_per_pixel"].get<int>(), 24);
}

TEST(Cli, RendersDefaultSceneFiniteAndNotUniform) {
  const fs::path png = tmp("default.png"), pfm = tmp("default.pfm"), stats = tmp("default.json");
  ASSERT_EQ(hv::app::runCli({"render", samples() + "/default.json", "--size", "160x90", "--out",
                             png.string(), "--hdr", pfm.string(), "--stats", stats.string()}),
            0);
  const hv::ImageRGBf hdr = hv::readPfm(pfm.string());
  ASSERT_EQ(hdr.width, 160);
  ASSERT_EQ(hdr.height, 90);
  float lo = 1e30f, hi = -1e30f;
  for (const auto& p : hdr.px) {
    for (int k = 0; k < 3; ++k) {
      ASSERT_TRUE(std::isfinite(p[k]));
      ASSERT_GE(p[k], 0.0f);
      lo = std::min(lo, p[k]);
      hi = std::max(hi, p[k]);
    }
  }
  EXPECT_GT(hi - lo, 0.1f) << "the image is uniform";
  const hv::ImageRGBA8 ldr = hv::readPng(png.string());
  EXPECT_EQ(ldr.width, 160);

  nlohmann::json j;
  std::ifstream(stats) >> j;
  for (const char* k : {"renderer", "width", "height", "passes", "total_ms",
                        "gbuffer_bytes_per_pixel", "light_counts", "program_variants"}) {
    EXPECT_TRUE(j.contains(k)) << k;
  }
  EXPECT_LE(j["gbuffer_bytes_per_pixel"].get<int>(), 16);
  for (const char* pass : {"gbuffer", "light_cull", "light", "ambient", "tonemap"}) {
    EXPECT_TRUE(j["passes"].contains(pass)) << pass;
  }
  EXPECT_EQ(j["light_counts"]["tube"].get<int>(), 1);
  // The manifest: every program of the frame with its key and one reason per define.
  const auto& m = j["manifest"];
  EXPECT_EQ(m["key"].get<std::string>().find("lights point+sphere+tube"), 0u) << m["key"];
  std::set<std::string> names;
  for (const auto& p : m["programs"]) {
    names.insert(
        p["program"].get<std::string>().substr(0, p["program"].get<std::string>().find(' ')));
    const std::string key = p["key"];
    const size_t defines = key.empty() ? 0 : size_t(std::count(key.begin(), key.end(), ';')) + 1;
    EXPECT_EQ(p["reasons"].size(), defines) << p["program"];
  }
  // Three lights: culled in one dispatch (light_cull_few), not by the three stages.
  EXPECT_EQ(names,
            (std::set<std::string>{"gbuffer", "light_cull_few", "light", "ambient", "emitter_cull",
                                   "emitters", "tonemap", "fxaa", "shadow"}));
}

TEST(Cli, UberRendersTheSameImage) {
  const fs::path a = tmp("spec.pfm"), b = tmp("uber.pfm"), stats = tmp("uber.json");
  ASSERT_EQ(hv::app::runCli({"render", samples() + "/default.json", "--size", "96x64", "--out",
                             tmp("spec.png").string(), "--hdr", a.string()}),
            0);
  ASSERT_EQ(hv::app::runCli({"render", samples() + "/default.json", "--size", "96x64", "--out",
                             tmp("uber.png").string(), "--hdr", b.string(), "--uber", "--stats",
                             stats.string()}),
            0);
  nlohmann::json j;
  std::ifstream(stats) >> j;
  EXPECT_NE(j["manifest"]["key"].get<std::string>().find("uber"), std::string::npos);
  const hv::ImageRGBf x = hv::readPfm(a.string()), y = hv::readPfm(b.string());
  ASSERT_EQ(x.px.size(), y.px.size());
  // Same tolerance as tests/render/test_variants.cpp: 2 half-float steps + 1e-4.
  for (size_t i = 0; i < x.px.size(); ++i) {
    for (int k = 0; k < 3; ++k) {
      ASSERT_NEAR(x.px[i][k], y.px[i][k], 1e-4f + std::abs(y.px[i][k]) * (2.0f / 512.0f)) << i;
    }
  }
}

TEST(Cli, SetOverridesAField) {
  const fs::path stats = tmp("override.json");
  ASSERT_EQ(hv::app::runCli({"render", samples() + "/default.json", "--size", "64x64", "--out",
                             tmp("o.png").string(), "--stats", stats.string(), "--set",
                             "settings.culling=\"brute_force\""}),
            0);
  nlohmann::json j;
  std::ifstream(stats) >> j;
  EXPECT_FALSE(j["passes"].contains("light_cull"));
}

TEST(Cli, CompareReportsMetrics) {
  hv::ImageRGBf a = hv::makeImageRGBf(4, 4, glm::vec3(1.0f));
  hv::ImageRGBf b = hv::makeImageRGBf(4, 4, glm::vec3(1.0f));
  b.px[0] = glm::vec3(2.0f);
  hv::writePfm(tmp("a.pfm").string(), a);
  hv::writePfm(tmp("b.pfm").string(), b);
  testing::internal::CaptureStdout();
  ASSERT_EQ(hv::app::runCli({"compare", tmp("a.pfm").string(), tmp("b.pfm").string(), "--json",
                             tmp("m.json").string(), "--heatmap", tmp("h.png").string()}),
            0);
  testing::internal::GetCapturedStdout();
  nlohmann::json j;
  std::ifstream(tmp("m.json")) >> j;
  EXPECT_NEAR(j["max_abs"].get<double>(), 1.0, 1e-9);
  EXPECT_TRUE(fs::exists(tmp("h.png")));
}

// bench --frame --shadow-sweep: one row per filter and number of shadowed lights, and the cached
// maps are not rendered again in the measured frames (the last column, maps rendered, is 0);
// misplaced options are usage errors naming the option.
TEST(Cli, ShadowSweepHasEveryRowAndReusesTheMaps) {
  testing::internal::CaptureStderr();
  EXPECT_EQ(hv::app::runCli({"bench", "--shadow-sweep"}), 2);
  EXPECT_NE(testing::internal::GetCapturedStderr().find("--shadow-sweep goes with --frame"),
            std::string::npos);
  testing::internal::CaptureStderr();
  EXPECT_EQ(hv::app::runCli({"bench", "--frame", "--shadow-sweep", "--scene",
                             samples() + "/shadows.json", "--shaders", "a,b"}),
            2);
  EXPECT_NE(testing::internal::GetCapturedStderr().find("--shadow-sweep takes no"),
            std::string::npos);
  testing::internal::CaptureStdout();
  EXPECT_EQ(hv::app::runCli({"bench", "--frame", "--shadow-sweep", "--scene",
                             samples() + "/shadows.json", "--size", "64x36", "--frames", "2"}),
            0);
  const std::string out = testing::internal::GetCapturedStdout();
  for (const char* row : {"hard, 1 light ", "hard, 2 lights", "pcf, 1 light ", "pcf, 2 lights",
                          "pcss, 1 light ", "pcss, 2 lights"}) {
    const size_t at = out.find(row);
    ASSERT_NE(at, std::string::npos) << row << "\n" << out;
    const std::string line = out.substr(at, out.find('\n', at) - at);
    EXPECT_EQ(line.substr(line.find_last_not_of(' ')), "0") << line;
    EXPECT_EQ(line[line.find_last_not_of(' ') - 1], ' ') << line;
  }
}
