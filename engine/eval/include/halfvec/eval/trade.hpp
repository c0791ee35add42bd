// The speed/accuracy trade report behind `halfvec trade` (docs/trade.md): renders a scene under
// one-at-a-time deviations of its accuracy/speed options and under the presets, times every pass
// (median of N frames after a warm-up) and measures each image's error against the CPU reference
// of the physically exact configuration (truthSettings), computed once and cached on disk.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "halfvec/image/image.hpp"
#include "halfvec/image/metrics.hpp"
#include "halfvec/reference/reference.hpp"
#include "halfvec/scene/scene.hpp"

namespace hv::eval {

// A configuration is "within noise" when its relative RMSE is at most this many times the
// reference's own noise (its standard error expressed as a relative RMSE, TradeReport::noise).
inline constexpr double kNoiseFactor = 2.0;
// Lit pixels where the reference has not converged, sum of the channels' standard errors over
// the sum of the channels above this, are left out of the metrics (and counted): light sampling
// of small area lights seen in near-mirror surfaces yields rare huge samples (docs/trade.md).
inline constexpr double kMaxReferenceRelError = 0.25;

struct TradeConfig {
  std::string name;   // "scene", "brdf.v=smith_ggx_correlated", "preset=fast", "exact", ...
  std::string group;  // scene, brdf, lights, culling, environment, preset, exact
  RenderSettings settings;
  int prefilter_samples = 256;       // Environment::prefilter_samples
  std::vector<std::string> aliases;  // names of identical configurations merged into this one
};

// What the reference integrates: the scene's material model (D, F, diffuse term, energy
// compensation, specular occlusion) with the approximations of the BRDF replaced by the exact
// terms: V = the exact height-correlated Smith term for GGX (Heitz 2014) or Walter's Beckmann
// Smith for Beckmann (Blinn-Phong keeps the scene's V), Schlick's F in place of its spherical-
// Gaussian fit, no Disney roughness remap, the inverse-square falloff (no +1). Area lights and
// the environment are integrated exactly by the reference whatever the scene's methods.
RenderSettings truthSettings(const RenderSettings& s);

struct TradePlan {
  std::vector<TradeConfig> configs;  // first: "scene" (the scene's own settings)
  std::vector<std::string> skipped;  // options left out for this scene, each with the reason
};

// The configurations for `scene`: its own settings, one row per other value of each option that
// applies to it (BRDF terms; the falloff and the sphere/tube methods only with lights of that
// type; brute-force culling only with at most `max_brute_force_lights` lights; the environment
// options only with an environment, the prefilter sample count only for a non-uniform one), the
// presets applied on top of the scene's settings, and "exact": truthSettings plus the most
// accurate light and environment methods. Identical configurations are merged (aliases).
TradePlan tradePlan(const Scene& scene, int max_brute_force_lights = 64);

// The GPU passes (FrameStats pass names) whose work a configuration group changes: "brdf" and
// "lights": {"light"}; "culling": {"light_cull", "light"}; "environment": {"ambient"}; others
// (scene, preset, exact): none, i.e. the whole frame.
std::vector<std::string> costPasses(const std::string& group);

struct TradeRow {
  TradeConfig config;
  std::vector<std::pair<std::string, double>> pass_ms;  // median GPU ms per pass, in pass order
  double total_ms = 0.0;                                // median of the per-frame totals
  // Cost relative to the scene's settings (row 0): the median over timed frames of (this row's
  // frame total / the scene row's total of the same round and frame index) with its
  // distribution-free 95% interval (eval::medianInterval); `same_cost` when it includes 1.
  double cost_ratio = 1.0, cost_lo = 1.0, cost_hi = 1.0;
  bool same_cost = true;
  // The same for the passes the option changes (costPasses of its group: the light pass for BRDF
  // and light options, light culling + the light pass for culling, the ambient pass for the
  // environment options), summed per frame: the part of the frame the option can change, free of
  // the other passes' noise. Empty `cost_passes` (the scene row, presets, exact): the frame.
  std::vector<std::string> cost_passes;
  double pass_cost_ratio = 1.0, pass_cost_lo = 1.0, pass_cost_hi = 1.0;
  bool pass_same_cost = true;
  // Engine HDR image vs the reference plus the engine's own emissive (TradeReport::
  // emissive_pixels), over the compared pixels; the headline is error.mean_rel (headlineError).
  ErrorMetrics error;
  double bias_rel_rmse = 0.0;  // sqrt(max(rmse^2 - noise_rmse^2, 0)) / mean |reference|
  bool within_noise = false;   // error.rel_rmse <= kNoiseFactor * TradeReport::noise_rel_rmse
  int64_t nonfinite = 0;       // NaN/Inf pixels of the engine image (all pixels)
  bool pareto = false;         // on the front of (total_ms, headlineError)
  std::string heatmap;         // file name relative to the report folder, empty if none
};

struct TradeOptions {
  int width = 320, height = 0;  // height 0: from the scene's aspect ratio
  int frames = 5;               // timed frames after one warm-up frame, per round
  int rounds = 3;               // timing passes over all configurations (interleaved)
  int samples = 256;            // reference samples per pixel
  double max_error = 0.05;      // headlineError bound for the "cheapest within" pick
  double max_ms = 0.0;          // time bound for the "most accurate within" pick; <= 0: scene's
  std::string report_dir;       // heat maps go to report_dir/heatmaps (empty: none written)
  enum class Heatmaps { All, Presets, None } heatmaps = Heatmaps::All;  // Presets: + scene, exact
  float heatmap_max = 0.2f;                                             // relative error scale
  std::string cache_dir;  // reference cache; empty: <halfvec cache dir>/reference
  bool use_cache = true;
  int max_brute_force_lights = 64;
  int threads = 0;  // reference threads (0: all cores)
  uint64_t seed = 1;
  // The reference's visibility rays (ReferenceOptions::visibility; part of the cache key). Off:
  // the shading-only truth the report has measured against so far.
  bool visibility = false;
  std::function<void(const std::string&)> progress;  // one line per step (may be empty)
};

struct TradeReport {
  std::string scene_path;
  int width = 0, height = 0, frames = 0, rounds = 0, samples = 0;
  RenderSettings truth;
  ReferenceStats reference;
  bool reference_cached = false;
  std::string reference_file;
  size_t lit_pixels = 0;          // compared pixels: lit, reference converged
  size_t unconverged_pixels = 0;  // lit pixels left out (kMaxReferenceRelError)
  double noise_rmse = 0.0;        // sqrt(mean of the reference's squared standard error)
  double noise_rel_rmse = 0.0;    // noise_rmse / mean |reference|, over lit pixels
  // Compared pixels where the engine draws emissive light (the G-buffer pass writes it into the
  // HDR target). The reference integrates lights and the environment only; the engine's
  // emissive (its Emissive term view) is added to it before any comparison, so that a pixel's
  // error is that of its shading, not the emissive the reference never has.
  size_t emissive_pixels = 0;
  std::vector<TradeRow> rows;
  std::vector<std::string> skipped;
  double max_error = 0.0, max_ms = 0.0;  // the bounds the picks used
  int cheapest_within_error = -1;        // row index, -1 if no row qualifies
  int most_accurate_within_ms = -1;
  int exact_row = -1;  // the row named (or aliased) "exact"
};

// Renders and measures every configuration of tradePlan(scene). Needs a current GL context.
TradeReport runTrade(const Scene& scene, const TradeOptions& options);

// The headline error of a row: the mean relative error over the compared pixels
// (ErrorMetrics::mean_rel), each pixel counting once. The relative RMSE stays a column, with the
// share of its squared error carried by the worst 0.1% of pixels (ErrorMetrics::top_share):
// where a few pixels carry it (a sun glint in a mirror-like surface), it ranks configurations by
// those pixels alone (docs/trade.md).
inline double headlineError(const TradeRow& row) {
  return row.error.mean_rel;
}

// Marks the rows on the Pareto front of (total_ms, headlineError), both minimized: no other row
// is at least as fast and at least as accurate and strictly better in one.
void markPareto(std::vector<TradeRow>& rows);
// Sets the picks from report.max_error / report.max_ms (ties: the first row).
void pickConfigurations(TradeReport& report);

// The report formats (markdown, CSV, plot) are the command's: samples/app/trade_report.hpp.

}  // namespace hv::eval
