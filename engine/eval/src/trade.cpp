// The trade report's run: the reference (cached by its inputs), every configuration of the plan
// rendered and timed in interleaved rounds, the error of each against the reference, heat maps.
// The plan is trade_plan.cpp's; the report formats are the command's (samples/app/trade_report).
#include "halfvec/eval/trade.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>

#include <nlohmann/json.hpp>

#include "halfvec/core/output_files.hpp"
#include "halfvec/eval/bench.hpp"
#include "halfvec/ibl/ibl.hpp"
#include "halfvec/render/renderer.hpp"

namespace hv::eval {

namespace fs = std::filesystem;

namespace {

// Bump whenever engine/reference changes what it computes for the same inputs.
constexpr const char* kReferenceCacheVersion = "trade-reference-v4";

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

// Progress lines only (printf prints inf and nan as such).
std::string fmtNum(double v, const char* f = "%.4g") {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

}  // namespace

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

// `ref` plus the engine's emissive image, pixel by pixel (emissive adds no noise: the reference's
// standard error stays its own).
ImageRGBf withEmissive(const ImageRGBf& ref, const ImageRGBf& emissive) {
  ImageRGBf out = ref;
  for (size_t i = 0; i < out.px.size(); ++i) out.px[i] += emissive.px[i];
  return out;
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
  const auto [truth_ref, ref_se] = tradeReference(scene, gb, opt, rep, say);
  // The emissive the engine draws (the same G-buffer, no light term), added to the reference;
  // the compared pixels and the noise are then those of the image the engine is compared with.
  renderer.render(w, h, render::DebugView::Emissive);
  const ImageRGBf emissive = renderer.readHdr();
  const ImageRGBf ref = withEmissive(truth_ref, emissive);
  const ComparedPixels px = comparedPixels(gb, ref, ref_se, rep);
  rep.emissive_pixels = 0;
  for (size_t i : px.lit) rep.emissive_pixels += emissive.px[i] != glm::vec3(0.0f);

  // Every configuration: time, then compare the first round's image; more timing rounds after.
  std::vector<ConfigTimes> times(plan.configs.size());
  for (size_t k = 0; k < plan.configs.size(); ++k) {
    timeConfig(renderer, work, plan.configs[k], w, h, rep.frames, times[k]);
    rep.rows.push_back(scoreConfig(plan.configs[k], renderer.readHdr(), ref, px, opt, rep));
    say(plan.configs[k].name + ": mean rel. error " + fmtNum(headlineError(rep.rows.back())) +
        ", rel. RMSE " + fmtNum(rep.rows.back().error.rel_rmse));
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

}  // namespace hv::eval
