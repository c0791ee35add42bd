// Spot lights in scene files: fields, KHR_lights_punctual's defaults, validation errors naming the
// file and the field, saved edits (docs/scene-format.md, "lights").
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "halfvec/scene/scene_loader.hpp"
#include "halfvec/scene/scene_writer.hpp"

using nlohmann::json;

namespace {

constexpr float kPi = 3.14159265f;

std::string sceneWithLight(const std::string& light) {
  return R"({"lights": [)" + light + "]}";
}

std::string parseError(const std::string& text) {
  try {
    hv::parseScene(json::parse(text), "spots.json");
  } catch (const hv::SceneError& e) {
    return e.what();
  }
  return "";
}

void expectNear(const glm::vec3& a, const glm::vec3& b, float tol) {
  EXPECT_NEAR(a.x, b.x, tol);
  EXPECT_NEAR(a.y, b.y, tol);
  EXPECT_NEAR(a.z, b.z, tol);
}

}  // namespace

TEST(SpotLights, SceneFileFieldsAndGltfDefaults) {
  const hv::Scene s = hv::parseScene(
      json::parse(sceneWithLight(
          R"({"type": "spot", "position": [0, 2, 0], "direction": [0, -2, 0], "range": 5},
             {"type": "spot", "radius": 0.1, "direction": [1, 0, 0], "inner_cone_angle": 0.2,
              "outer_cone_angle": 0.5})")),
      "spots.json");
  ASSERT_EQ(s.lights.size(), 2u);
  const hv::Light& a = s.lights[0];
  EXPECT_EQ(a.type, hv::LightType::Spot);
  EXPECT_EQ(a.radius, 0.0f);  // a point spot unless a radius is given
  EXPECT_EQ(hv::lightShape(a), hv::LightType::Point);
  expectNear(a.direction, {0, -1, 0}, 1e-7f);  // normalized
  EXPECT_EQ(a.inner_cone_angle, 0.0f);         // KHR_lights_punctual's defaults
  EXPECT_FLOAT_EQ(a.outer_cone_angle, kPi / 4.0f);
  const hv::Light& b = s.lights[1];
  EXPECT_EQ(hv::lightShape(b), hv::LightType::Sphere);
  EXPECT_FLOAT_EQ(b.inner_cone_angle, 0.2f);
  EXPECT_FLOAT_EQ(b.outer_cone_angle, 0.5f);
}

TEST(SpotLights, InvalidConesAreErrorsNamingFileAndField) {
  struct Case {
    const char* light;
    const char* field;
  } cases[] = {
      {R"({"type": "spot", "inner_cone_angle": 0.5, "outer_cone_angle": 0.5})",
       "spots.json: /lights/0/outer_cone_angle: expected 0 <= inner_cone_angle < "
       "outer_cone_angle"},
      {R"({"type": "spot", "inner_cone_angle": 0.9})",  // above the default outer pi/4
       "spots.json: /lights/0/inner_cone_angle: expected 0 <= inner_cone_angle"},
      {R"({"type": "spot", "outer_cone_angle": 1.6})", "spots.json: /lights/0/outer_cone_angle"},
      {R"({"type": "spot", "outer_cone_angle": 0})", "spots.json: /lights/0/outer_cone_angle"},
      {R"({"type": "spot", "inner_cone_angle": -0.1})", "spots.json: /lights/0/inner_cone_angle"},
      {R"({"type": "spot", "direction": [0, 0, 0]})", "spots.json: /lights/0/direction"},
      {R"({"type": "point", "direction": [0, -1, 0]})", "spots.json: /lights/0/direction"},
  };
  for (const Case& c : cases) {
    const std::string e = parseError(sceneWithLight(c.light));
    EXPECT_NE(e.find(c.field), std::string::npos) << c.light << " -> " << e;
  }
  // pi/2 itself is allowed (a hemisphere).
  EXPECT_EQ(parseError(sceneWithLight(R"({"type": "spot", "outer_cone_angle": 1.5707963})")), "");
}

TEST(SpotLights, SavedEditsWriteTheCone) {
  const std::string text = sceneWithLight(R"({"type": "spot", "outer_cone_angle": 0.5})");
  const hv::Scene loaded = hv::parseScene(json::parse(text), "spots.json");
  hv::Scene edited = loaded;
  edited.lights[0].inner_cone_angle = 0.25f;
  edited.lights[0].direction = {1, 0, 0};
  const std::string out = hv::applyJsonEdits(
      text, hv::sceneEdits(text, loaded, edited, false, "spots.json"), "spots.json");
  const hv::Scene again = hv::parseScene(json::parse(out), "spots.json");
  EXPECT_FLOAT_EQ(again.lights[0].inner_cone_angle, 0.25f);
  EXPECT_FLOAT_EQ(again.lights[0].outer_cone_angle, 0.5f);
  expectNear(again.lights[0].direction, {1, 0, 0}, 1e-7f);
}
