// The viewer-like options of render and view: --print-scene applies --set, the camera options,
// --no-key-light and --look gltf, each checked on what --print-scene prints and on a render.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/cli.hpp"
#include "scene/gltf_test_files.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

std::string defaultScene() {
  return std::string(HV_SAMPLES_DIR) + "/default.json";
}

// The tests' hand-built quad as a model file.
std::string quadModel() {
  const fs::path p = hv::test::tempDir() / "cli_quad.gltf";
  std::ofstream(p) << hv::test::quad().dump();
  return p.string();
}

// What --print-scene prints for `args` (rc 0 asserted), as ordered JSON.
nlohmann::ordered_json printed(std::vector<std::string> args) {
  args.insert(args.begin(), "render");
  args.push_back("--print-scene");
  testing::internal::CaptureStdout();
  EXPECT_EQ(hv::app::runCli(args), 0);
  return nlohmann::ordered_json::parse(testing::internal::GetCapturedStdout());
}

std::string runErr(const std::vector<std::string>& args, int expected_rc) {
  testing::internal::CaptureStderr();
  EXPECT_EQ(hv::app::runCli(args), expected_rc);
  return testing::internal::GetCapturedStderr();
}

}  // namespace

TEST(CliViewer, PrintSceneAppliesSetKeepingKeyOrder) {
  const auto plain = printed({defaultScene()});
  const auto set =
      printed({defaultScene(), "--set", "settings.exposure=2.5", "--set", "lights.0.intensity=7"});
  EXPECT_EQ(set["settings"]["exposure"], 2.5);
  EXPECT_EQ(set["lights"][0]["intensity"], 7);
  // Everything else as the file has it, in the file's order.
  std::vector<std::string> keys_plain, keys_set;
  for (auto it = plain.begin(); it != plain.end(); ++it) keys_plain.push_back(it.key());
  for (auto it = set.begin(); it != set.end(); ++it) keys_set.push_back(it.key());
  EXPECT_EQ(keys_set, keys_plain);
  EXPECT_EQ(set["camera"], plain["camera"]);
  // A bad override fails as it does for a render.
  const std::string err =
      runErr({"render", defaultScene(), "--print-scene", "--set", "lights.99.intensity=1"}, 1);
  EXPECT_NE(err.find("lights.99"), std::string::npos) << err;
}

TEST(CliViewer, CameraOptions) {
  const auto j = printed(
      {quadModel(), "--camera-position", "1,2,3.5", "--camera-target", "0,0.5,0", "--fov", "30"});
  EXPECT_EQ(j["camera"]["position"], json::parse("[1, 2, 3.5]"));
  EXPECT_EQ(j["camera"]["target"], json::parse("[0, 0.5, 0]"));
  EXPECT_EQ(j["camera"]["fov_y_deg"], 30);
  // Later options win, --set included, in the order given.
  const auto k = printed({defaultScene(), "--fov", "30", "--set", "camera.fov_y_deg=20"});
  EXPECT_EQ(k["camera"]["fov_y_deg"], 20);
  std::string err = runErr({"render", defaultScene(), "--camera-position", "1,2"}, 2);
  EXPECT_NE(err.find("--camera-position expects X,Y,Z"), std::string::npos) << err;
  err = runErr({"render", defaultScene(), "--camera-target", "1,2,x"}, 2);
  EXPECT_NE(err.find("--camera-target"), std::string::npos) << err;
  err = runErr({"render", defaultScene(), "--fov", "180"}, 2);
  EXPECT_NE(err.find("--fov expects a number in [0.01, 179.9]"), std::string::npos) << err;
}

TEST(CliViewer, NoKeyLight) {
  EXPECT_EQ(printed({quadModel()})["lights"].size(), 1u);
  EXPECT_EQ(printed({quadModel(), "--no-key-light"})["lights"].size(), 0u);
  const std::string err = runErr({"render", defaultScene(), "--no-key-light", "--print-scene"}, 1);
  EXPECT_NE(err.find("--no-key-light"), std::string::npos) << err;
}

TEST(CliViewer, LookGltf) {
  const auto j = printed({quadModel(), "--look", "gltf"});
  EXPECT_EQ(j["lights"].size(), 0u);
  EXPECT_EQ(j["settings"]["tone_map"], "pbr_neutral");
  EXPECT_EQ(j["settings"]["gamma"], "srgb");
  EXPECT_EQ(j["settings"]["dither"], false);
  // --set applies after the look.
  EXPECT_EQ(printed({quadModel(), "--look", "gltf", "--set",
                     "settings.dither=true"})["settings"]["dither"],
            true);
  // A scene file keeps its lights: the look only sets the output conventions.
  const auto s = printed({defaultScene(), "--look", "gltf"});
  EXPECT_GT(s["lights"].size(), 0u);
  EXPECT_EQ(s["settings"]["tone_map"], "pbr_neutral");
  const std::string err = runErr({"render", defaultScene(), "--look", "three"}, 2);
  EXPECT_NE(err.find("--look expects gltf or scene"), std::string::npos) << err;
}

TEST(CliViewer, LookGltfRenders) {
  const fs::path out = hv::test::tempDir() / "cli_look.png";
  fs::remove(out);
  testing::internal::CaptureStdout();
  EXPECT_EQ(hv::app::runCli({"render", quadModel(), "--look", "gltf", "--size", "48x32", "--out",
                             out.string(), "--camera-position", "0.5,0.5,3", "--camera-target",
                             "0.5,0.5,0"}),
            0);
  testing::internal::GetCapturedStdout();
  EXPECT_TRUE(fs::is_regular_file(out));
}
