// The trade report's plan: which configurations to run for a scene (one row per other value of
// each approximation option of the settings table, the presets, the exact configuration), the
// truth settings the reference uses, and the Pareto front over the measured rows.
#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <string>
#include <type_traits>

#include "halfvec/eval/trade.hpp"
#include "halfvec/ibl/sky_sun.hpp"
#include "halfvec/scene/enums.hpp"
#include "halfvec/scene/presets.hpp"

namespace hv::eval {

namespace {

std::string str(std::string_view s) {
  return std::string(s);
}

// ---- settings as names ------------------------------------------------------------------------
template <class E>
void enumRows(std::vector<TradeConfig>& out, const char* key, const RenderSettings& base, int pf,
              E RenderSettings::*field, const char* group) {
  for (size_t i = 0; i < enumNames<E>().size(); ++i) {
    const auto v = static_cast<E>(i);
    if (v == base.*field) continue;
    TradeConfig c{std::string(key) + "=" + str(toString(v)), group, base, pf, {}};
    c.settings.*field = v;
    out.push_back(c);
  }
}

void boolRow(std::vector<TradeConfig>& out, const char* key, const RenderSettings& base, int pf,
             bool RenderSettings::*field, const char* group) {
  TradeConfig c{std::string(key) + "=" + (base.*field ? "false" : "true"), group, base, pf, {}};
  c.settings.*field = !(base.*field);
  out.push_back(c);
}

// An integer (settings.shadow_map_size): half and twice the scene's value, within its range.
void intRows(std::vector<TradeConfig>& out, const char* key, const RenderSettings& base, int pf,
             int RenderSettings::*field, const SettingInfo& info, const char* group) {
  for (const int v : {base.*field / 2, base.*field * 2}) {
    if (v == base.*field || double(v) < info.lo || double(v) > info.hi) continue;
    TradeConfig c{std::string(key) + "=" + std::to_string(v), group, base, pf, {}};
    c.settings.*field = v;
    out.push_back(c);
  }
}

// A float (settings.max_error): the row's trade values other than the scene's.
void floatRows(std::vector<TradeConfig>& out, const char* key, const RenderSettings& base, int pf,
               float RenderSettings::*field, const SettingInfo& info, const char* group) {
  for (const double v : info.trade_values) {
    if (v == 0.0 || float(v) == base.*field) continue;
    std::ostringstream name;
    name << key << "=" << v;
    TradeConfig c{name.str(), group, base, pf, {}};
    c.settings.*field = float(v);
    out.push_back(c);
  }
}

}  // namespace

RenderSettings truthSettings(const RenderSettings& s) {
  RenderSettings t = s;
  if (s.d == DistributionTerm::GGX) t.v = VisibilityTerm::SmithGGXCorrelated;  // Heitz 2014 eq. 99
  if (s.d == DistributionTerm::Beckmann) t.v = VisibilityTerm::SmithBeckmannSeparable;
  if (s.f == FresnelTerm::SchlickSG)
    t.f = FresnelTerm::SchlickPow5;  // SG fits Schlick (Karis eq. 5)
  t.remap_roughness = false;
  t.falloff_plus_one = false;
  return t;
}

namespace {

// Each feature of the scene that makes settings change code, with why its settings are not
// varied where the scene lacks it (null where it has it).
using Absences = std::array<std::pair<SettingFeature, const char*>, 7>;

Absences absentFeatures(const Scene& scene) {
  bool sphere = false, tube = false, shadowed = false;
  for (const Light& l : scene.lights) {
    // A sphere spot runs the sphere code, and so does a directional light (a sphere at infinity).
    sphere |= lightShape(l) == LightType::Sphere || l.type == LightType::Directional;
    tube |= l.type == LightType::Tube;
    shadowed |= l.shadows;
  }
  const bool lights = !scene.lights.empty();
  const bool env = scene.environment.kind != EnvironmentKind::None;
  const char* uniform = scene.environment.kind == EnvironmentKind::Uniform ? "uniform environment"
                        : env                                              ? nullptr
                                                                           : "no environment";
  return {{{SettingFeature::Lights, lights ? nullptr : "no lights"},
           {SettingFeature::SphereLights, sphere ? nullptr : "no sphere or directional lights"},
           {SettingFeature::TubeLights, tube ? nullptr : "no tube lights"},
           {SettingFeature::AmbientIbl, env ? nullptr : "no environment"},
           {SettingFeature::ShadowedLights, shadowed ? nullptr : "no shadowed lights"},
           {SettingFeature::EnvironmentSun,
            environmentHasSun(scene.environment) ? nullptr : "no sun in the environment"},
           {SettingFeature::VaryingAmbient, uniform}}};
}

// One row per other value of each approximation option of the settings table
// (render_settings.hpp), where the scene has what makes it change code; the options left out,
// one line per missing feature.
void optionRows(const Scene& scene, int max_brute_force_lights, std::vector<TradeConfig>& c,
                std::vector<std::string>& skipped) {
  const RenderSettings& b = scene.settings;
  const int pf = scene.environment.prefilter_samples;
  const Absences absent = absentFeatures(scene);
  std::vector<std::string> skipped_keys(std::size(absent));
  forEachSetting([&](const auto& row) {
    using T = typename std::decay_t<decltype(row)>::Type;
    if (!row.info.trade) return;
    for (size_t i = 0; i < std::size(absent); ++i) {
      if (absent[i].first != row.info.feature || !absent[i].second) continue;
      skipped_keys[i] += (skipped_keys[i].empty() ? "" : ", ") + std::string(row.key);
      return;
    }
    if constexpr (std::is_same_v<T, Culling>) {
      if (b.culling != Culling::BruteForce && int(scene.lights.size()) > max_brute_force_lights) {
        skipped.push_back("culling=brute_force: " + std::to_string(scene.lights.size()) +
                          " lights (more than " + std::to_string(max_brute_force_lights) +
                          "; brute force shades every light at every pixel)");
        return;
      }
    }
    if constexpr (std::is_same_v<T, bool>) {
      boolRow(c, row.key, b, pf, row.member, row.info.trade_group);
    } else if constexpr (std::is_same_v<T, int>) {
      intRows(c, row.key, b, pf, row.member, row.info, row.info.trade_group);
    } else if constexpr (std::is_same_v<T, float>) {
      floatRows(c, row.key, b, pf, row.member, row.info, row.info.trade_group);
    } else if constexpr (std::is_enum_v<T>) {
      enumRows(c, row.key, b, pf, row.member, row.info.trade_group);
    }
  });
  for (size_t i = 0; i < std::size(absent); ++i) {
    if (!skipped_keys[i].empty()) skipped.push_back(skipped_keys[i] + ": " + absent[i].second);
  }
}

// A quarter and four times the scene's prefilter sample count, where the count changes the bake.
void prefilterRows(const Scene& scene, std::vector<TradeConfig>& c,
                   std::vector<std::string>& skipped) {
  const int pf = scene.environment.prefilter_samples;
  if (scene.environment.kind == EnvironmentKind::None) {
    skipped.push_back("environment.prefilter_samples: no environment");
  } else if (scene.environment.kind == EnvironmentKind::Uniform) {
    skipped.push_back(
        "environment.prefilter_samples: a uniform environment prefilters exactly with any count");
  } else {
    for (int p : {std::max(pf / 4, 1), std::min(pf * 4, 65536)}) {
      if (p == pf) continue;
      c.push_back({"environment.prefilter_samples=" + std::to_string(p),
                   "environment",
                   scene.settings,
                   p,
                   {}});
    }
  }
}

// The exact configuration: the reference's BRDF and the most accurate methods of the engine.
TradeConfig exactConfig(const RenderSettings& b, int pf) {
  TradeConfig exact{"exact", "exact", truthSettings(b), pf, {}};
  exact.settings.sphere_diffuse = SphereDiffuse::HorizonCorrect;
  exact.settings.sphere_normalization = true;
  exact.settings.sphere_specular = SphereSpecular::Ltc;  // docs/accuracy.md: the closest methods
  exact.settings.tube_specular = TubeSpecular::Ltc;
  exact.settings.tube_normalization = true;
  exact.settings.tube_diffuse = TubeDiffuse::Ltc;
  exact.settings.env_brdf = EnvBrdf::Table;
  exact.settings.irradiance = Irradiance::Cubemap;
  return exact;
}

// Configurations that render alike (same settings and prefilter samples) are one row: the first
// one's, with the others' names as its aliases.
std::vector<TradeConfig> mergeAlike(const std::vector<TradeConfig>& c) {
  std::vector<TradeConfig> configs;
  for (const TradeConfig& t : c) {
    auto same = std::find_if(configs.begin(), configs.end(), [&](const TradeConfig& o) {
      return o.prefilter_samples == t.prefilter_samples && o.settings == t.settings;
    });
    if (same != configs.end()) {
      same->aliases.push_back(t.name);
    } else {
      configs.push_back(t);
    }
  }
  return configs;
}

}  // namespace

TradePlan tradePlan(const Scene& scene, int max_brute_force_lights) {
  TradePlan plan;
  const RenderSettings& b = scene.settings;
  const int pf = scene.environment.prefilter_samples;
  std::vector<TradeConfig> c;
  c.push_back({"scene", "scene", b, pf, {}});
  optionRows(scene, max_brute_force_lights, c, plan.skipped);
  prefilterRows(scene, c, plan.skipped);
  for (std::string_view p : settingsPresetNames()) {
    TradeConfig t{"preset=" + str(p), "preset", b, pf, {}};
    applySettingsPreset(p, t.settings);
    c.push_back(t);
  }
  c.push_back(exactConfig(b, pf));
  plan.configs = mergeAlike(c);
  return plan;
}

void markPareto(std::vector<TradeRow>& rows) {
  for (TradeRow& r : rows) {
    const double t = r.total_ms, e = headlineError(r);
    r.pareto = std::isfinite(e) && r.nonfinite == 0;
    for (const TradeRow& o : rows) {
      if (&o == &r || !std::isfinite(headlineError(o)) || o.nonfinite) continue;
      const double ot = o.total_ms, oe = headlineError(o);
      if (ot <= t && oe <= e && (ot < t || oe < e)) {
        r.pareto = false;
        break;
      }
    }
  }
}

void pickConfigurations(TradeReport& r) {
  r.cheapest_within_error = r.most_accurate_within_ms = -1;
  for (size_t i = 0; i < r.rows.size(); ++i) {
    const TradeRow& row = r.rows[i];
    if (row.nonfinite || !std::isfinite(headlineError(row))) continue;
    if (headlineError(row) <= r.max_error &&
        (r.cheapest_within_error < 0 ||
         row.total_ms < r.rows[size_t(r.cheapest_within_error)].total_ms)) {
      r.cheapest_within_error = int(i);
    }
    if (row.total_ms <= r.max_ms &&
        (r.most_accurate_within_ms < 0 ||
         headlineError(row) < headlineError(r.rows[size_t(r.most_accurate_within_ms)]))) {
      r.most_accurate_within_ms = int(i);
    }
  }
}

std::vector<std::string> costPasses(const std::string& group) {
  if (group == "brdf" || group == "lights") return {"light"};
  if (group == "culling") return {"light_cull", "light"};
  if (group == "environment") return {"ambient"};
  return {};
}

}  // namespace hv::eval
