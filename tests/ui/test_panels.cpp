// Panel models without a window: edits reach the GPU through Renderer::updateMaterials, reset
// restores, saveMaterials round-trips through the scene file, the light generator is seeded.
#include <gtest/gtest.h>

#include <cmath>

#include <cstdio>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "render/render_fixture.hpp"
#include "halfvec/scene/enums.hpp"
#include "halfvec/scene/scene_loader.hpp"
#include "halfvec/ui/panels.hpp"

namespace {

using hv::ui::LightGenerator;
using hv::ui::MaterialPanelModel;

glm::vec3 centerBaseColor(const hv::GBufferReadback& g) {
  return g.base_color[size_t(g.height / 2) * size_t(g.width) + size_t(g.width / 2)];
}
float centerRoughness(const hv::GBufferReadback& g) {
  return g.roughness[size_t(g.height / 2) * size_t(g.width) + size_t(g.width / 2)];
}

void expectNear(glm::vec3 a, glm::vec3 b, float tol) {
  EXPECT_NEAR(a.x, b.x, tol);
  EXPECT_NEAR(a.y, b.y, tol);
  EXPECT_NEAR(a.z, b.z, tol);
}

TEST(MaterialPanel, EditReachesGBufferAndResetRestores) {
  testContext();
  hv::Material m;
  m.name = "plane";
  m.base_color = {0.8f, 0.8f, 0.8f};
  m.roughness = 0.3f;
  hv::Scene scene = planeScene(m);
  hv::render::Renderer renderer;
  renderer.setScene(scene);
  renderer.render(64, 64);
  auto g0 = renderer.readGBuffer();
  expectNear(centerBaseColor(g0), m.base_color, 0.02f);
  EXPECT_NEAR(centerRoughness(g0), 0.3f, 0.01f);

  MaterialPanelModel model(scene);
  model.select(0);
  EXPECT_TRUE(model.setBaseColor({0.2f, 0.6f, 0.1f}));
  EXPECT_TRUE(model.setRoughness(0.9f));
  EXPECT_TRUE(model.takeDirty());
  EXPECT_FALSE(model.takeDirty());
  EXPECT_TRUE(model.modified(0));
  renderer.updateMaterials();
  renderer.render(64, 64);
  auto g1 = renderer.readGBuffer();
  expectNear(centerBaseColor(g1), {0.2f, 0.6f, 0.1f}, 0.02f);
  EXPECT_NEAR(centerRoughness(g1), 0.9f, 0.01f);

  EXPECT_TRUE(model.reset());
  EXPECT_FALSE(model.modified(0));
  renderer.updateMaterials();
  renderer.render(64, 64);
  auto g2 = renderer.readGBuffer();
  expectNear(centerBaseColor(g2), m.base_color, 0.02f);
  EXPECT_NEAR(centerRoughness(g2), 0.3f, 0.01f);
}

TEST(MaterialPanel, SettersClampToTheSceneFormatRanges) {
  hv::Scene scene;
  scene.materials.resize(2);
  MaterialPanelModel model(scene);
  model.select(7);
  EXPECT_EQ(model.selected(), 1);
  model.setRoughness(2.0f);
  model.setMetallic(-1.0f);
  model.setCavity(NAN);
  model.setBaseColor({1.5f, -0.5f, 0.5f});
  model.setEmissive({-1.0f, 5.0f, 1e9f});
  EXPECT_EQ(model.current().roughness, 1.0f);
  EXPECT_EQ(model.current().metallic, 0.0f);
  EXPECT_EQ(model.current().cavity, 0.0f);
  EXPECT_EQ(model.current().base_color, glm::vec3(1.0f, 0.0f, 0.5f));
  EXPECT_EQ(model.current().emissive, glm::vec3(0.0f, 5.0f, MaterialPanelModel::kMaxEmissive));
  EXPECT_FALSE(model.setShadingModel(hv::ShadingModel::Background));
  EXPECT_TRUE(model.setShadingModel(hv::ShadingModel::Unlit));
  EXPECT_FALSE(model.setShadingModel(hv::ShadingModel::Unlit));  // no change
  EXPECT_FALSE(model.setAlpha(1.5f));                            // clamped to 1: no change
  EXPECT_TRUE(model.setAlpha(NAN));
  EXPECT_EQ(model.current().base_alpha, 0.0f);
  EXPECT_TRUE(model.setAlphaMode(hv::AlphaMode::Blend));
  EXPECT_FALSE(model.setAlphaMode(hv::AlphaMode::Blend));
  // The coat: an unlit material has none; a weight above 0 makes it clear_coat, 0 default_lit;
  // choosing clear_coat in the menu gives a full coat; values are clamped to [0, 1].
  EXPECT_FALSE(model.setClearCoat(0.5f, 0.1f));  // still unlit
  EXPECT_TRUE(model.setShadingModel(hv::ShadingModel::DefaultLit));
  EXPECT_TRUE(model.setClearCoat(0.5f, 2.0f));
  EXPECT_EQ(model.current().model, hv::ShadingModel::ClearCoat);
  EXPECT_EQ(model.current().clearcoat, 0.5f);
  EXPECT_EQ(model.current().clearcoat_roughness, 1.0f);
  EXPECT_TRUE(model.setClearCoat(0.0f, 0.1f));
  EXPECT_EQ(model.current().model, hv::ShadingModel::DefaultLit);
  EXPECT_TRUE(model.setShadingModel(hv::ShadingModel::ClearCoat));
  EXPECT_EQ(model.current().clearcoat, 1.0f);
  EXPECT_TRUE(model.resetAll());
  EXPECT_EQ(model.current().alpha_mode, hv::AlphaMode::Opaque);
  EXPECT_EQ(model.current().base_alpha, 1.0f);
  EXPECT_EQ(model.current().roughness, 0.5f);
  EXPECT_EQ(model.current().model, hv::ShadingModel::DefaultLit);
  EXPECT_EQ(model.current().clearcoat, 0.0f);
}

TEST(MaterialPanel, SaveMaterialsRoundTrip) {
  const auto dir = std::filesystem::temp_directory_path() / "hv_test_ui_save";
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "scene.json").string();
  {
    std::ofstream(path) << R"({
      "description": "keep me",
      "camera": {"position": [0, 2, 5], "target": [0, 0, 0]},
      "materials": {"red": {"base_color": [0.7, 0.05, 0.05], "roughness": 0.3},
                    "metal": {"base_color": [1, 1, 1], "metallic": 1, "double_sided": true}},
      "objects": [
        {"name": "floor", "primitive": "plane", "size": [4, 4], "material": "red"},
        {"name": "ball", "primitive": "sphere", "radius": 0.5, "material": {"roughness": 0.2}},
        {"primitive": "sphere", "radius": 0.5, "material": "metal"}
      ],
      "lights": [{"type": "point", "position": [0, 2, 0], "intensity": 5, "range": 5}],
      "environment": {"type": "uniform", "color": [0.1, 0.1, 0.1]},
      "settings": {"exposure": 1.5}
    })";
  }
  hv::Scene scene = hv::loadScene(path);
  MaterialPanelModel model(scene);
  auto indexOf = [&](const hv::Scene& s, const std::string& name) {
    for (size_t i = 0; i < s.materials.size(); ++i) {
      if (s.materials[i].name == name) return int(i);
    }
    ADD_FAILURE() << "no material " << name;
    return 0;
  };
  model.select(indexOf(scene, "red"));
  model.setBaseColor({0.1f, 0.2f, 0.3f});
  model.setRoughness(0.75f);
  model.setEmissive({1.0f, 2.0f, 3.0f});
  model.select(indexOf(scene, "ball"));
  model.setMetallic(0.5f);
  model.setShadingModel(hv::ShadingModel::Unlit);
  EXPECT_EQ(model.saveMaterials(path), 2);  // red and ball; metal unchanged

  hv::Scene back = hv::loadScene(path);
  const hv::Material& red = back.materials[size_t(indexOf(back, "red"))];
  expectNear(red.base_color, {0.1f, 0.2f, 0.3f}, 1e-6f);
  EXPECT_FLOAT_EQ(red.roughness, 0.75f);
  expectNear(red.emissive, {1.0f, 2.0f, 3.0f}, 1e-6f);
  const hv::Material& ball = back.materials[size_t(indexOf(back, "ball"))];
  EXPECT_FLOAT_EQ(ball.metallic, 0.5f);
  EXPECT_FLOAT_EQ(ball.roughness, 0.2f);
  EXPECT_EQ(ball.model, hv::ShadingModel::Unlit);
  const hv::Material& metal = back.materials[size_t(indexOf(back, "metal"))];
  EXPECT_TRUE(metal.double_sided);  // fields the panel does not edit survive
  EXPECT_FLOAT_EQ(back.settings.exposure, 1.5f);
  ASSERT_EQ(back.lights.size(), 1u);
  nlohmann::json j = nlohmann::json::parse(std::ifstream(path));
  EXPECT_EQ(j["description"], "keep me");
  EXPECT_EQ(j["objects"][2].count("name"), 0u);
  std::filesystem::remove_all(dir);
}

TEST(LightsPanel, GeneratorCountMixBoxAndDeterminism) {
  LightGenerator g;
  g.count = 500;
  g.seed = 42;
  const auto a = hv::ui::generateLights(g);
  const auto b = hv::ui::generateLights(g);
  ASSERT_EQ(a.size(), 500u);
  ASSERT_EQ(b.size(), 500u);
  int counts[3] = {0, 0, 0};
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].type, b[i].type);
    EXPECT_EQ(a[i].position, b[i].position);
    EXPECT_EQ(a[i].color, b[i].color);
    EXPECT_EQ(a[i].intensity, b[i].intensity);
    EXPECT_TRUE(glm::all(glm::greaterThanEqual(a[i].position, g.box_min)));
    EXPECT_TRUE(glm::all(glm::lessThanEqual(a[i].position, g.box_max)));
    EXPECT_GE(a[i].intensity, g.intensity_min);
    EXPECT_LE(a[i].intensity, g.intensity_max);
    counts[int(a[i].type)]++;
  }
  for (int c : counts) EXPECT_GT(c, 100);  // equal weights: roughly a third each
  g.seed = 43;
  const auto c = hv::ui::generateLights(g);
  EXPECT_NE(a[0].position, c[0].position);

  g.point_weight = g.sphere_weight = 0.0f;
  g.count = 50;
  for (const auto& l : hv::ui::generateLights(g)) {
    EXPECT_EQ(l.type, hv::LightType::Tube);
    EXPECT_NEAR(glm::length(l.axis), 1.0f, 1e-5f);
    EXPECT_EQ(l.length, g.length);
  }
}

TEST(LightsPanel, AddRemoveEditGenerate) {
  hv::Scene scene;
  hv::ui::LightsPanelModel model(scene);
  EXPECT_EQ(model.current(), nullptr);
  EXPECT_EQ(model.add(hv::LightType::Sphere), 0);
  EXPECT_EQ(model.add(hv::LightType::Tube), 1);
  EXPECT_TRUE(model.takeDirty());
  EXPECT_TRUE(model.setIntensity(-3.0f));
  EXPECT_EQ(scene.lights[1].intensity, 0.0f);
  EXPECT_TRUE(model.setAxis({0.0f, 0.0f, 2.0f}));
  EXPECT_EQ(scene.lights[1].axis, glm::vec3(0.0f, 0.0f, 1.0f));
  EXPECT_FALSE(model.setAxis(glm::vec3(0.0f)));
  EXPECT_TRUE(model.setRange(0.0f));
  EXPECT_GT(scene.lights[1].range, 0.0f);
  EXPECT_TRUE(model.remove(0));
  EXPECT_EQ(scene.lights.size(), 1u);
  EXPECT_EQ(scene.lights[0].type, hv::LightType::Tube);
  LightGenerator g;
  g.count = 10;
  model.generate(g, false);
  EXPECT_EQ(scene.lights.size(), 11u);
  model.generate(g, true);
  EXPECT_EQ(scene.lights.size(), 10u);
  model.clear();
  EXPECT_EQ(model.count(), 0u);
}

// The error budget is a slider over the row's range: values outside it are clamped, NaN ignored.
TEST(RenderingPanel, ErrorBudgetSliderClampsToItsRange) {
  hv::Scene scene;
  hv::ui::RenderSettingsModel model(scene);
  ASSERT_EQ(model.floatFields().size(), 1u);
  EXPECT_STREQ(model.floatFields()[0].label, "max error (budget)");
  EXPECT_TRUE(model.setFloat(0, 0.05f));
  EXPECT_EQ(scene.settings.max_error, 0.05f);
  EXPECT_FALSE(model.setFloat(0, 0.05f));  // unchanged
  EXPECT_TRUE(model.setFloat(0, 7.0f));
  EXPECT_EQ(scene.settings.max_error, 1.0f);
  EXPECT_TRUE(model.setFloat(0, -1.0f));
  EXPECT_EQ(scene.settings.max_error, 0.0f);
  EXPECT_FALSE(model.setFloat(0, std::nanf("")));
  EXPECT_FALSE(model.setFloat(1, 0.1f));  // no such field
}

TEST(RenderingPanel, EveryEnumFieldUsesEnumNames) {
  hv::Scene scene;
  hv::ui::RenderSettingsModel model(scene);
  EXPECT_GE(model.enumFields().size(), 11u);
  EXPECT_GE(model.boolFields().size(), 7u);
  for (size_t i = 0; i < model.enumFields().size(); ++i) {
    const auto& f = model.enumFields()[i];
    ASSERT_GE(f.names.size(), 2u) << f.label;
    const int before = f.get(scene.settings);
    const int other = (before + 1) % int(f.names.size());
    EXPECT_TRUE(model.setEnum(i, other)) << f.label;
    EXPECT_EQ(f.get(scene.settings), other);
    EXPECT_FALSE(model.setEnum(i, int(f.names.size())));  // out of range ignored
  }
  EXPECT_EQ(scene.settings.v, hv::VisibilityTerm::SmithGGXCorrelated);
  EXPECT_TRUE(model.takeNeedsSetScene());  // irradiance changed: the bake depends on it
  EXPECT_FALSE(model.takeNeedsSetScene());
  EXPECT_TRUE(model.setBool(0, !scene.settings.remap_roughness));
  EXPECT_FALSE(model.takeNeedsSetScene());
  EXPECT_TRUE(model.setExposure(1000.0f));
  EXPECT_EQ(scene.settings.exposure, 64.0f);
  const auto views = hv::ui::RenderSettingsModel::debugViewNames();
  ASSERT_EQ(views.size(), hv::render::kDebugViewCount);
  EXPECT_STREQ(views[size_t(hv::render::DebugView::DirectSpecular)], "direct_specular");
  EXPECT_STREQ(views[size_t(hv::render::DebugView::Emissive)], "emissive");
  EXPECT_STREQ(views.back(), "predicted_error");
}

}  // namespace

namespace {

TEST(RenderingPanel, EnvironmentChoiceNeedsARebake) {
  hv::Scene scene;
  scene.environment.kind = hv::EnvironmentKind::Sky;
  hv::ui::RenderSettingsModel model(scene);
  EXPECT_FALSE(model.setEnvironmentKind(hv::EnvironmentKind::Sky));
  EXPECT_FALSE(model.takeNeedsSetScene());
  // No HDR file known yet: "hdr" cannot be chosen by kind alone.
  EXPECT_FALSE(model.setEnvironmentKind(hv::EnvironmentKind::HdrFile));
  EXPECT_TRUE(model.setEnvironmentKind(hv::EnvironmentKind::Uniform));
  EXPECT_TRUE(model.takeNeedsSetScene());
  EXPECT_TRUE(model.setEnvironmentColor({0.5f, -1.0f, 2e9f}));
  EXPECT_EQ(scene.environment.color, glm::vec3(0.5f, 0.0f, 1000.0f));
  EXPECT_TRUE(model.takeNeedsSetScene());
  EXPECT_FALSE(model.setEnvironmentHdr("/nonexistent/sky.hdr"));
  EXPECT_EQ(scene.environment.kind, hv::EnvironmentKind::Uniform);
  EXPECT_FALSE(model.takeNeedsSetScene());
  const auto file = std::filesystem::temp_directory_path() / "hv_panel_env.hdr";
  std::ofstream(file) << "not really an HDR";
  EXPECT_TRUE(model.setEnvironmentHdr(file.string()));
  EXPECT_EQ(scene.environment.kind, hv::EnvironmentKind::HdrFile);
  EXPECT_EQ(scene.environment.path, file.string());
  EXPECT_TRUE(model.takeNeedsSetScene());
  EXPECT_TRUE(model.setEnvironmentKind(hv::EnvironmentKind::None));
  EXPECT_TRUE(model.setEnvironmentKind(hv::EnvironmentKind::HdrFile));  // the path is kept
  std::filesystem::remove(file);
}

}  // namespace
