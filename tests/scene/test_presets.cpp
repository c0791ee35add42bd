// Settings presets ("settings": {"preset": ...}): what each sets, explicit settings override it,
// and a bad name is an error naming the file and the field.
#include <gtest/gtest.h>

#include <string>

#include "halfvec/scene/presets.hpp"
#include "halfvec/scene/scene_loader.hpp"

namespace {

using nlohmann::json;

hv::RenderSettings settingsOf(const std::string& settings_json) {
  return hv::parseScene(json::parse(R"({"settings": )" + settings_json + "}"), "presets.json")
      .settings;
}

std::string errorOf(const std::string& settings_json) {
  try {
    settingsOf(settings_json);
  } catch (const hv::SceneError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(Presets, SetWhatTheyClaim) {
  const hv::RenderSettings fast = settingsOf(R"({"preset": "fast"})");
  EXPECT_EQ(fast.v, hv::VisibilityTerm::SchlickGGX);
  EXPECT_EQ(fast.env_brdf, hv::EnvBrdf::Analytic);
  EXPECT_EQ(fast.irradiance, hv::Irradiance::SH9);
  EXPECT_EQ(fast.sphere_diffuse, hv::SphereDiffuse::KarisPoint);
  EXPECT_EQ(fast.tube_specular, hv::TubeSpecular::ClosestPointEq19);

  const hv::RenderSettings balanced = settingsOf(R"({"preset": "balanced"})");
  EXPECT_EQ(balanced.v, hv::VisibilityTerm::SchlickGGX);
  EXPECT_TRUE(balanced.remap_roughness);
  EXPECT_TRUE(balanced.falloff_plus_one);
  EXPECT_EQ(balanced.env_brdf, hv::EnvBrdf::Table);
  EXPECT_EQ(balanced.irradiance, hv::Irradiance::Cubemap);

  const hv::RenderSettings accurate = settingsOf(R"({"preset": "accurate"})");
  EXPECT_EQ(accurate.v, hv::VisibilityTerm::SchlickGGX);
  EXPECT_TRUE(accurate.remap_roughness);
  EXPECT_FALSE(accurate.falloff_plus_one);
  EXPECT_EQ(accurate.sphere_diffuse, hv::SphereDiffuse::HorizonCorrect);
  EXPECT_TRUE(accurate.sphere_normalization);
  EXPECT_EQ(accurate.sphere_specular, hv::SphereSpecular::Ltc);
  EXPECT_EQ(accurate.tube_specular, hv::TubeSpecular::Ltc);
  EXPECT_EQ(accurate.tube_diffuse, hv::TubeDiffuse::Ltc);
  EXPECT_TRUE(accurate.tube_normalization);
  EXPECT_EQ(accurate.env_brdf, hv::EnvBrdf::Table);
  EXPECT_EQ(accurate.irradiance, hv::Irradiance::Cubemap);

  // Loading a preset = applying it to the defaults; it leaves the other fields alone.
  for (std::string_view name : hv::settingsPresetNames()) {
    hv::RenderSettings expected;
    ASSERT_TRUE(hv::applySettingsPreset(name, expected));
    const hv::RenderSettings got = settingsOf(R"({"preset": ")" + std::string(name) + R"("})");
    EXPECT_EQ(got.v, expected.v) << name;
    EXPECT_EQ(got.env_brdf, expected.env_brdf) << name;
    EXPECT_EQ(got.irradiance, expected.irradiance) << name;
    EXPECT_EQ(got.d, hv::DistributionTerm::GGX) << name;
    EXPECT_EQ(got.width, 960) << name;
    EXPECT_EQ(got.culling, hv::Culling::Auto) << name;
    EXPECT_FALSE(got.energy_compensation) << name;
  }
}

TEST(Presets, ExplicitSettingsOverrideThePreset) {
  const hv::RenderSettings s = settingsOf(
      R"({"env_brdf": "table", "preset": "fast", "brdf": {"v": "smith_ggx_correlated"}})");
  EXPECT_EQ(s.env_brdf, hv::EnvBrdf::Table);               // explicit, although listed first
  EXPECT_EQ(s.v, hv::VisibilityTerm::SmithGGXCorrelated);  // explicit
  EXPECT_EQ(s.irradiance, hv::Irradiance::SH9);            // from the preset
  EXPECT_TRUE(s.remap_roughness);                          // from the preset
}

TEST(Presets, BadNameNamesFileAndField) {
  const std::string typo = errorOf(R"({"preset": "acurate"})");
  EXPECT_NE(typo.find("presets.json"), std::string::npos) << typo;
  EXPECT_NE(typo.find("/settings/preset"), std::string::npos) << typo;
  EXPECT_NE(typo.find("unknown preset \"acurate\""), std::string::npos) << typo;
  EXPECT_NE(typo.find("did you mean \"accurate\""), std::string::npos) << typo;
  EXPECT_NE(typo.find(R"("fast", "balanced" or "accurate")"), std::string::npos) << typo;

  const std::string not_string = errorOf(R"({"preset": 2})");
  EXPECT_NE(not_string.find("/settings/preset"), std::string::npos) << not_string;
  EXPECT_NE(not_string.find("expected a string"), std::string::npos) << not_string;

  hv::RenderSettings untouched;
  untouched.v = hv::VisibilityTerm::Implicit;
  EXPECT_FALSE(hv::applySettingsPreset("ultra", untouched));
  EXPECT_EQ(untouched.v, hv::VisibilityTerm::Implicit);
}
