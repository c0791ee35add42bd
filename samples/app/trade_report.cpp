// The trade report's formats (markdown, CSV, the cost/error plot) and its files: `halfvec trade`
// writes them; engine/eval returns the data (halfvec/eval/trade.hpp).
#include "app/trade_report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "halfvec/core/output_files.hpp"
#include "halfvec/image/image.hpp"
#include "halfvec/image/plot.hpp"

namespace hv::app {

using namespace hv::eval;
namespace fs = std::filesystem;

namespace {

std::string fmtNum(double v, const char* f = "%.4g") {
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  if (std::isnan(v)) return "nan";
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

}  // namespace

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
  o << ",total_ms,mean_rel,p99_rel,top_share,rel_rmse,bias_rel_rmse,max_abs,rmse,within_noise,"
       "pareto,"
       "nonfinite_pixels,cost_ratio,cost_lo,cost_hi,same_cost,cost_passes,pass_cost_ratio,"
       "pass_cost_lo,pass_cost_hi,pass_same_cost\n";
  for (const TradeRow& row : r.rows) {
    std::string aliases;
    for (const auto& a : row.config.aliases) aliases += (aliases.empty() ? "" : ";") + a;
    o << csvField(sceneName(r)) << "," << csvField(row.config.name) << "," << csvField(aliases)
      << "," << row.config.group;
    for (const auto& p : passes) o << "," << fmtNum(passMs(row, p), "%.4f");
    o << "," << fmtNum(row.total_ms, "%.4f") << "," << fmtNum(row.error.mean_rel, "%.6g") << ","
      << fmtNum(row.error.p99_rel, "%.6g") << "," << fmtNum(row.error.top_share, "%.6g") << ","
      << fmtNum(row.error.rel_rmse, "%.6g") << "," << fmtNum(row.bias_rel_rmse, "%.6g") << ","
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

namespace {

// The paragraph under the heading: the size, what the time columns are, the reference's samples,
// noise and left-out pixels, and what the error columns are.
std::string methodParagraph(const TradeReport& r) {
  std::ostringstream o;
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
    << fmtNum(kMaxReferenceRelError, "%g") << "). The reference is given the engine's own "
    << "emissive (" << r.emissive_pixels
    << " compared pixels have some), which it does not integrate. Error columns: mean rel. = the "
       "mean over the compared pixels of |engine - reference| / (reference + "
    << fmtNum(kRelEpsilon, "%g")
    << ") (summed over the channels; the headline: the front, the picks and the plot use it), "
       "p99 rel. = its 99th percentile, worst 0.1% = the share of the squared error (what rel. "
       "RMSE is made of) carried by the worst 0.1% of pixels: near 1, rel. RMSE describes those "
       "pixels, not the image.\n\n";
  return o.str();
}

// The last column: the front, within noise, the picks, non-finite pixels, the heat map.
std::string rowFlags(const TradeReport& r, size_t i, const std::string& prefix) {
  const TradeRow& row = r.rows[i];
  std::string flags;
  if (row.pareto) flags += "front ";
  if (row.within_noise) flags += "~ ";
  if (int(i) == r.cheapest_within_error) flags += "cheapest ";
  if (int(i) == r.most_accurate_within_ms) flags += "most-accurate ";
  if (row.nonfinite) flags += "NaN/Inf:" + std::to_string(row.nonfinite) + " ";
  if (!row.heatmap.empty()) flags += "[heat map](" + prefix + row.heatmap + ")";
  return flags;
}

// "x scene (95%)" (the scene row is 1) and "its passes x scene (95%)" ("frame" where the option
// has no passes of its own).
std::string costCell(const TradeRow& row, size_t i) {
  if (i == 0) return "1";
  return fmtNum(row.cost_ratio, "%.2f") + " (" + fmtNum(row.cost_lo, "%.2f") + "-" +
         fmtNum(row.cost_hi, "%.2f") + ")" + (row.same_cost ? " same cost" : "");
}

std::string passCostCell(const TradeRow& row, size_t i) {
  if (i == 0) return "1";
  if (row.cost_passes.empty()) return "frame";
  std::string s;
  for (const std::string& p : row.cost_passes) s += (s.empty() ? "" : "+") + p;
  return s + " " + fmtNum(row.pass_cost_ratio, "%.2f") + " (" + fmtNum(row.pass_cost_lo, "%.2f") +
         "-" + fmtNum(row.pass_cost_hi, "%.2f") + ")" + (row.pass_same_cost ? " same cost" : "");
}

std::string rowTable(const TradeReport& r, const std::string& prefix) {
  std::ostringstream o;
  const auto passes = passNames(r);
  o << "| configuration |";
  for (const auto& p : passes) o << " " << p << " ms |";
  o << " total ms | x scene (95%) | its passes x scene (95%) | mean rel. | p99 rel. | worst 0.1% "
       "| rel. RMSE | bias | max abs | |\n|---|";
  for (size_t i = 0; i < passes.size(); ++i) o << "---:|";
  o << "---:|---:|---:|---:|---:|---:|---:|---:|---:|---|\n";
  for (size_t i = 0; i < r.rows.size(); ++i) {
    const TradeRow& row = r.rows[i];
    std::string name = "`" + row.config.name + "`";
    for (const auto& a : row.config.aliases) name += " = `" + a + "`";
    o << "| " << name << " |";
    for (const auto& p : passes) o << " " << fmtNum(passMs(row, p), "%.3f") << " |";
    o << " " << fmtNum(row.total_ms, "%.3f") << " | " << costCell(row, i) << " | "
      << passCostCell(row, i) << " | " << fmtNum(row.error.mean_rel, "%.4f") << " | "
      << fmtNum(row.error.p99_rel, "%.4f") << " | " << fmtNum(100.0 * row.error.top_share, "%.1f")
      << "% | " << fmtNum(row.error.rel_rmse, "%.4f") << " | " << fmtNum(row.bias_rel_rmse, "%.4f")
      << " | " << fmtNum(row.error.max_abs, "%.3g") << " | " << rowFlags(r, i, prefix) << " |\n";
  }
  return o.str();
}

// The two picks (or that none qualifies) and the options that do not apply to the scene.
std::string picks(const TradeReport& r) {
  std::ostringstream o;
  if (r.cheapest_within_error >= 0) {
    const TradeRow& c = r.rows[size_t(r.cheapest_within_error)];
    o << "- Cheapest within mean rel. error <= " << fmtNum(r.max_error, "%g") << ": `"
      << label(c.config) << "` (" << fmtNum(c.total_ms, "%.3f") << " ms, "
      << fmtNum(headlineError(c), "%.4f") << ").\n";
  } else {
    o << "- No configuration is within mean rel. error <= " << fmtNum(r.max_error, "%g") << ".\n";
  }
  if (r.most_accurate_within_ms >= 0) {
    const TradeRow& c = r.rows[size_t(r.most_accurate_within_ms)];
    o << "- Most accurate within " << fmtNum(r.max_ms, "%.3f") << " ms: `" << label(c.config)
      << "` (" << fmtNum(c.total_ms, "%.3f") << " ms, mean rel. error "
      << fmtNum(headlineError(c), "%.4f") << ").\n";
  } else {
    o << "- No configuration renders within " << fmtNum(r.max_ms, "%.3f") << " ms.\n";
  }
  for (const std::string& s : r.skipped) o << "- Not applicable: " << s << ".\n";
  return o.str();
}

}  // namespace

std::string tradeMarkdown(const TradeReport& r, const std::string& prefix, int level) {
  std::ostringstream o;
  const std::string h(size_t(std::max(level, 1)), '#');
  o << h << " " << sceneName(r) << " (`" << r.scene_path << "`)\n\n";
  o << methodParagraph(r) << rowTable(r, prefix) << "\n" << picks(r);
  o << "\n![error vs time, " << sceneName(r) << "](" << prefix << "plot.png)\n";
  return o.str();
}

ImageRGBA8 tradePlot(const TradeReport& r) {
  ScatterPlot p;
  p.title = sceneName(r) + ": error vs GPU time (" + std::to_string(r.width) + "x" +
            std::to_string(r.height) + ")";
  p.x_label = "total GPU ms per frame (median)";
  p.y_label = "mean relative error vs reference (log)";
  p.log_y = true;
  std::vector<size_t> front;
  for (size_t i = 0; i < r.rows.size(); ++i) {
    const TradeRow& row = r.rows[i];
    PlotPoint pt;
    pt.x = row.total_ms;
    pt.y = headlineError(row);
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
| `fast` | Karis 2013 defaults, `env_brdf: analytic` | the analytic fit removes a texture fetch, at the error of the `env_brdf=analytic` rows (against the scene rows, which use the table by default) |
| `balanced` | Karis 2013 defaults, `irradiance: cubemap` | the irradiance cube map's error is equal to or lower than SH9's on every sample scene (`irradiance=cubemap` rows), for one more fetch |
| `accurate` | `balanced` + `falloff_plus_one: false`, `sphere_diffuse: horizon_correct`, `sphere_specular`, `tube_specular`, `tube_diffuse: ltc` | the inverse-square law is the emitter's true falloff: the largest single gain where lights are close to surfaces (`falloff_plus_one=false`, many_lights); the horizon-correct sphere diffuse is exact for a Lambertian lobe (docs/lights.md), equal or better in every table, at no measurable cost. The `ltc` sphere and tube methods have the lowest median and worst error of each light method on the accuracy sweeps (the "Summary" table of docs/accuracy.md, regenerated by `halfvec accuracy`; `sphere_specular=ltc`, `tube_specular=ltc`, `tube_diffuse=ltc` rows for the scenes). The eq. 18 tube point is not taken: it measured slightly worse than eq. 19 (`tube_specular=smallest_angle_eq18` rows) |

All presets keep `sphere_normalization` and `tube_normalization` on: turning sphere normalization
off gives by far the largest error on every scene with sphere lights except many_lights (where it is
neutral); turning tube normalization off changes the sample scenes' error little either way
(`tube_normalization=false` rows), but on the accuracy sweeps it makes thin tubes' highlights many
times too bright (the "eq. 19, no normalization" row of the "Summary" table of docs/accuracy.md).
`accurate` keeps Schlick's V with the Disney remap rather than the exact configuration's
height-correlated V without remap. With the scene's own settings (and `fast` and `balanced`), the
relative RMSE on the sample scenes is dominated by highlight pixels where the representative-point
sphere and tube specular is several times brighter than the reference (the chrome spheres of
default, the roughness-0.05 spheres of sphere_grid, the glossy floor of area_lights). `accurate`'s
`ltc` methods remove most of that: its relative RMSE is below the scene's settings' on every sample
scene (the "Measured" table). gltf's relative RMSE is carried by a few pixels (the "worst 0.1%"
column): the sky's sun reflected in the visor, a directional light since `sky_sun: light` (its
row here puts the sun back into the prefiltered cube, docs/ibl.md), whose glint the representative
point draws too bright and `accurate`'s LTC close to the reference. With the representative
point, rows whose terms darken glossy highlights can score a lower error by offsetting the
overestimate, which is no reason to choose them.

Times: the "x scene" column is each row's frame time over the scene row's, frame by frame within
a round, with its 95% interval over one run's frames; "same cost" marks rows whose interval
includes 1. "its passes x scene" is the same ratio over only the passes the option changes (the
light pass for BRDF and light options, culling and the light pass for culling, the ambient pass
for environment options), so that the rest of the frame's noise does not hide it. On llvmpipe
these verdicts are not stable from run to run for small differences, more so when the machine is
busy: read a ratio whose interval is wide as unmeasured. The `ltc` light modes are the one large
cost; `halfvec bench --methods` measures their light pass alone, per light type, from interleaved
frames (docs/lights.md).
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

}  // namespace hv::app
