#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "halfvec/scene/enums.hpp"
#include "halfvec/scene/scene_loader.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

const fs::path kSamples = fs::path(HV_SOURCE_DIR) / "samples" / "scenes";

// The message of the SceneError `f` throws ("" if none).
template <class F>
std::string errorOf(F&& f) {
  try {
    f();
  } catch (const hv::SceneError& e) {
    return e.what();
  }
  return "";
}

std::string parseError(const std::string& text) {
  return errorOf([&] { hv::parseScene(json::parse(text), "scene.json"); });
}

}  // namespace

TEST(Enums, RoundTrip) {
  for (auto name : hv::enumNames<hv::VisibilityTerm>()) {
    auto v = hv::fromString<hv::VisibilityTerm>(name);
    ASSERT_TRUE(v.has_value());
    EXPECT_EQ(hv::toString(*v), name);
  }
  EXPECT_EQ(hv::toString(hv::ShadingModel::DefaultLit), "default_lit");
  EXPECT_EQ(hv::toString(hv::EnvironmentKind::HdrFile), "hdr");
  EXPECT_FALSE(hv::fromString<hv::ToneMap>("filmic").has_value());
  EXPECT_EQ(hv::enumNamesJoined<hv::Gamma>(), "\"gamma22\" or \"srgb\"");
}

TEST(SceneLoader, EverySampleLoads) {
  int n = 0;
  for (const auto& entry : fs::directory_iterator(kSamples)) {
    if (entry.path().extension() != ".json") continue;
    SCOPED_TRACE(entry.path().string());
    std::vector<std::string> warnings;
    hv::Scene s;
    ASSERT_NO_THROW(s = hv::loadScene(entry.path().string(), {}, &warnings));
    EXPECT_FALSE(s.objects.empty());
    EXPECT_FALSE(s.lights.empty());
    for (const hv::Mesh& m : s.meshes) {
      EXPECT_GE(m.material, 0);
      EXPECT_LT(m.material, int(s.materials.size()));
    }
    for (const hv::Object& o : s.objects)
      for (int m : o.meshes) EXPECT_LT(m, int(s.meshes.size()));
    ++n;
  }
  EXPECT_EQ(n, 12);  // every file in samples/scenes
}

TEST(SceneLoader, DefaultSceneContents) {
  const hv::Scene s = hv::loadScene((kSamples / "default.json").string());
  int counts[3] = {};
  for (const hv::Light& l : s.lights) ++counts[int(l.type)];
  EXPECT_EQ(counts[0], 1);
  EXPECT_EQ(counts[1], 1);
  EXPECT_EQ(counts[2], 1);
  EXPECT_EQ(s.environment.kind, hv::EnvironmentKind::Sky);
  EXPECT_EQ(s.objects.size(), 12u);
}

TEST(SceneLoader, ManyLightsIsDeterministicAndLarge) {
  const std::string p = (kSamples / "many_lights.json").string();
  const hv::Scene a = hv::loadScene(p), b = hv::loadScene(p);
  ASSERT_GE(a.lights.size(), 1024u);
  ASSERT_EQ(a.lights.size(), b.lights.size());
  int counts[3] = {};
  for (size_t i = 0; i < a.lights.size(); ++i) {
    EXPECT_EQ(a.lights[i].position, b.lights[i].position);
    EXPECT_EQ(a.lights[i].color, b.lights[i].color);
    ++counts[int(a.lights[i].type)];
    EXPECT_NEAR(glm::length(a.lights[i].axis), 1.0f, 1e-5f);
  }
  EXPECT_GT(counts[0], 0);
  EXPECT_GT(counts[1], 0);
  EXPECT_GT(counts[2], 0);
}

TEST(SceneLoader, GltfSampleFallsBackWhenAssetMissing) {
  std::vector<std::string> warnings;
  const hv::Scene s = hv::loadScene((kSamples / "gltf.json").string(),
                                    {"objects.0.gltf=/nonexistent/helmet.glb"}, &warnings);
  ASSERT_EQ(s.objects.size(), 1u);
  EXPECT_EQ(s.objects[0].name, "helmet");
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("fallback"), std::string::npos);
}

TEST(SceneLoader, Overrides) {
  const hv::Scene s =
      hv::loadScene((kSamples / "default.json").string(),
                    {"settings.width=640", "lights.0.intensity=5", "camera.position=[0,1,4]",
                     "settings.tone_map=none", "settings.brdf.v=smith_ggx_correlated",
                     "environment.type=uniform"});
  EXPECT_EQ(s.settings.width, 640);
  EXPECT_FLOAT_EQ(s.lights[0].intensity, 5.0f);
  EXPECT_EQ(s.camera.position, glm::vec3(0, 1, 4));
  EXPECT_EQ(s.settings.tone_map, hv::ToneMap::None);
  EXPECT_EQ(s.settings.v, hv::VisibilityTerm::SmithGGXCorrelated);
  EXPECT_EQ(s.environment.kind, hv::EnvironmentKind::Uniform);
  const std::string e =
      errorOf([] { hv::loadScene((kSamples / "default.json").string(), {"settings.widht=640"}); });
  EXPECT_NE(e.find("/settings/widht"), std::string::npos) << e;
  EXPECT_NE(e.find("did you mean \"width\""), std::string::npos) << e;
  EXPECT_NE(errorOf([] {
              hv::loadScene((kSamples / "default.json").string(), {"lights.9.x=1"});
            }).find("out of range"),
            std::string::npos);
}

TEST(SceneLoader, ErrorsNameFilePathAndExpectation) {
  EXPECT_EQ(parseError(R"({"objects":[{"primitive":"plane"},{"primitive":"plane"},
      {"primitive":"sphere","material":{"roughness":1.5}}]})"),
            "scene.json: /objects/2/material/roughness: expected a number in [0, 1], got 1.5");
  EXPECT_NE(parseError(R"({"setings":{}})").find("did you mean \"settings\""), std::string::npos);
  EXPECT_NE(
      parseError(R"({"settings":{"width":"wide"}})").find("/settings/width: expected an integer"),
      std::string::npos);
  EXPECT_NE(parseError(R"({"settings":{"tone_map":"reinhart"}})").find("did you mean \"reinhard\""),
            std::string::npos);
  EXPECT_NE(parseError(R"({"objects":[{"primitive":"cone"}]})").find("/objects/0/primitive"),
            std::string::npos);
  EXPECT_NE(parseError(R"({"objects":[{"primitive":"sphere","material":"nope"}]})")
                .find("no material named \"nope\""),
            std::string::npos);
  EXPECT_NE(
      parseError(R"({"objects":[{"primitive":"sphere","size":3}]})").find("unknown key \"size\""),
      std::string::npos);
  EXPECT_NE(parseError(R"({"lights":[{"type":"point","radius":1}]})").find("/lights/0/radius"),
            std::string::npos);
  EXPECT_NE(parseError(R"({"lights":[{"type":"tube","axis":[0,0,0]}]})").find("/lights/0/axis"),
            std::string::npos);
  EXPECT_NE(parseError(R"({"camera":{"near":1,"far":0.5}})").find("/camera/far"),
            std::string::npos);
  EXPECT_NE(
      parseError(R"({"environment":{"type":"hdr","path":"missing.hdr"}})").find("file not found"),
      std::string::npos);
  EXPECT_NE(
      parseError(R"({"objects":[{"gltf":"missing.glb"}]})").find("/objects/0/gltf: file not found"),
      std::string::npos);
  EXPECT_NE(parseError(R"({"environment":{"cube_size":100}})").find("power of two"),
            std::string::npos);
  EXPECT_NE(parseError(R"({"light_generators":[{"count":0}]})").find("/light_generators/0/count"),
            std::string::npos);
  EXPECT_NE(errorOf([] { hv::loadScene("/nonexistent/scene.json"); }).find("cannot open"),
            std::string::npos);
}

TEST(SceneLoader, MaterialsAsListAndInline) {
  const hv::Scene s = hv::parseScene(json::parse(R"({
    "materials":[{"name":"a","metallic":1},{"name":"b","shading_model":"unlit"}],
    "objects":[{"primitive":"box","material":"b"},{"primitive":"sphere","material":{"roughness":0.2}},
               {"primitive":"capsule"}]})"),
                                     "x.json");
  ASSERT_EQ(s.meshes.size(), 3u);
  EXPECT_EQ(s.materials[size_t(s.meshes[0].material)].model, hv::ShadingModel::Unlit);
  EXPECT_FLOAT_EQ(s.materials[size_t(s.meshes[1].material)].roughness, 0.2f);
  EXPECT_EQ(s.materials[size_t(s.meshes[2].material)].name, "default");
  EXPECT_NE(parseError(R"({"materials":[{"name":"a"},{"name":"a"}]})").find("duplicate"),
            std::string::npos);
}

TEST(SceneLoader, MaterialAlphaKeys) {
  const hv::Scene s = hv::parseScene(json::parse(R"({
    "materials":[{"name":"glass","alpha":0.3,"alpha_mode":"blend"},
                 {"name":"leaf","alpha_mode":"mask","alpha_cutoff":0.25}],
    "objects":[{"primitive":"box","material":"glass"},{"primitive":"plane","material":"leaf"},
               {"primitive":"sphere"}]})"),
                                     "x.json");
  const hv::Material& glass = s.materials[size_t(s.meshes[0].material)];
  EXPECT_EQ(glass.alpha_mode, hv::AlphaMode::Blend);
  EXPECT_FLOAT_EQ(glass.base_alpha, 0.3f);
  const hv::Material& leaf = s.materials[size_t(s.meshes[1].material)];
  EXPECT_EQ(leaf.alpha_mode, hv::AlphaMode::Mask);
  EXPECT_FLOAT_EQ(leaf.alpha_cutoff, 0.25f);
  EXPECT_FLOAT_EQ(leaf.base_alpha, 1.0f);
  EXPECT_EQ(s.materials[size_t(s.meshes[2].material)].alpha_mode, hv::AlphaMode::Opaque);
  EXPECT_EQ(parseError(R"({"materials":[{"name":"a","alpha":1.5}]})"),
            "scene.json: /materials/0/alpha: expected a number in [0, 1], got 1.5");
  EXPECT_NE(parseError(R"({"materials":[{"name":"a","alpha_mode":"blending"}]})")
                .find("/materials/0/alpha_mode"),
            std::string::npos);
}

// clearcoat makes the material clear_coat; clear_coat alone is a full coat; a coat on an unlit
// material, clear_coat with a weight of 0 and weights outside [0, 1] are errors naming the key.
TEST(SceneLoader, MaterialClearCoatKeys) {
  const hv::Scene s = hv::parseScene(json::parse(R"({
    "materials":[{"name":"paint","clearcoat":0.8,"clearcoat_roughness":0.05},
                 {"name":"varnish","shading_model":"clear_coat"},
                 {"name":"plain","clearcoat":0}],
    "objects":[{"primitive":"box","material":"paint"},{"primitive":"plane","material":"varnish"},
               {"primitive":"sphere","material":"plain"}]})"),
                                     "x.json");
  const hv::Material& paint = s.materials[size_t(s.meshes[0].material)];
  EXPECT_EQ(paint.model, hv::ShadingModel::ClearCoat);
  EXPECT_FLOAT_EQ(paint.clearcoat, 0.8f);
  EXPECT_FLOAT_EQ(paint.clearcoat_roughness, 0.05f);
  const hv::Material& varnish = s.materials[size_t(s.meshes[1].material)];
  EXPECT_EQ(varnish.model, hv::ShadingModel::ClearCoat);
  EXPECT_FLOAT_EQ(varnish.clearcoat, 1.0f);
  EXPECT_EQ(s.materials[size_t(s.meshes[2].material)].model, hv::ShadingModel::DefaultLit);
  EXPECT_EQ(parseError(R"({"materials":[{"name":"a","clearcoat":1.5}]})"),
            "scene.json: /materials/0/clearcoat: expected a number in [0, 1], got 1.5");
  EXPECT_EQ(parseError(R"({"materials":[{"name":"a","clearcoat_roughness":-0.1}]})"),
            "scene.json: /materials/0/clearcoat_roughness: expected a number in [0, 1], got -0.1");
  EXPECT_NE(parseError(R"({"materials":[{"name":"a","shading_model":"unlit","clearcoat":1}]})")
                .find("/materials/0/clearcoat: an unlit material has no clear coat"),
            std::string::npos);
  EXPECT_NE(parseError(R"({"materials":[{"name":"a","shading_model":"clear_coat","clearcoat":0}]})")
                .find("/materials/0/clearcoat: shading_model \"clear_coat\" needs clearcoat > 0"),
            std::string::npos);
}

TEST(SceneLoader, TransformsAndEnvExpansion) {
  const hv::Scene s = hv::parseScene(
      json::parse(R"({"objects":[{"primitive":"box","transform":{"translation":[1,2,3],
        "rotation_deg":[0,90,0],"scale":2}}]})"),
      "x.json");
  const glm::vec4 p = s.objects[0].transform * glm::vec4(1, 0, 0, 1);
  EXPECT_NEAR(p.x, 1.0f, 1e-5f);
  EXPECT_NEAR(p.y, 2.0f, 1e-5f);
  EXPECT_NEAR(p.z, 1.0f, 1e-5f);  // +X rotated 90 deg about +Y is -Z
  EXPECT_NE(parseError(R"({"objects":[{"primitive":"box","transform":{"rotation_deg":[0,0,0],
      "quaternion":[0,0,0,1]}}]})")
                .find("not both"),
            std::string::npos);
  ::setenv("HV_TEST_VAR", "abc", 1);
  EXPECT_EQ(hv::expandEnvVars("x/${HV_TEST_VAR}/y"), "x/abc/y");
  EXPECT_THROW(hv::expandEnvVars("${HV_SURELY_UNSET_VAR_42}"), hv::SceneError);
}
