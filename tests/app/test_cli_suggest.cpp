// "Did you mean" for commands, options and view names; --print-scene; models by path through the
// command line (runCli, no subprocess).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "app/cli.hpp"
#include "halfvec/core/suggest.hpp"

namespace {

std::string runErr(const std::vector<std::string>& args, int expected_rc) {
  testing::internal::CaptureStderr();
  EXPECT_EQ(hv::app::runCli(args), expected_rc);
  return testing::internal::GetCapturedStderr();
}

std::string defaultScene() {
  return std::string(HV_SAMPLES_DIR) + "/default.json";
}

}  // namespace

TEST(CliSuggest, ClosestNameNeedsATypoNotAnyWord) {
  const std::vector<std::string_view> names = {"render", "reference", "view"};
  EXPECT_EQ(hv::closestName("rendr", names), "render");
  EXPECT_EQ(hv::closestName("refrence", names), "reference");
  EXPECT_EQ(hv::closestName("vew", names), "view");
  EXPECT_EQ(hv::closestName("completely-different", names), "");
}

TEST(CliSuggest, UnknownCommandSuggestsTheClosest) {
  const std::string err = runErr({"rendr", "x.json"}, 2);
  EXPECT_NE(err.find("did you mean \"render\"?"), std::string::npos) << err;
}

TEST(CliSuggest, UnknownOptionSuggestsOneFromTheHelp) {
  std::string err = runErr({"render", defaultScene(), "--sise", "64x64"}, 2);
  EXPECT_NE(err.find("did you mean \"--size\"?"), std::string::npos) << err;
  err = runErr({"compare", "a.pfm", "b.pfm", "--heatmp", "h.png"}, 2);
  EXPECT_NE(err.find("did you mean \"--heatmap\"?"), std::string::npos) << err;
  err = runErr({"render", defaultScene(), "--zzzzzzzzzz"}, 2);
  EXPECT_EQ(err.find("did you mean"), std::string::npos) << err;
}

TEST(CliSuggest, UnknownViewNameSuggestsOne) {
  const std::string err = runErr({"render", defaultScene(), "--view", "dpth"}, 2);
  EXPECT_NE(err.find("did you mean \"depth\"?"), std::string::npos) << err;
  EXPECT_NE(err.find("lights_per_tile"), std::string::npos) << err;  // and lists them all
}

TEST(CliSuggest, PrintSceneWritesLoadableJson) {
  testing::internal::CaptureStdout();
  ASSERT_EQ(hv::app::runCli({"render", defaultScene(), "--print-scene"}), 0);
  const std::string out = testing::internal::GetCapturedStdout();
  const auto j = nlohmann::json::parse(out);
  EXPECT_TRUE(j.contains("camera"));
  EXPECT_TRUE(j.contains("objects"));
}

TEST(CliSuggest, ModelFileWithSceneOptionsIsNotAJsonError) {
  // A .glb that is not a glTF: the error is the glTF loader's, not "invalid JSON".
  const auto p = std::filesystem::temp_directory_path() / "hv_not_a_model.glb";
  { std::ofstream(p) << "not a model"; }
  const std::string err = runErr({"render", p.string(), "--print-scene"}, 1);
  EXPECT_EQ(err.find("invalid JSON"), std::string::npos) << err;
  EXPECT_NE(err.find("hv_not_a_model.glb"), std::string::npos) << err;
  std::filesystem::remove(p);
}
