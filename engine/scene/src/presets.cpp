#include "halfvec/scene/presets.hpp"

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
  // Every preset starts from Karis 2013's choices for the approximations it governs.
  auto karis = [&s] {
    s.v = VisibilityTerm::SchlickGGX;
    s.remap_roughness = true;
    s.falloff_plus_one = true;
    s.sphere_diffuse = SphereDiffuse::KarisPoint;
    s.sphere_normalization = true;
    s.sphere_specular = SphereSpecular::RepresentativePoint;
    s.tube_specular = TubeSpecular::ClosestPointEq19;
    s.tube_normalization = true;
    s.tube_diffuse = TubeDiffuse::KarisEq16;
    s.env_brdf = EnvBrdf::Table;
    s.irradiance = Irradiance::SH9;
  };
  if (name == "fast") {
    karis();
    s.env_brdf = EnvBrdf::Analytic;
  } else if (name == "balanced") {
    karis();
    s.irradiance = Irradiance::Cubemap;
  } else if (name == "accurate") {
    karis();
    s.irradiance = Irradiance::Cubemap;
    s.falloff_plus_one = false;
    s.sphere_diffuse = SphereDiffuse::HorizonCorrect;
    // docs/accuracy.md: median / worst error over the sweeps, ltc vs the representative point:
    // sphere specular 2.2% / 17% vs 32% / 1676% (with this preset's Schlick-GGX V), tube specular
    // 3.6% / 16% vs 41% / 96%, tube diffuse 1.9% / 4.2% vs 8.6% / 20%.
    s.sphere_specular = SphereSpecular::Ltc;
    s.tube_specular = TubeSpecular::Ltc;
    s.tube_diffuse = TubeDiffuse::Ltc;
  } else {
    return false;
  }
  return true;
}

}  // namespace hv
