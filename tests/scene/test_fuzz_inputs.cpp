// Replays the committed hostile and fuzzer-found inputs of tests/fuzz/scene and tests/fuzz/gltf
// (minimized; scripts/fuzz.sh also seeds its corpora with them): each must load or be rejected
// with a SceneError naming the file, never crash or throw anything else.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "halfvec/scene/gltf_loader.hpp"
#include "halfvec/scene/scene_loader.hpp"

namespace fs = std::filesystem;

namespace {

std::vector<fs::path> inputs(const char* target) {
  std::vector<fs::path> out;
  for (const auto& e :
       fs::directory_iterator(fs::path(HV_SOURCE_DIR) / "tests" / "fuzz" / target)) {
    out.push_back(e.path());
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace

TEST(FuzzInputs, SceneFilesAndOverrides) {
  int rejected = 0;
  for (const fs::path& p : inputs("scene")) {
    std::ifstream f(p, std::ios::binary);
    const std::string all((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
    const size_t nul = all.find('\0');  // as the fuzzer's input: JSON, then NUL-separated --set
    std::vector<std::string> overrides;
    if (nul != std::string::npos) overrides.push_back(all.substr(nul + 1));
    try {
      hv::loadSceneFromString(all.substr(0, nul), p.string(), overrides);
    } catch (const hv::SceneError& e) {
      EXPECT_NE(std::string(e.what()).find(p.string()), std::string::npos) << e.what();
      ++rejected;
    }
  }
  EXPECT_EQ(rejected, int(inputs("scene").size())) << "every committed scene input is hostile";
}

TEST(FuzzInputs, GltfFiles) {
  int rejected = 0;
  for (const fs::path& p : inputs("gltf")) {
    hv::Scene scene;
    try {
      hv::loadGltf(p.string(), glm::mat4(1.0f), scene);
    } catch (const hv::SceneError& e) {
      EXPECT_NE(std::string(e.what()).find(p.string()), std::string::npos) << e.what();
      ++rejected;
    }
  }
  EXPECT_EQ(rejected, int(inputs("gltf").size())) << "every committed glTF input is hostile";
}
