#include "scene/presets.hpp"

#include <array>

namespace hv {

namespace {
constexpr std::array<std::string_view, 3> kNames = {"fast", "balanced", "accurate"};
}  // namespace

std::span<const std::string_view> settingsPresetNames() {
  return kNames;
}

bool applySettingsPreset(std::string_view name, RenderSettings& s) {
  // The rationale of each choice, with the measurements behind it: docs/trade.md ("Presets").
  if (name == "fast") {
    s.v = VisibilityTerm::SchlickGGX;
    s.remap_roughness = true;
    s.falloff_plus_one = true;
    s.sphere_diffuse = SphereDiffuse::KarisPoint;
    s.sphere_normalization = true;
    s.tube_specular = TubeSpecular::ClosestPointEq19;
    s.tube_normalization = true;
    s.env_brdf = EnvBrdf::Analytic;
    s.irradiance = Irradiance::SH9;
  } else if (name == "balanced") {
    s.v = VisibilityTerm::SchlickGGX;
    s.remap_roughness = true;
    s.falloff_plus_one = true;
    s.sphere_diffuse = SphereDiffuse::KarisPoint;
    s.sphere_normalization = true;
    s.tube_specular = TubeSpecular::ClosestPointEq19;
    s.tube_normalization = true;
    s.env_brdf = EnvBrdf::Table;
    s.irradiance = Irradiance::Cubemap;
  } else if (name == "accurate") {
    s.v = VisibilityTerm::SchlickGGX;
    s.remap_roughness = true;
    s.falloff_plus_one = false;
    s.sphere_diffuse = SphereDiffuse::HorizonCorrect;
    s.sphere_normalization = true;
    s.tube_specular = TubeSpecular::ClosestPointEq19;
    s.tube_normalization = true;
    s.env_brdf = EnvBrdf::Table;
    s.irradiance = Irradiance::Cubemap;
  } else {
    return false;
  }
  return true;
}

}  // namespace hv
