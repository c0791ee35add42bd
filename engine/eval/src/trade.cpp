#include "halfvec/eval/trade.hpp"

#include "halfvec/core/output_files.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <sstream>
#include <type_traits>

#include <nlohmann/json.hpp>

#include "halfvec/eval/bench.hpp"
#include "halfvec/ibl/ibl.hpp"
#include "halfvec/image/plot.hpp"
#include "halfvec/render/renderer.hpp"
#include "halfvec/scene/enums.hpp"
#include "halfvec/scene/presets.hpp"

namespace hv::eval {

namespace fs = std::filesystem;

namespace {

// Bump whenever engine/reference changes what it computes for the same inputs.
constexpr const char* kReferenceCacheVersion = "trade-reference-v4";

std::string str(std::string_view s) {
  return std::string(s);
}

// ---- FNV-1a over the inputs of the reference --------------------------------------------------
struct Hasher {
  uint64_t h = 1469598103934665603ull;
  void bytes(const void* p, size_t n) {
    const auto* b = static_cast<const unsigned char*>(p);
    for (size_t i = 0; i < n; ++i) h = (h ^ b[i]) * 1099511628211ull;
  }
  template <class T>
  void pod(const T& v) {
    bytes(&v, sizeof v);
  }
  template <class T>
  void vec(const std::vector<T>& v) {
    pod(v.size());
    if (!v.empty()) bytes(v.data(), v.size() * sizeof(T));
  }
  void text(const std::string& s) {
    pod(s.size());
    bytes(s.data(), s.size());
  }
};

std::string readText(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  std::ostringstream o;
  if (f) o << f.rdbuf();
  return o.str();
}

// Scene content (the file's text and everything the reference reads), size, samples, seed, the
// truth settings and the visibility mode (with visibility, the triangles and alpha inputs that
// occlude, off screen too; without it the key is the one it was before visibility existed).
uint64_t referenceKey(const Scene& scene, const GBufferReadback& gb, const RenderSettings& truth,
                      int samples, uint64_t seed, bool visibility) {
  Hasher k;
  k.text(kReferenceCacheVersion);
  k.text(readText(scene.source_path));
  k.pod(gb.width), k.pod(gb.height);
  k.vec(gb.base_color), k.vec(gb.metallic), k.vec(gb.roughness), k.vec(gb.cavity);
  k.vec(gb.depth), k.vec(gb.normal), k.vec(gb.model);
  const Camera& c = scene.camera;
  k.pod(c.position), k.pod(c.target), k.pod(c.up), k.pod(c.fov_y_deg);
  for (const Light& l : scene.lights) {
    k.pod(l.type), k.pod(l.position), k.pod(l.color), k.pod(l.intensity), k.pod(l.radius);
    k.pod(l.length), k.pod(l.axis), k.pod(l.range);
  }
  const Environment& e = scene.environment;
  k.pod(e.kind), k.text(e.path), k.pod(e.color), k.pod(e.intensity), k.pod(e.rotation_deg);
  k.pod(truth.d), k.pod(truth.v), k.pod(truth.f), k.pod(truth.diffuse);
  k.pod(truth.remap_roughness), k.pod(truth.falloff_plus_one);
  k.pod(truth.energy_compensation), k.pod(truth.specular_occlusion);
  k.pod(samples), k.pod(seed);
  if (visibility) {
    k.text("visibility");
    for (const Object& o : scene.objects) k.pod(o.transform), k.vec(o.meshes);
    for (const Mesh& m : scene.meshes) {
      for (const Vertex& v : m.vertices) k.pod(v.position), k.pod(v.uv0), k.pod(v.uv1);
      k.vec(m.indices), k.pod(m.material);
    }
    for (const Material& m : scene.materials) {
      k.pod(m.alpha_mode), k.pod(m.alpha_cutoff), k.pod(m.base_alpha);
      k.pod(m.base_color_tex.image), k.pod(m.base_color_tex.texcoord);
    }
    for (const ImageData& i : scene.images) k.pod(i.width), k.pod(i.height), k.vec(i.rgba);
  }
  return k.h;
}

std::string defaultCacheDir() {
  return (fs::path(iblCacheDir(BakeOptions{})) / "reference").string();
}

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// The lit pixels of `img` as one row (metrics over lit pixels only).
ImageRGBf litRow(const ImageRGBf& img, const std::vector<size_t>& lit) {
  ImageRGBf row = makeImageRGBf(int(lit.size()), 1);
  for (size_t i = 0; i < lit.size(); ++i) row.px[i] = img.px[lit[i]];
  return row;
}

// `img` with every pixel that is not lit replaced by `fill`'s (zero error in a heat map).
ImageRGBf maskedLike(const ImageRGBf& img, const ImageRGBf& fill, const std::vector<bool>& lit) {
  ImageRGBf out = img;
  for (size_t i = 0; i < out.px.size(); ++i)
    if (!lit[i]) out.px[i] = fill.px[i];
  return out;
}

std::string slug(const std::string& name) {
  std::string s;
  for (char c : name) s += (std::isalnum(static_cast<unsigned char>(c)) || c == '_') ? c : '-';
  return s;
}

std::string fmtNum(double v, const char* f = "%.4g") {
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  if (std::isnan(v)) return "nan";
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
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

TradePlan tradePlan(const Scene& scene, int max_brute_force_lights) {
  TradePlan plan;
  const RenderSettings& b = scene.settings;
  const int pf = scene.environment.prefilter_samples;
  const bool env = scene.environment.kind != EnvironmentKind::None;
  bool sphere = false, tube = false;
  for (const Light& l : scene.lights) {
    sphere |= l.type == LightType::Sphere;
    tube |= l.type == LightType::Tube;
  }
  const bool lights = !scene.lights.empty();
  std::vector<TradeConfig> c;
  c.push_back({"scene", "scene", b, pf, {}});
  // One row per other value of each approximation option of the settings table
  // (render_settings.hpp), where the scene has what makes it change code.
  const std::pair<SettingFeature, const char*> absent[] = {
      {SettingFeature::Lights, lights ? nullptr : "no lights"},
      {SettingFeature::SphereLights, sphere ? nullptr : "no sphere lights"},
      {SettingFeature::TubeLights, tube ? nullptr : "no tube lights"},
      {SettingFeature::AmbientIbl, env ? nullptr : "no environment"}};
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
      if (b.culling == Culling::Tiled && int(scene.lights.size()) > max_brute_force_lights) {
        plan.skipped.push_back("culling=brute_force: " + std::to_string(scene.lights.size()) +
                               " lights (more than " + std::to_string(max_brute_force_lights) +
                               "; brute force shades every light at every pixel)");
        return;
      }
    }
    if constexpr (std::is_same_v<T, bool>) {
      boolRow(c, row.key, b, pf, row.member, row.info.trade_group);
    } else if constexpr (std::is_enum_v<T>) {
      enumRows(c, row.key, b, pf, row.member, row.info.trade_group);
    }
  });
  for (size_t i = 0; i < std::size(absent); ++i) {
    if (!skipped_keys[i].empty()) plan.skipped.push_back(skipped_keys[i] + ": " + absent[i].second);
  }
  if (!env) {
    plan.skipped.push_back("environment.prefilter_samples: no environment");
  } else if (scene.environment.kind == EnvironmentKind::Uniform) {
    plan.skipped.push_back(
        "environment.prefilter_samples: a uniform environment prefilters exactly with any count");
  } else {
    for (int p : {std::max(pf / 4, 1), std::min(pf * 4, 65536)}) {
      if (p == pf) continue;
      c.push_back({"environment.prefilter_samples=" + std::to_string(p), "environment", b, p, {}});
    }
  }
  for (std::string_view p : settingsPresetNames()) {
    TradeConfig t{"preset=" + str(p), "preset", b, pf, {}};
    applySettingsPreset(p, t.settings);
    c.push_back(t);
  }
  // The exact configuration: the reference's BRDF and the most accurate methods of the engine.
  TradeConfig exact{"exact", "exact", truthSettings(b), pf, {}};
  exact.settings.sphere_diffuse = SphereDiffuse::HorizonCorrect;
  exact.settings.sphere_normalization = true;
  exact.settings.sphere_specular = SphereSpecular::Ltc;  // docs/accuracy.md: the closest methods
  exact.settings.tube_specular = TubeSpecular::Ltc;
  exact.settings.tube_normalization = true;
  exact.settings.tube_diffuse = TubeDiffuse::Ltc;
  exact.settings.env_brdf = EnvBrdf::Table;
  exact.settings.irradiance = Irradiance::Cubemap;
  c.push_back(exact);

  for (TradeConfig& t : c) {
    auto same = std::find_if(plan.configs.begin(), plan.configs.end(), [&](const TradeConfig& o) {
      return o.prefilter_samples == t.prefilter_samples && o.settings == t.settings;
    });
    if (same != plan.configs.end()) {
      same->aliases.push_back(t.name);
    } else {
      plan.configs.push_back(t);
    }
  }
  return plan;
}

void markPareto(std::vector<TradeRow>& rows) {
  for (TradeRow& r : rows) {
    const double t = r.total_ms, e = r.error.rel_rmse;
    r.pareto = std::isfinite(e) && r.nonfinite == 0;
    for (const TradeRow& o : rows) {
      if (&o == &r || !std::isfinite(o.error.rel_rmse) || o.nonfinite) continue;
      const double ot = o.total_ms, oe = o.error.rel_rmse;
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
    if (row.nonfinite || !std::isfinite(row.error.rel_rmse)) continue;
    if (row.error.rel_rmse <= r.max_error &&
        (r.cheapest_within_error < 0 ||
         row.total_ms < r.rows[size_t(r.cheapest_within_error)].total_ms)) {
      r.cheapest_within_error = int(i);
    }
    if (row.total_ms <= r.max_ms &&
        (r.most_accurate_within_ms < 0 ||
         row.error.rel_rmse < r.rows[size_t(r.most_accurate_within_ms)].error.rel_rmse)) {
      r.most_accurate_within_ms = int(i);
    }
  }
}

namespace {
using Say = std::function<void(const std::string&)>;

// Stage 1: the reference of the exact configuration (rep.truth), read from the cache when its
// inputs match, else rendered (and cached). Fills rep.reference*, returns (image, std. error).
std::pair<ImageRGBf, ImageRGBf> tradeReference(const Scene& scene, const GBufferReadback& gb,
                                               const TradeOptions& opt, TradeReport& rep,
                                               const Say& say) {
  const int w = rep.width, h = rep.height;
  Scene truth_scene = scene;
  truth_scene.settings = rep.truth;
  const uint64_t key = referenceKey(scene, gb, rep.truth, rep.samples, opt.seed, opt.visibility);
  const fs::path cache =
      opt.cache_dir.empty() ? fs::path(defaultCacheDir()) : fs::path(opt.cache_dir);
  char name[64];
  std::snprintf(name, sizeof name, "reference-%016llx", static_cast<unsigned long long>(key));
  const fs::path img_path = cache / (std::string(name) + ".pfm");
  const fs::path se_path = cache / (std::string(name) + "-se.pfm");
  const fs::path meta_path = cache / (std::string(name) + ".json");
  rep.reference_file = img_path.string();
  ImageRGBf ref, ref_se;
  if (opt.use_cache && fs::exists(img_path) && fs::exists(se_path) && fs::exists(meta_path)) {
    ref = readPfm(img_path.string());
    ref_se = readPfm(se_path.string());
    const auto j = nlohmann::json::parse(readText(meta_path.string()));
    rep.reference.lit_pixels = j.at("lit_pixels").get<size_t>();
    rep.reference.total_samples = j.at("total_samples").get<uint64_t>();
    rep.reference.mean_rel_error = j.at("mean_rel_error").get<double>();
    rep.reference.max_rel_error = j.at("max_rel_error").get<double>();
    rep.reference.seconds = j.at("seconds").get<double>();
    rep.reference_cached =
        ref.width == w && ref.height == h && ref_se.width == w && ref_se.height == h;
    if (rep.reference_cached) say("reference: cached " + img_path.string());
  }
  if (rep.reference_cached) return {std::move(ref), std::move(ref_se)};
  say("reference: " + std::to_string(w) + "x" + std::to_string(h) + ", " +
      std::to_string(rep.samples) + " samples per pixel ...");
  ReferenceOptions ro;
  ro.samples = rep.samples;
  ro.threads = opt.threads;
  ro.seed = opt.seed;
  ro.visibility = opt.visibility;
  const ReferenceResult rr = renderReference(truth_scene, gb, ro);
  rep.reference = rr.stats;
  say("reference: " + fmtNum(rr.stats.seconds, "%.1f") + " s");
  if (opt.use_cache) {
    fs::create_directories(cache);
    OutputFiles files;  // the three appear together or not at all (a cache hit needs all)
    writePfm(files.add(img_path).string(), rr.image);
    writePfm(files.add(se_path).string(), rr.std_error);
    nlohmann::ordered_json j = {{"scene", scene.source_path},
                                {"width", w},
                                {"height", h},
                                {"samples", rep.samples},
                                {"visibility", opt.visibility},
                                {"lit_pixels", rr.stats.lit_pixels},
                                {"total_samples", rr.stats.total_samples},
                                {"mean_rel_error", rr.stats.mean_rel_error},
                                {"max_rel_error", rr.stats.max_rel_error},
                                {"seconds", rr.stats.seconds}};
    files.write(meta_path, j.dump(2) + "\n");
    files.commit();
  }
  return {rr.image, rr.std_error};
}

// Stage 2: the compared pixels (lit, and the reference converged there) and the reference's
// noise over them (rep.lit_pixels, unconverged_pixels, noise_rmse, noise_rel_rmse).
struct ComparedPixels {
  std::vector<bool> mask;
  std::vector<size_t> lit;
};
ComparedPixels comparedPixels(const GBufferReadback& gb, const ImageRGBf& ref,
                              const ImageRGBf& ref_se, TradeReport& rep) {
  ComparedPixels c;
  c.mask.assign(gb.model.size(), false);
  for (size_t i = 0; i < gb.model.size(); ++i) {
    if (gb.model[i] != uint32_t(ShadingModel::DefaultLit)) continue;
    const double sum = double(ref.px[i].x) + double(ref.px[i].y) + double(ref.px[i].z);
    const double se = double(ref_se.px[i].x) + double(ref_se.px[i].y) + double(ref_se.px[i].z);
    if (!(se <= kMaxReferenceRelError * sum) && se > 0.0) {
      ++rep.unconverged_pixels;
      continue;
    }
    c.mask[i] = true;
    c.lit.push_back(i);
  }
  rep.lit_pixels = c.lit.size();
  double sq = 0.0, abs_ref = 0.0;
  for (size_t i : c.lit)
    for (int ch = 0; ch < 3; ++ch) {
      sq += double(ref_se.px[i][ch]) * double(ref_se.px[i][ch]);
      abs_ref += std::abs(double(ref.px[i][ch]));
    }
  const double n = std::max(double(c.lit.size()) * 3.0, 1.0);
  rep.noise_rmse = std::sqrt(sq / n);
  rep.noise_rel_rmse = abs_ref > 0.0 ? rep.noise_rmse / (abs_ref / n) : 0.0;
  return c;
}

bool wantHeatmap(const TradeOptions& opt, const TradeConfig& cfg) {
  if (opt.report_dir.empty()) return false;
  if (opt.heatmaps == TradeOptions::Heatmaps::All) return true;
  return opt.heatmaps == TradeOptions::Heatmaps::Presets &&
         (cfg.group == "scene" || cfg.group == "preset" || cfg.group == "exact" ||
          std::any_of(cfg.aliases.begin(), cfg.aliases.end(), [](const std::string& a) {
            return a.rfind("preset=", 0) == 0 || a == "exact";
          }));
}

// Stage 3: one configuration's image against the reference: error, bias, non-finite pixels and
// (when asked) its heat map.
TradeRow scoreConfig(const TradeConfig& cfg, const ImageRGBf& img, const ImageRGBf& ref,
                     const ComparedPixels& px, const TradeOptions& opt, const TradeReport& rep) {
  TradeRow row;
  row.config = cfg;
  for (const glm::vec3& v : img.px)
    row.nonfinite += !(std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z));
  row.error = compareImages(litRow(img, px.lit), litRow(ref, px.lit));
  const double mean_ref = row.error.rel_rmse > 0.0 ? row.error.rmse / row.error.rel_rmse : 0.0;
  row.bias_rel_rmse =
      mean_ref > 0.0
          ? std::sqrt(
                std::max(row.error.rmse * row.error.rmse - rep.noise_rmse * rep.noise_rmse, 0.0)) /
                mean_ref
          : 0.0;
  row.within_noise = row.error.rel_rmse <= kNoiseFactor * rep.noise_rel_rmse;
  if (wantHeatmap(opt, cfg)) {
    fs::create_directories(fs::path(opt.report_dir) / "heatmaps");
    row.heatmap = "heatmaps/" + slug(cfg.name) + ".png";
    OutputFiles heat;
    writePng(heat.add(fs::path(opt.report_dir) / row.heatmap).string(),
             relativeErrorHeatMap(maskedLike(img, ref, px.mask), maskedLike(ref, ref, px.mask),
                                  opt.heatmap_max));
    heat.commit();
  }
  return row;
}

// Stage 4 (timings): `rounds` passes over all configurations, each timing `frames` frames after a
// warm-up, so that a change of the machine's load hits every configuration alike.
struct ConfigTimes {
  std::vector<double> totals;
  std::map<std::string, std::vector<double>> per_pass;
  std::vector<std::string> order;
};
void timeConfig(render::Renderer& renderer, Scene& work, const TradeConfig& cfg, int w, int h,
                int frames, ConfigTimes& t) {
  work.settings = cfg.settings;
  work.environment.prefilter_samples = cfg.prefilter_samples;
  renderer.setScene(work);
  renderer.render(w, h);  // warm-up: compiles this configuration's programs
  for (int f = 0; f < frames; ++f) {
    const render::FrameStats st = renderer.render(w, h);
    t.totals.push_back(st.total_ms);
    for (const auto& [pass, ms] : st.passes) {
      if (!t.per_pass.count(pass)) t.order.push_back(pass);
      t.per_pass[pass].push_back(ms);
    }
  }
}

// Per-frame ratio of row k's time over the scene row's (same round and frame index), summed over
// `passes` (empty: the frame total), with its median and 95% interval.
MedianInterval costRatio(const ConfigTimes& row, const ConfigTimes& scene,
                         const std::vector<std::string>& passes) {
  auto frameMs = [&](const ConfigTimes& t, size_t i, bool& ok) {
    if (passes.empty()) return t.totals[i];
    double sum = 0.0;
    for (const std::string& p : passes) {
      const auto it = t.per_pass.find(p);
      if (it == t.per_pass.end()) continue;  // a pass this configuration does not run: 0 ms
      if (i >= it->second.size()) {
        ok = false;
        return 0.0;
      }
      sum += it->second[i];
    }
    return sum;
  };
  std::vector<double> ratios;
  for (size_t i = 0; i < std::min(row.totals.size(), scene.totals.size()); ++i) {
    bool ok = true;
    const double a = frameMs(row, i, ok), b = frameMs(scene, i, ok);
    if (ok && b > 0.0) ratios.push_back(a / b);
  }
  return medianInterval(ratios);
}
}  // namespace

std::vector<std::string> costPasses(const std::string& group) {
  if (group == "brdf" || group == "lights") return {"light"};
  if (group == "culling") return {"light_cull", "light"};
  if (group == "environment") return {"ambient"};
  return {};
}

TradeReport runTrade(const Scene& scene, const TradeOptions& opt) {
  const Say say = [&](const std::string& s) {
    if (opt.progress) opt.progress(s);
  };
  TradeReport rep;
  rep.scene_path = scene.source_path;
  rep.width = opt.width;
  rep.height = opt.height > 0
                   ? opt.height
                   : std::max(1, int(std::lround(double(opt.width) * scene.settings.height /
                                                 scene.settings.width)));
  rep.frames = std::max(opt.frames, 1);
  rep.samples = std::max(opt.samples, 1);
  rep.rounds = std::max(opt.rounds, 1);
  const int w = rep.width, h = rep.height;
  const TradePlan plan = tradePlan(scene, opt.max_brute_force_lights);
  rep.skipped = plan.skipped;

  // The G-buffer does not depend on the lighting settings: one readback for the reference.
  Scene work = scene;
  render::Renderer renderer;
  renderer.setScene(work);
  renderer.render(w, h);
  const GBufferReadback gb = renderer.readGBuffer();
  rep.truth = truthSettings(scene.settings);
  const auto [ref, ref_se] = tradeReference(scene, gb, opt, rep, say);
  const ComparedPixels px = comparedPixels(gb, ref, ref_se, rep);

  // Every configuration: time, then compare the first round's image; more timing rounds after.
  std::vector<ConfigTimes> times(plan.configs.size());
  for (size_t k = 0; k < plan.configs.size(); ++k) {
    timeConfig(renderer, work, plan.configs[k], w, h, rep.frames, times[k]);
    rep.rows.push_back(scoreConfig(plan.configs[k], renderer.readHdr(), ref, px, opt, rep));
    say(plan.configs[k].name + ": rel RMSE " + fmtNum(rep.rows.back().error.rel_rmse));
  }
  for (int round = 1; round < rep.rounds; ++round) {
    say("timing round " + std::to_string(round + 1) + " of " + std::to_string(rep.rounds));
    for (size_t k = 0; k < plan.configs.size(); ++k) {
      timeConfig(renderer, work, plan.configs[k], w, h, rep.frames, times[k]);
    }
  }
  for (size_t k = 0; k < rep.rows.size(); ++k) {
    rep.rows[k].total_ms = median(times[k].totals);
    const MedianInterval cost = costRatio(times[k], times[0], {});  // frame by frame
    rep.rows[k].cost_ratio = cost.median;
    rep.rows[k].cost_lo = cost.lo;
    rep.rows[k].cost_hi = cost.hi;
    rep.rows[k].same_cost = cost.contains(1.0);
    std::vector<std::string> passes = costPasses(rep.rows[k].config.group);
    // A pass one of the two rows does not run counts 0 ms there (brute-force culling has no
    // culling pass); one that neither runs is left out.
    std::erase_if(passes, [&](const std::string& p) {
      return !times[k].per_pass.count(p) && !times[0].per_pass.count(p);
    });
    const MedianInterval pass_cost = passes.empty() ? cost : costRatio(times[k], times[0], passes);
    rep.rows[k].cost_passes = passes;
    rep.rows[k].pass_cost_ratio = pass_cost.median;
    rep.rows[k].pass_cost_lo = pass_cost.lo;
    rep.rows[k].pass_cost_hi = pass_cost.hi;
    rep.rows[k].pass_same_cost = pass_cost.contains(1.0);
    for (const std::string& p : times[k].order)
      rep.rows[k].pass_ms.push_back({p, median(times[k].per_pass[p])});
    const TradeConfig& c = rep.rows[k].config;
    if (c.name == "exact" ||
        std::find(c.aliases.begin(), c.aliases.end(), "exact") != c.aliases.end())
      rep.exact_row = int(k);
  }
  markPareto(rep.rows);
  rep.max_error = opt.max_error;
  rep.max_ms = opt.max_ms > 0.0 ? opt.max_ms : rep.rows.front().total_ms;
  pickConfigurations(rep);
  return rep;
}

// ---- Output ---------------------------------------------------------------------------------

namespace {
std::vector<std::string> passNames(const TradeReport& r) {
  std::vector<std::string> names;
  for (const TradeRow& row : r.rows)
    for (const auto& [p, ms] : row.pass_ms)
      if (std::find(names.begin(), names.end(), p) == names.end()) names.push_back(p);
  return names;
}

double passMs(const TradeRow& row, const std::string& pass) {
  for (const auto& [p, ms] : row.pass_ms)
    if (p == pass) return ms;
  return 0.0;
}

std::string label(const TradeConfig& c) {
  std::string s = c.name;
  for (const std::string& a : c.aliases) s += " = " + a;
  return s;
}

std::string csvField(const std::string& s) {
  if (s.find_first_of(",\"") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

std::string sceneName(const TradeReport& r) {
  return fs::path(r.scene_path).stem().string();
}
}  // namespace

std::string tradeCsv(const TradeReport& r) {
  std::ostringstream o;
  const auto passes = passNames(r);
  o << "scene,configuration,aliases,group";
  for (const auto& p : passes) o << "," << p << "_ms";
  o << ",total_ms,rel_rmse,bias_rel_rmse,p99_rel,max_abs,rmse,within_noise,pareto,"
       "nonfinite_pixels,cost_ratio,cost_lo,cost_hi,same_cost,cost_passes,pass_cost_ratio,"
       "pass_cost_lo,pass_cost_hi,pass_same_cost\n";
  for (const TradeRow& row : r.rows) {
    std::string aliases;
    for (const auto& a : row.config.aliases) aliases += (aliases.empty() ? "" : ";") + a;
    o << csvField(sceneName(r)) << "," << csvField(row.config.name) << "," << csvField(aliases)
      << "," << row.config.group;
    for (const auto& p : passes) o << "," << fmtNum(passMs(row, p), "%.4f");
    o << "," << fmtNum(row.total_ms, "%.4f") << "," << fmtNum(row.error.rel_rmse, "%.6g") << ","
      << fmtNum(row.bias_rel_rmse, "%.6g") << "," << fmtNum(row.error.p99_rel, "%.6g") << ","
      << fmtNum(row.error.max_abs, "%.6g") << "," << fmtNum(row.error.rmse, "%.6g") << ","
      << (row.within_noise ? 1 : 0) << "," << (row.pareto ? 1 : 0) << "," << row.nonfinite << ","
      << fmtNum(row.cost_ratio, "%.4f") << "," << fmtNum(row.cost_lo, "%.4f") << ","
      << fmtNum(row.cost_hi, "%.4f") << "," << (row.same_cost ? 1 : 0) << ",";
    std::string cost_passes;
    for (const auto& p : row.cost_passes) cost_passes += (cost_passes.empty() ? "" : ";") + p;
    o << csvField(cost_passes) << "," << fmtNum(row.pass_cost_ratio, "%.4f") << ","
      << fmtNum(row.pass_cost_lo, "%.4f") << "," << fmtNum(row.pass_cost_hi, "%.4f") << ","
      << (row.pass_same_cost ? 1 : 0) << "\n";
  }
  return o.str();
}

std::string tradeMarkdown(const TradeReport& r, const std::string& prefix, int level) {
  std::ostringstream o;
  const std::string h(size_t(std::max(level, 1)), '#');
  o << h << " " << sceneName(r) << " (`" << r.scene_path << "`)\n\n";
  o << r.width << "x" << r.height << ", GPU ms = median of " << r.frames * r.rounds << " frames ("
    << r.rounds << " rounds over all configurations of " << r.frames
    << " frames after a warm-up frame); x scene: the median over those frames of the row's frame "
       "time / the scene row's of the same round and frame, with its 95% interval (\"same cost\" "
       "where it includes 1); its passes x scene: the same for the passes the option changes (the "
       "light pass for BRDF and light options, light culling and the light pass for culling, the "
       "ambient pass for environment options; \"frame\" for presets and exact), free of the "
       "other passes' noise. Reference: "
    << r.samples << " samples per pixel over " << (r.lit_pixels + r.unconverged_pixels)
    << " lit pixels"
    << (r.reference_cached ? " (read from the cache; computed in " : " (computed in ")
    << fmtNum(r.reference.seconds, "%.1f")
    << " s); its mean relative standard error of luminance is "
    << fmtNum(r.reference.mean_rel_error, "%.3g") << ", as a relative RMSE the noise is "
    << fmtNum(r.noise_rel_rmse, "%.3g") << " (rows marked `~` are within "
    << fmtNum(kNoiseFactor, "%g") << "x of it). Compared: " << r.lit_pixels
    << " pixels; left out: " << r.unconverged_pixels
    << " where the reference has not converged (relative standard error > "
    << fmtNum(kMaxReferenceRelError, "%g") << ").\n\n";
  const auto passes = passNames(r);
  o << "| configuration |";
  for (const auto& p : passes) o << " " << p << " ms |";
  o << " total ms | x scene (95%) | its passes x scene (95%) | rel. RMSE | bias | p99 rel. | max "
       "abs | |\n|---|";
  for (size_t i = 0; i < passes.size(); ++i) o << "---:|";
  o << "---:|---:|---:|---:|---:|---:|---:|---|\n";
  for (size_t i = 0; i < r.rows.size(); ++i) {
    const TradeRow& row = r.rows[i];
    std::string name = "`" + row.config.name + "`";
    for (const auto& a : row.config.aliases) name += " = `" + a + "`";
    o << "| " << name << " |";
    for (const auto& p : passes) o << " " << fmtNum(passMs(row, p), "%.3f") << " |";
    std::string flags;
    if (row.pareto) flags += "front ";
    if (row.within_noise) flags += "~ ";
    if (int(i) == r.cheapest_within_error) flags += "cheapest ";
    if (int(i) == r.most_accurate_within_ms) flags += "most-accurate ";
    if (row.nonfinite) flags += "NaN/Inf:" + std::to_string(row.nonfinite) + " ";
    if (!row.heatmap.empty()) flags += "[heat map](" + prefix + row.heatmap + ")";
    const std::string cost =
        i == 0 ? std::string("1")
               : fmtNum(row.cost_ratio, "%.2f") + " (" + fmtNum(row.cost_lo, "%.2f") + "-" +
                     fmtNum(row.cost_hi, "%.2f") + ")" + (row.same_cost ? " same cost" : "");
    std::string pass_cost = "frame";
    if (i == 0) {
      pass_cost = "1";
    } else if (!row.cost_passes.empty()) {
      pass_cost.clear();
      for (const std::string& p : row.cost_passes) pass_cost += (pass_cost.empty() ? "" : "+") + p;
      pass_cost += " " + fmtNum(row.pass_cost_ratio, "%.2f") + " (" +
                   fmtNum(row.pass_cost_lo, "%.2f") + "-" + fmtNum(row.pass_cost_hi, "%.2f") + ")" +
                   (row.pass_same_cost ? " same cost" : "");
    }
    o << " " << fmtNum(row.total_ms, "%.3f") << " | " << cost << " | " << pass_cost << " | "
      << fmtNum(row.error.rel_rmse, "%.4f") << " | " << fmtNum(row.bias_rel_rmse, "%.4f") << " | "
      << fmtNum(row.error.p99_rel, "%.4f") << " | " << fmtNum(row.error.max_abs, "%.3g") << " | "
      << flags << " |\n";
  }
  o << "\n";
  if (r.cheapest_within_error >= 0) {
    const TradeRow& c = r.rows[size_t(r.cheapest_within_error)];
    o << "- Cheapest within rel. RMSE <= " << fmtNum(r.max_error, "%g") << ": `" << label(c.config)
      << "` (" << fmtNum(c.total_ms, "%.3f") << " ms, " << fmtNum(c.error.rel_rmse, "%.4f")
      << ").\n";
  } else {
    o << "- No configuration is within rel. RMSE <= " << fmtNum(r.max_error, "%g") << ".\n";
  }
  if (r.most_accurate_within_ms >= 0) {
    const TradeRow& c = r.rows[size_t(r.most_accurate_within_ms)];
    o << "- Most accurate within " << fmtNum(r.max_ms, "%.3f") << " ms: `" << label(c.config)
      << "` (" << fmtNum(c.total_ms, "%.3f") << " ms, " << fmtNum(c.error.rel_rmse, "%.4f")
      << ").\n";
  } else {
    o << "- No configuration renders within " << fmtNum(r.max_ms, "%.3f") << " ms.\n";
  }
  for (const std::string& s : r.skipped) o << "- Not applicable: " << s << ".\n";
  o << "\n![error vs time, " << sceneName(r) << "](" << prefix << "plot.png)\n";
  return o.str();
}

ImageRGBA8 tradePlot(const TradeReport& r) {
  ScatterPlot p;
  p.title = sceneName(r) + ": error vs GPU time (" + std::to_string(r.width) + "x" +
            std::to_string(r.height) + ")";
  p.x_label = "total GPU ms per frame (median)";
  p.y_label = "relative RMSE vs reference (log)";
  p.log_y = true;
  std::vector<size_t> front;
  for (size_t i = 0; i < r.rows.size(); ++i) {
    const TradeRow& row = r.rows[i];
    PlotPoint pt;
    pt.x = row.total_ms;
    pt.y = row.error.rel_rmse;
    pt.label = row.config.name;
    for (const std::string& a : row.config.aliases)
      if (a.rfind("preset=", 0) == 0 || a == "exact") pt.label += " = " + a;
    pt.marked = row.pareto;
    pt.labeled = row.pareto || row.config.group == "preset" || row.config.group == "scene" ||
                 pt.label != row.config.name;
    p.points.push_back(pt);
    if (row.pareto) front.push_back(i);
  }
  std::sort(front.begin(), front.end(),
            [&](size_t a, size_t b) { return r.rows[a].total_ms < r.rows[b].total_ms; });
  p.front = front;
  return drawScatterPlot(p);
}

std::string presetRationale() {
  return R"(The presets (engine/scene/src/presets.cpp; `"settings": {"preset": "fast"}`, explicit keys
override) set only approximation options: the V term and roughness remap, the falloff, the sphere
and tube methods, the environment BRDF and the irradiance. They never change the material model
(D, F, diffuse term, energy compensation, specular occlusion) or the culling. They were chosen
from the tables below:

| preset | sets | why (rows of the tables below) |
|---|---|---|
| `fast` | Karis 2013 defaults, `env_brdf: analytic` | the analytic fit removes a texture fetch; its relative RMSE is up to 8% above the table's (default), within 1% elsewhere (`env_brdf=analytic` rows) |
| `balanced` | Karis 2013 defaults, `irradiance: cubemap` | the irradiance cube map's error is equal to or lower than SH9's on every sample scene (`irradiance=cubemap` rows), for one more fetch |
| `accurate` | `balanced` + `falloff_plus_one: false`, `sphere_diffuse: horizon_correct`, `sphere_specular`, `tube_specular`, `tube_diffuse: ltc` | the inverse-square law is the emitter's true falloff: the largest single gain where lights are close to surfaces (`falloff_plus_one=false`, many_lights); the horizon-correct sphere diffuse is exact for a Lambertian lobe (docs/lights.md), equal or better in every table, at no measurable cost. The `ltc` sphere and tube methods have the lowest median and worst error of each light method on the accuracy sweeps (the "Summary" table of docs/accuracy.md, regenerated by `halfvec accuracy`; `sphere_specular=ltc`, `tube_specular=ltc`, `tube_diffuse=ltc` rows for the scenes). The eq. 18 tube point is not taken: it measured slightly worse than eq. 19 (`tube_specular=smallest_angle_eq18` rows) |

All presets keep `sphere_normalization` and `tube_normalization` on: turning sphere
normalization off gives by far the largest error on every scene with sphere lights except
many_lights (where it is neutral); turning tube normalization off changes the sample scenes'
error by about 1% either way, but on the accuracy sweeps (docs/accuracy.md) it makes thin tubes'
highlights up to 120x too bright. `accurate` keeps Schlick's V with the Disney remap rather than
the exact configuration's height-correlated V without remap. With the scene's own settings (and `fast` and
`balanced`), the relative RMSE on the sample scenes is dominated by highlight pixels where the
representative-point sphere and tube specular is several times brighter than the reference (the
chrome spheres of default, the roughness-0.05 spheres of sphere_grid, the glossy floor of
area_lights). `accurate`'s `ltc` methods remove most of that: its relative RMSE is below the
scene's settings' on every sample scene (the "Measured" table). gltf barely moves: its error is
carried by a few pixels of the helmet's smooth metal with a large absolute difference (the max abs
column). With the representative point, rows whose terms darken glossy highlights can score a
lower error by offsetting the overestimate, which is no reason to choose them.

Times: the "x scene" column is each row's frame time over the scene row's, frame by frame within
a round, with its 95% interval over one run's frames; "same cost" marks rows whose interval
includes 1. "its passes x scene" is the same ratio over only the passes the option changes (the
light pass for BRDF and light options, culling and the light pass for culling, the ambient pass
for environment options), so that the rest of the frame's noise does not hide it. On llvmpipe
these verdicts are not stable from run to run for differences below about 1.3x, more so when the
machine is busy: read a ratio whose interval is wide as unmeasured. The `ltc` light modes are the
one large cost; `halfvec bench --methods` measures their light pass alone, per light type, from
interleaved frames (docs/lights.md).
)";
}

void writeTradeReport(const TradeReport& r, const std::string& dir) {
  fs::create_directories(dir);
  OutputFiles files;  // the report's three files appear together, whole, or not at all
  files.write(fs::path(dir) / "trade.md", tradeMarkdown(r, "", 1));
  files.write(fs::path(dir) / "trade.csv", tradeCsv(r));
  writePng(files.add(fs::path(dir) / "plot.png").string(), tradePlot(r));
  files.commit();
}

}  // namespace hv::eval
