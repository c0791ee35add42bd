// KHR_lights_punctual import: point, spot and directional lights placed by a rotated, scaled and
// translated node under a turned model, candela and lux to I and E, the range rule, errors naming
// the element, the directional budget, and the order of a scene file's lights (docs/gltf.md,
// "Lights").
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>

#include "halfvec/scene/gltf_loader.hpp"
#include "halfvec/scene/scene_loader.hpp"
#include "scene/gltf_test_files.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

constexpr float kPi = 3.14159265f;

void expectNear(const glm::vec3& a, const glm::vec3& b, float tol) {
  EXPECT_NEAR(a.x, b.x, tol);
  EXPECT_NEAR(a.y, b.y, tol);
  EXPECT_NEAR(a.z, b.z, tol);
}

}  // namespace

namespace {

// The quad of gltf_test_files.hpp (nodes 0 and 1) with KHR_lights_punctual: a point light of
// range 5 on node 2 (translated), a spot without a range on node 3 (rotated, scaled and
// translated), a directional light on node 4.
json litQuad() {
  json j = hv::test::quad();
  j["extensionsUsed"] = {"KHR_lights_punctual"};
  j["extensions"]["KHR_lights_punctual"]["lights"] = {
      {{"type", "point"}, {"color", {1.0, 0.5, 0.25}}, {"intensity", 20.0}, {"range", 5.0}},
      {{"type", "spot"},
       {"intensity", 100.0},
       {"spot", {{"innerConeAngle", 0.2}, {"outerConeAngle", 0.5}}}},
      {{"type", "directional"}, {"intensity", 3.0}}};
  // Node 3: a rotation of 90 degrees about +X (glTF's quaternion order x, y, z, w).
  const float h = std::sqrt(0.5f);
  j["nodes"].push_back({{"translation", {1.0, 2.0, 3.0}},
                        {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
  j["nodes"].push_back({{"translation", {-1.0, 4.0, 0.5}},
                        {"rotation", {h, 0.0, 0.0, h}},
                        {"scale", {2.0, 2.0, 2.0}},
                        {"extensions", {{"KHR_lights_punctual", {{"light", 1}}}}}});
  j["nodes"].push_back({{"extensions", {{"KHR_lights_punctual", {{"light", 2}}}}}});
  j["scenes"][0]["nodes"] = {0, 2, 3, 4};
  return j;
}

std::string writeGltf(const json& j, const std::string& name) {
  const fs::path p = hv::test::tempDir() / name;
  std::ofstream(p) << j.dump();
  return p.string();
}

}  // namespace

TEST(GltfLights, PointSpotAndDirectionalFromTheNodesWorldTransform) {
  hv::Scene scene;
  std::vector<std::string> warnings;
  hv::GltfOptions opt;
  opt.warnings = &warnings;
  // The file's transform (a turn of 90 degrees about +Y) composes with the nodes'.
  const glm::mat4 t = glm::mat4_cast(glm::angleAxis(kPi / 2.0f, glm::vec3(0, 1, 0)));
  hv::loadGltf(writeGltf(litQuad(), "lights.gltf"), t, scene, opt);
  ASSERT_EQ(scene.lights.size(), 3u);
  const hv::Light& p = scene.lights[0];
  EXPECT_EQ(p.type, hv::LightType::Point);
  expectNear(p.position, glm::vec3(t * glm::vec4(1, 2, 3, 1)), 1e-5f);
  expectNear(p.color, {1.0f, 0.5f, 0.25f}, 0.0f);
  EXPECT_EQ(p.intensity, 20.0f);  // candela -> I, one to one (docs/lights.md)
  EXPECT_EQ(p.range, 5.0f);
  const hv::Light& s = scene.lights[1];
  EXPECT_EQ(s.type, hv::LightType::Spot);
  EXPECT_EQ(s.radius, 0.0f);
  expectNear(s.position, glm::vec3(t * glm::vec4(-1, 4, 0.5f, 1)), 1e-5f);
  // Local -Z, turned 90 degrees about +X, is +Y; the file's turn about +Y leaves it; the node's
  // scale of 2 does not lengthen it.
  expectNear(s.direction, {0, 1, 0}, 1e-6f);
  EXPECT_EQ(s.intensity, 100.0f);
  EXPECT_FLOAT_EQ(s.inner_cone_angle, 0.2f);
  EXPECT_FLOAT_EQ(s.outer_cone_angle, 0.5f);
  // No range: where I / d^2 falls to 0.01, sqrt(100 / 0.01) = 100 m.
  EXPECT_FLOAT_EQ(s.range, 100.0f);
  EXPECT_FLOAT_EQ(hv::gltfInfiniteRange({1.0f, 0.5f, 0.25f}, 20.0f), std::sqrt(2000.0f));
  // The directional light: lux -> E one to one, the node's local -Z under the file's turn (-X),
  // a single direction (the extension's lights have no size), no range.
  const hv::Light& d = scene.lights[2];
  EXPECT_EQ(d.type, hv::LightType::Directional);
  EXPECT_EQ(d.intensity, 3.0f);
  expectNear(d.direction, glm::vec3(t * glm::vec4(0, 0, -1, 0)), 1e-6f);
  expectNear(d.direction, {-1, 0, 0}, 1e-6f);
  EXPECT_EQ(d.angular_diameter, 0.0f);
  EXPECT_FALSE(d.shadows);
  EXPECT_TRUE(warnings.empty()) << warnings[0];
}

// More directional light instances than every pixel shades (kMaxDirectionalLights): the first
// ones are imported, one warning names the first left out; with a scene file's own directional
// lights the total is an error naming the objects.
TEST(GltfLights, DirectionalLightsBeyondTheBudgetWarnOrFail) {
  json j = litQuad();
  for (size_t i = 0; i < hv::kMaxDirectionalLights; ++i) {
    j["nodes"].push_back({{"extensions", {{"KHR_lights_punctual", {{"light", 2}}}}}});
    j["scenes"][0]["nodes"].push_back(j["nodes"].size() - 1);
  }
  hv::Scene scene;
  std::vector<std::string> warnings;
  hv::GltfOptions opt;
  opt.warnings = &warnings;
  hv::loadGltf(writeGltf(j, "suns.gltf"), glm::mat4(1.0f), scene, opt);
  size_t directional = 0;
  for (const hv::Light& l : scene.lights) directional += l.type == hv::LightType::Directional;
  EXPECT_EQ(directional, hv::kMaxDirectionalLights);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("kMaxDirectionalLights"), std::string::npos) << warnings[0];
  EXPECT_NE(warnings[0].find("nodes[8]"), std::string::npos) << warnings[0];
  const std::string text = R"({"objects": [{"gltf": ")" + writeGltf(j, "suns2.gltf") + R"("}],
      "lights": [{"type": "directional"}]})";
  try {
    hv::parseScene(json::parse(text), "suns.json", &warnings);
    ADD_FAILURE() << "five directional lights loaded";
  } catch (const hv::SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("suns.json: /objects: 5 directional lights"),
              std::string::npos)
        << e.what();
  }
}

TEST(GltfLights, BadLightsAreErrorsNamingThem) {
  auto error = [](const json& j) {
    hv::Scene scene;
    std::vector<std::string> w;
    hv::GltfOptions opt;
    opt.warnings = &w;
    try {
      hv::loadGltf(writeGltf(j, "bad_lights.gltf"), glm::mat4(1.0f), scene, opt);
    } catch (const hv::SceneError& e) {
      EXPECT_TRUE(scene.lights.empty()) << "half-loaded scene";
      return std::string(e.what());
    }
    return std::string();
  };
  json j = litQuad();
  j["extensions"]["KHR_lights_punctual"]["lights"][1]["spot"]["innerConeAngle"] = 0.6;
  EXPECT_NE(error(j).find("lights[1].spot"), std::string::npos) << error(j);
  j = litQuad();
  j["nodes"][3]["extensions"]["KHR_lights_punctual"]["light"] = 7;
  EXPECT_NE(error(j).find("nodes[3].extensions.KHR_lights_punctual.light"), std::string::npos)
      << error(j);
  j = litQuad();
  j["extensions"]["KHR_lights_punctual"]["lights"][0]["intensity"] = -1.0;
  EXPECT_NE(error(j).find("lights[0].intensity"), std::string::npos) << error(j);
}

TEST(GltfLights, SceneFileKeepsItsOwnLightsFirst) {
  const std::string gltf = writeGltf(litQuad(), "model_lights.gltf");
  const std::string text = R"({"objects": [{"gltf": ")" + gltf + R"("}],
      "lights": [{"type": "sphere", "position": [0, 1, 0]}]})";
  std::vector<std::string> warnings;
  const hv::Scene s = hv::parseScene(json::parse(text), "with_model.json", &warnings);
  ASSERT_EQ(s.lights.size(), 4u);
  EXPECT_EQ(s.lights[0].type, hv::LightType::Sphere);  // /lights/0 stays scene.lights[0]
  EXPECT_EQ(s.lights[1].type, hv::LightType::Point);
  EXPECT_EQ(s.lights[2].type, hv::LightType::Spot);
  EXPECT_EQ(s.lights[3].type, hv::LightType::Directional);
}
