// The trade report's run, stage by stage: the reference (trade_reference.cpp: cached by its
// inputs), the compared pixels, every configuration of the plan rendered and timed in interleaved
// rounds, the error of each against the reference, heat maps, the cost ratios. The plan is
// trade_plan.cpp's; the report formats are the command's (samples/app/trade_report).
#include "halfvec/eval/trade.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <map>

#include "halfvec/core/output_files.hpp"
#include "halfvec/eval/bench.hpp"
#include "halfvec/render/renderer.hpp"
#include "trade_reference.hpp"

namespace hv::eval {

namespace fs = std::filesystem;

namespace {

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
using trade_detail::Say;
using trade_detail::tradeReference;

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
    if (!isLit(ShadingModel(gb.model[i]))) continue;
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

// The report before any measurement: the scene, the image size (the scene's aspect ratio where
// no height is given) and the counts, each at least 1.
TradeReport emptyReport(const Scene& scene, const TradeOptions& opt) {
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
  rep.truth = truthSettings(scene.settings);
  return rep;
}

// What every configuration is compared with: the reference plus the engine's emissive, and the
// pixels compared.
struct Target {
  ImageRGBf ref;
  ComparedPixels px;
};

// Stages 1 and 2 on the scene's G-buffer (it does not depend on the lighting settings: one
// readback serves the reference). The emissive the engine draws (the same G-buffer, no light
// term) is added to the reference; the compared pixels and the noise are then those of the image
// the engine is compared with. `work`: the copy of `scene` the renderer keeps rendering.
Target compareTarget(render::Renderer& renderer, const Scene& scene, const Scene& work,
                     const TradeOptions& opt, TradeReport& rep, const Say& say) {
  const int w = rep.width, h = rep.height;
  renderer.setScene(work);
  renderer.render(w, h);
  const GBufferReadback gb = renderer.readGBuffer();
  const auto [truth_ref, ref_se] = tradeReference(scene, gb, opt, rep, say);
  renderer.render(w, h, render::DebugView::Emissive);
  const ImageRGBf emissive = renderer.readHdr();
  Target t{withEmissive(truth_ref, emissive), {}};
  t.px = comparedPixels(gb, t.ref, ref_se, rep);
  rep.emissive_pixels = 0;
  for (size_t i : t.px.lit) rep.emissive_pixels += emissive.px[i] != glm::vec3(0.0f);
  return t;
}

// Stage 5: a row's times from all rounds: medians per frame and pass, and its cost against the
// scene row, over the frame and over the passes its option changes.
void timeColumns(TradeRow& row, const ConfigTimes& t, const ConfigTimes& scene) {
  row.total_ms = median(t.totals);
  const MedianInterval cost = costRatio(t, scene, {});  // frame by frame
  row.cost_ratio = cost.median;
  row.cost_lo = cost.lo;
  row.cost_hi = cost.hi;
  row.same_cost = cost.contains(1.0);
  std::vector<std::string> passes = costPasses(row.config.group);
  // A pass one of the two rows does not run counts 0 ms there (brute-force culling has no
  // culling pass); one that neither runs is left out.
  std::erase_if(passes, [&](const std::string& p) {
    return !t.per_pass.count(p) && !scene.per_pass.count(p);
  });
  const MedianInterval pass_cost = passes.empty() ? cost : costRatio(t, scene, passes);
  row.cost_passes = passes;
  row.pass_cost_ratio = pass_cost.median;
  row.pass_cost_lo = pass_cost.lo;
  row.pass_cost_hi = pass_cost.hi;
  row.pass_same_cost = pass_cost.contains(1.0);
  for (const std::string& p : t.order) row.pass_ms.push_back({p, median(t.per_pass.at(p))});
}

bool isExact(const TradeConfig& c) {
  return c.name == "exact" ||
         std::find(c.aliases.begin(), c.aliases.end(), "exact") != c.aliases.end();
}

}  // namespace

TradeReport runTrade(const Scene& scene, const TradeOptions& opt) {
  const Say say = [&](const std::string& s) {
    if (opt.progress) opt.progress(s);
  };
  TradeReport rep = emptyReport(scene, opt);
  const int w = rep.width, h = rep.height;
  const TradePlan plan = tradePlan(scene, opt.max_brute_force_lights);
  rep.skipped = plan.skipped;
  Scene work = scene;
  render::Renderer renderer;
  const Target target = compareTarget(renderer, scene, work, opt, rep, say);

  // Every configuration: time, then compare the first round's image; more timing rounds after.
  std::vector<ConfigTimes> times(plan.configs.size());
  for (size_t k = 0; k < plan.configs.size(); ++k) {
    timeConfig(renderer, work, plan.configs[k], w, h, rep.frames, times[k]);
    rep.rows.push_back(
        scoreConfig(plan.configs[k], renderer.readHdr(), target.ref, target.px, opt, rep));
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
    timeColumns(rep.rows[k], times[k], times[0]);
    if (isExact(rep.rows[k].config)) rep.exact_row = int(k);
  }
  markPareto(rep.rows);
  rep.max_error = opt.max_error;
  rep.max_ms = opt.max_ms > 0.0 ? opt.max_ms : rep.rows.front().total_ms;
  pickConfigurations(rep);
  return rep;
}

}  // namespace hv::eval
