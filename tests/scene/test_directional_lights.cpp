// Directional lights in scene files: fields and defaults, validation errors naming the file and
// the field, the budget of kMaxDirectionalLights, the shadows key, saved edits and the round trip
// (docs/scene-format.md, "lights").
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "halfvec/scene/scene_loader.hpp"
#include "halfvec/scene/scene_writer.hpp"

using nlohmann::json;

namespace {

std::string sceneWithLights(const std::string& lights) {
  return R"({"lights": [)" + lights + "]}";
}

std::string parseError(const std::string& text) {
  std::vector<std::string> warnings;
  try {
    hv::parseScene(json::parse(text), "suns.json", &warnings);
  } catch (const hv::SceneError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(DirectionalLightFiles, SceneFileFieldsAndDefaults) {
  const hv::Scene s = hv::parseScene(json::parse(sceneWithLights(
                                         R"({"type": "directional"},
             {"type": "directional", "direction": [0, 0, -3], "intensity": 2.5,
              "color": [1, 0.9, 0.8], "angular_diameter": 0})")),
                                     "suns.json");
  ASSERT_EQ(s.lights.size(), 2u);
  const hv::Light& a = s.lights[0];
  EXPECT_EQ(a.type, hv::LightType::Directional);
  EXPECT_EQ(hv::lightShape(a), hv::LightType::Directional);
  EXPECT_EQ(a.direction, glm::vec3(0, -1, 0));  // straight down
  EXPECT_EQ(a.angular_diameter, hv::kSunAngularDiameter);
  EXPECT_NEAR(a.angular_diameter, 0.53f * 3.14159265f / 180.0f, 2e-4f);  // the sun's 0.53 deg
  EXPECT_FALSE(a.shadows);
  const hv::Light& b = s.lights[1];
  EXPECT_EQ(b.direction, glm::vec3(0, 0, -1));  // normalized
  EXPECT_EQ(b.intensity, 2.5f);
  EXPECT_EQ(b.angular_diameter, 0.0f);  // a single direction
}

TEST(DirectionalLightFiles, InvalidFieldsAreErrorsNamingFileAndField) {
  struct Case {
    const char* light;
    const char* field;
  } cases[] = {
      {R"({"type": "directional", "direction": [0, 0, 0]})", "suns.json: /lights/0/direction"},
      {R"({"type": "directional", "angular_diameter": -0.1})",
       "suns.json: /lights/0/angular_diameter"},
      {R"({"type": "directional", "angular_diameter": 1.6})",
       "suns.json: /lights/0/angular_diameter"},
      {R"({"type": "directional", "position": [0, 1, 0]})",
       "suns.json: /lights/0/position: unknown key"},
      {R"({"type": "directional", "range": 5})", "suns.json: /lights/0/range: unknown key"},
      {R"({"type": "directional", "radius": 0.1})", "suns.json: /lights/0/radius: unknown key"},
      {R"({"type": "directional", "intensity": -1})", "suns.json: /lights/0/intensity"},
      {R"({"type": "sphere", "angular_diameter": 0.1})",
       "suns.json: /lights/0/angular_diameter: unknown key"},
  };
  for (const Case& c : cases) {
    const std::string e = parseError(sceneWithLights(c.light));
    EXPECT_NE(e.find(c.field), std::string::npos) << c.light << " -> " << e;
  }
  // pi/2 itself is allowed.
  EXPECT_EQ(
      parseError(sceneWithLights(R"({"type": "directional", "angular_diameter": 1.5707963})")), "");
  // The fifth directional light is an error naming it.
  std::string five;
  for (int i = 0; i < 5; ++i) five += std::string(i ? ", " : "") + R"({"type": "directional"})";
  const std::string e = parseError(sceneWithLights(five));
  EXPECT_NE(e.find("suns.json: /lights/4/type: a directional light beyond the scene's 4"),
            std::string::npos)
      << e;
  std::string four;
  for (int i = 0; i < 4; ++i) four += std::string(i ? ", " : "") + R"({"type": "directional"})";
  EXPECT_EQ(parseError(sceneWithLights(four)), "");
}

// "shadows": true loads (the key applies to every light), without a warning: a directional light
// draws an orthographic map.
TEST(DirectionalLightFiles, ShadowsKeyLoadsWithoutAWarning) {
  std::vector<std::string> warnings;
  const hv::Scene s =
      hv::parseScene(json::parse(sceneWithLights(R"({"type": "directional", "shadows": true})")),
                     "suns.json", &warnings);
  EXPECT_TRUE(s.lights[0].shadows);
  EXPECT_TRUE(warnings.empty()) << warnings[0];
}

TEST(DirectionalLightFiles, SavedEditsAndTheRoundTrip) {
  const std::string text = sceneWithLights(R"({"type": "directional", "intensity": 3})");
  const hv::Scene loaded = hv::parseScene(json::parse(text), "suns.json");
  hv::Scene edited = loaded;
  edited.lights[0].direction = {1, 0, 0};
  edited.lights[0].angular_diameter = 0.1f;
  edited.lights[0].intensity = 4.0f;
  const std::string out = hv::applyJsonEdits(
      text, hv::sceneEdits(text, loaded, edited, false, "suns.json"), "suns.json");
  const hv::Scene again = hv::parseScene(json::parse(out), "suns.json");
  EXPECT_EQ(again.lights[0].type, hv::LightType::Directional);
  EXPECT_EQ(again.lights[0].direction, glm::vec3(1, 0, 0));
  EXPECT_FLOAT_EQ(again.lights[0].angular_diameter, 0.1f);
  EXPECT_EQ(again.lights[0].intensity, 4.0f);
  // A light retyped to directional: the whole list is written, without position or range.
  hv::Scene retyped = loaded;
  retyped.lights.push_back(loaded.lights[0]);
  retyped.lights[1].type = hv::LightType::Point;
  const std::string out2 = hv::applyJsonEdits(
      text, hv::sceneEdits(text, loaded, retyped, false, "suns.json"), "suns.json");
  const hv::Scene again2 = hv::parseScene(json::parse(out2), "suns.json");
  ASSERT_EQ(again2.lights.size(), 2u);
  EXPECT_EQ(again2.lights[0].type, hv::LightType::Directional);
  EXPECT_EQ(again2.lights[1].type, hv::LightType::Point);
}
