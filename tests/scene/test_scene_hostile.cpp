// Hostile scene files and overrides (issue 18): values that pass a check in double but break as
// the float they are stored in, a few KB of JSON asking for gigabytes, numbers beyond double range,
// override indices beyond size_t. Each must give a SceneError naming the file and the JSON path.
#include <gtest/gtest.h>

#include <string>

#include "halfvec/scene/scene_loader.hpp"

namespace {

std::string loadError(const std::string& text, const std::vector<std::string>& overrides = {}) {
  try {
    hv::loadSceneFromString(text, "hostile.json", overrides);
  } catch (const hv::SceneError& e) {
    return e.what();
  }
  return "";
}

bool has(const std::string& s, const std::string& what) {
  return s.find(what) != std::string::npos;
}

}  // namespace

TEST(SceneHostile, ValuesAreValidatedAsTheFloatTheyBecome) {
  // The issue's ten cases that rendered with exit 0 and a broken image, and the sphere radius
  // whose error named neither file nor field.
  const struct {
    const char* json;
    const char* path;
  } cases[] = {
      {R"({"camera": {"near": 1e-300}})", "/camera/near"},
      {R"({"camera": {"fov_y_deg": 1e-300}})", "/camera/fov_y_deg"},
      {R"({"camera": {"far": 1e308}})", "/camera/far"},
      {R"({"lights": [{"type": "point", "intensity": 1e308}]})", "/lights/0/intensity"},
      {R"({"lights": [{"type": "point", "color": [1e308, 1, 1]}]})", "/lights/0/color"},
      {R"({"lights": [{"type": "sphere", "radius": 1e308}]})", "/lights/0/radius"},
      {R"({"lights": [{"type": "sphere", "radius": 1e-300}]})", "/lights/0/radius"},
      {R"({"lights": [{"type": "point", "range": 1e-300}]})", "/lights/0/range"},
      {R"({"lights": [{"type": "tube", "length": 1e308}]})", "/lights/0/length"},
      {R"({"lights": [{"type": "point", "position": [1e308, 0, 0]}]})", "/lights/0/position"},
      {R"({"objects": [{"primitive": "sphere", "radius": 1e308}]})", "/objects/0/radius"},
      {R"({"objects": [{"primitive": "plane", "size": [1e-300, 1]}]})", "/objects/0/size"},
      {R"({"objects": [{"primitive": "box", "transform": {"scale": 1e-300}}]})",
       "/objects/0/transform/scale"},
      {R"({"objects": [{"primitive": "box", "transform": {"quaternion": [1e308, 0, 0, 1]}}]})",
       "/objects/0/transform/quaternion"},
      {R"({"settings": {"exposure": 1e-300}})", "/settings/exposure"},
      {R"({"environment": {"intensity": 1e308}})", "/environment/intensity"},
      {R"({"materials": {"m": {"emissive": [1e308, 0, 0]}}})", "/materials/m/emissive"},
      {R"({"light_generators": [{"intensity": [0, 1e308]}]})", "/light_generators/0/intensity"},
      {R"({"objects": [{"primitive": "sphere", "segments": 18446744073709551615}]})",
       "/objects/0/segments"},
  };
  for (const auto& c : cases) {
    const std::string e = loadError(c.json);
    EXPECT_TRUE(has(e, "hostile.json") && has(e, c.path)) << c.json << " -> " << e;
  }
}

TEST(SceneHostile, BudgetsForLightsAndTessellation) {
  // 40 generators of 1,048,576 lights: about 2 KB asking for 40 Mi lights.
  std::string gens;
  for (int i = 0; i < 40; ++i) gens += std::string(i ? "," : "") + R"({"count": 1048576})";
  std::string e = loadError(R"({"light_generators": [)" + gens + "]}");
  EXPECT_TRUE(has(e, "/light_generators/1/count") && has(e, "kMaxSceneLights")) << e;
  // 20 spheres of 4096 x 4096 segments.
  std::string objs;
  for (int i = 0; i < 20; ++i) {
    objs +=
        std::string(i ? "," : "") + R"({"primitive": "sphere", "segments": 4096, "rings": 4096})";
  }
  e = loadError(R"({"objects": [)" + objs + "]}");
  EXPECT_TRUE(has(e, "/objects/0/segments") && has(e, "kMaxPrimitiveVertices")) << e;
  // Within the budget both load.
  EXPECT_EQ(loadError(R"({"light_generators": [{"count": 1048576}]})"), "");
  EXPECT_EQ(loadError(R"({"objects": [{"primitive": "sphere", "segments": 1024, "rings": 512}]})"),
            "");
}

TEST(SceneHostile, ParseErrorsNameFileAndPosition) {
  std::string e = loadError("{\n  \"settings\": {\"exposure\": 1e400}\n}");
  EXPECT_TRUE(has(e, "hostile.json") && has(e, "line 2")) << e;
  e = loadError("{\"camera\": ");
  EXPECT_TRUE(has(e, "hostile.json") && has(e, "invalid JSON")) << e;
  EXPECT_FALSE(has(loadError("{}", {"settings.exposure=1e400"}), "internal error"));
  e = loadError(std::string("{}\0{\"garbage\"", 14));  // nlohmann would stop at the NUL
  EXPECT_TRUE(has(e, "hostile.json") && has(e, "NUL byte at offset 2")) << e;
}

TEST(SceneHostile, OverrideIndicesParsedStrictly) {
  const std::string scene = R"({"lights": [{"type": "point"}]})";
  std::string e = loadError(scene, {"lights.99999999999999999999999.intensity=1"});
  EXPECT_TRUE(has(e, "hostile.json") && has(e, "lights.99999999999999999999999") &&
              has(e, "out of range"))
      << e;
  e = loadError(scene, {"lights.0x1.intensity=1"});
  EXPECT_TRUE(has(e, "not an array index")) << e;
  e = loadError(scene, {"lights.+0.intensity=1"});
  EXPECT_TRUE(has(e, "not an array index")) << e;
  EXPECT_EQ(loadError(scene, {"lights.0.intensity=2", "lights.1={\"type\": \"sphere\"}"}), "");
}
