// The scene file's shadow keys (docs/scene-format.md): a light's "shadows", the settings
// shadow_filter and shadow_map_size; read, rejected with the field named, and written back.
#include <gtest/gtest.h>

#include <string>

#include "halfvec/scene/scene_error.hpp"
#include "halfvec/scene/scene_loader.hpp"
#include "halfvec/scene/scene_writer.hpp"

using namespace hv;

namespace {

const char* kScene = R"({
  "objects": [{"primitive": "plane", "size": [4, 4]}],
  "lights": [
    {"type": "point", "position": [0, 2, 0], "shadows": true},
    {"type": "sphere", "position": [1, 2, 0], "radius": 0.2},
    {"type": "tube", "position": [-1, 2, 0], "radius": 0.05, "length": 1, "shadows": false}
  ],
  "settings": {"shadow_filter": "pcf", "shadow_map_size": 512}
})";

std::string errorOf(const std::string& text) {
  try {
    loadSceneFromString(text, "s.json");
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(ShadowKeys, ReadFromLightsAndSettings) {
  const Scene s = loadSceneFromString(kScene, "s.json");
  ASSERT_EQ(s.lights.size(), 3u);
  EXPECT_TRUE(s.lights[0].shadows);
  EXPECT_FALSE(s.lights[1].shadows);  // the default
  EXPECT_FALSE(s.lights[2].shadows);
  EXPECT_EQ(s.settings.shadow_filter, ShadowFilter::Pcf);
  EXPECT_EQ(s.settings.shadow_map_size, 512);
  const Scene d = loadSceneFromString(R"({"lights": [{"type": "point"}]})", "d.json");
  EXPECT_EQ(d.settings.shadow_filter, ShadowFilter::Pcss);
  EXPECT_EQ(d.settings.shadow_map_size, 1024);
  EXPECT_EQ(d.settings.shadow_resolution, ShadowResolution::Full);
}

TEST(ShadowKeys, BadValuesNameTheField) {
  std::string e = errorOf(R"({"lights": [{"type": "sphere", "shadows": 1}]})");
  EXPECT_NE(e.find("/lights/0/shadows"), std::string::npos) << e;
  EXPECT_NE(e.find("expected true or false"), std::string::npos) << e;
  e = errorOf(R"({"settings": {"shadow_filter": "vsm"}})");
  EXPECT_NE(e.find("/settings/shadow_filter"), std::string::npos) << e;
  EXPECT_NE(e.find("pcss"), std::string::npos) << e;  // the names it takes
  e = errorOf(R"({"settings": {"shadow_map_size": 4096}})");
  EXPECT_NE(e.find("/settings/shadow_map_size"), std::string::npos) << e;
  EXPECT_NE(e.find("2048"), std::string::npos) << e;
  e = errorOf(R"({"settings": {"shadow_resolution": "quarter"}})");
  EXPECT_NE(e.find("/settings/shadow_resolution"), std::string::npos) << e;
  EXPECT_NE(e.find("half"), std::string::npos) << e;
}

TEST(ShadowKeys, EditsAreWrittenBack) {
  const Scene loaded = loadSceneFromString(kScene, "s.json");
  Scene edited = loaded;
  edited.lights[0].shadows = false;
  edited.lights[1].shadows = true;
  edited.settings.shadow_filter = ShadowFilter::Hard;
  edited.settings.shadow_map_size = 256;
  edited.settings.shadow_resolution = ShadowResolution::Half;
  const std::string out =
      applyJsonEdits(kScene, sceneEdits(kScene, loaded, edited, false, "s.json"), "s.json");
  const Scene again = loadSceneFromString(out, "s.json");
  EXPECT_FALSE(again.lights[0].shadows);
  EXPECT_TRUE(again.lights[1].shadows);
  EXPECT_FALSE(again.lights[2].shadows);
  EXPECT_EQ(again.settings.shadow_filter, ShadowFilter::Hard);
  EXPECT_EQ(again.settings.shadow_map_size, 256);
  EXPECT_EQ(again.settings.shadow_resolution, ShadowResolution::Half);
}
