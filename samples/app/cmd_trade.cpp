// `halfvec trade`: the speed/accuracy trade report of a scene (halfvec/eval/trade.hpp,
// docs/trade.md).
#include <algorithm>
#include <cmath>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "app/commands.hpp"
#include "app/trade_report.hpp"
#include "halfvec/core/output_files.hpp"
#include "halfvec/eval/trade.hpp"
#include "halfvec/image/image.hpp"
#include "halfvec/platform/context.hpp"
#include "halfvec/scene/presets.hpp"
#include "halfvec/scene/scene_loader.hpp"

namespace hv::app {

namespace fs = std::filesystem;

namespace {
constexpr const char* kHelp = R"(Usage: halfvec trade SCENE.json [SCENE.json ...] [options]

For each accuracy/speed option that applies to the scene (BRDF terms, roughness remap, falloff,
sphere and tube light methods, culling, environment BRDF, irradiance, prefilter samples, energy
compensation, specular occlusion) renders the scene with that one option changed, and with the
presets fast / balanced / accurate and the exact configuration; times every pass (median of N
frames after a warm-up) and compares the HDR image with the CPU reference of the exact
configuration over lit pixels (computed once, cached on disk). See docs/trade.md.

Options:
  --report DIR        write trade.md, trade.csv, plot.png and heatmaps/ (DIR/<scene>/ when
                      several scenes are given); without it the table goes to stdout
  --doc FILE.md       also write one markdown document with every scene's report (needs --report)
  --size WxH          image size (default 320 wide, the scene's aspect ratio)
  --size-for NAME=WxH the size for the scene file named NAME(.json) (repeatable)
  --frames N          timed frames per configuration and round (default 5)
  --rounds R          timing rounds over all configurations, interleaved (default 3)
  --samples N         reference samples per pixel (default 256)
  --max-error E       name the cheapest configuration with mean rel. error <= E (default 0.05)
  --max-ms T          name the most accurate configuration within T ms (default: the scene's)
  --heatmaps WHICH    all | presets (scene, presets, exact) | none (default all)
  --no-cache          recompute the reference (and do not store it)
  --cache DIR         reference cache folder (default: <halfvec cache>/reference)
  --threads N         reference worker threads (default: all cores)
  --visibility on|off the reference traces shadow and environment visibility rays (on) or
                      integrates the shading alone (off); default: on for a scene with a
                      shadowed light, off otherwise (the mode is part of the cache key)
)";

constexpr const char* kDocIntro =
    R"(This file is generated: do not edit it by hand. It is written by

    %s

(`halfvec trade --help`; the code is engine/eval/src/trade.cpp). For every sample scene it renders the
scene under one-at-a-time changes of each accuracy/speed option that applies to it, the presets and
the exact configuration, and measures time and error.

## What "error" is relative to

The truth is the CPU reference renderer (docs/reference.md) run on the engine's own G-buffer with
the **exact configuration** of the scene's material model (`eval::truthSettings` in
halfvec/eval/trade.hpp):

- the scene's D term, Fresnel (Schlick's SG fit replaced by Schlick's pow5, which it
  approximates), diffuse term, energy compensation and specular occlusion: these define the
  material, so rows changing them measure a different material, not an approximation;
- the exact V term for the D term: height-correlated Smith for GGX (Heitz 2014), Walter's
  Beckmann Smith for Beckmann; no Disney roughness remap (a look choice of Karis 2013 for
  analytic lights); the inverse-square falloff (no +1);
- sphere and tube lights integrated over the emitter by Monte Carlo, the environment integrated
  over the hemisphere against the full-resolution environment (not the cube map): so the
  representative-point methods, split-sum IBL, SH9, the env BRDF table or fit and the prefilter
  sample count all count as error.

The reference samples the sky's sun explicitly and combines emitter sampling of sphere and tube
lights with GGX-VNDF directions (multiple importance sampling, docs/reference.md), so glossy
highlights of small emitters and of the sun converge; lit pixels where it still has not converged
(the sum of its channels' standard errors above 25%% of the value) are left out and counted per
scene.

Metrics are over lit (`default_lit`) pixels only, on linear HDR radiance before tone mapping.
The reference integrates lights and the environment; the emissive the engine draws (its G-buffer
pass writes it into the HDR image) is added to it, so that an emissive surface's error is that
of its shading. The headline is the **mean relative error**: the mean over the compared pixels of
the per-pixel relative error |engine - reference| / (reference + 0.01) (summed over the channels),
each pixel counting once whatever its brightness; with it the 99th percentile of the same (p99)
and "worst 0.1%%", the share of the squared error carried by the worst 0.1%% of pixels. Relative
RMSE (RMSE / mean |reference|) stays a column: it weighs pixels by their squared error, so where
"worst 0.1%%" is near 100%% it describes a few pixels (a sun glint in a glossy surface), not the
image. "bias" = the relative RMSE with the reference's own noise removed (sqrt(RMSE^2 -
noise^2)); max abs = the largest channel difference (halfvec/image/metrics.hpp). The reference is a
Monte Carlo estimate: its standard error, expressed as a relative RMSE, is given per scene; rows
whose relative RMSE is within %gx of it are marked `~` and cannot be told apart from the exact
image. "front" marks the Pareto front of (total ms, mean relative error); the heat maps show the
per-pixel relative error on a 0 to %g scale.

Times are GPU timer queries on the machine that ran the command (its renderer string is below);
on llvmpipe (Mesa's CPU rasterizer) they are CPU times shared with other work and noisy: compare
ratios within one scene, not absolute values.
)";

struct SceneRun {
  std::string path;
  eval::TradeReport report;
  std::string dir;
};

std::string stem(const std::string& p) {
  return fs::path(p).stem().string();
}

void writeDoc(const std::string& file, const std::string& command, const std::string& renderer,
              const std::vector<SceneRun>& runs, const eval::TradeOptions& opt) {
  std::ostringstream o;
  char intro[8192];
  std::snprintf(intro, sizeof intro, kDocIntro, command.c_str(), eval::kNoiseFactor,
                double(opt.heatmap_max));
  o << "# Speed/accuracy trade report\n\n" << intro << "\nRenderer: " << renderer << ".\n\n";
  o << "## Presets\n\n" << presetRationale() << "\n";
  o << "Measured (scene's settings: total GPU ms / mean relative error / relative RMSE against "
       "the exact reference; presets and exact: frame time x the scene's settings' with its 95% "
       "interval, \"same\" where it includes 1 / mean relative error / relative RMSE):\n\n";
  o << "| scene | size | scene's settings | fast | balanced | accurate | exact |\n";
  o << "|---|---|---:|---:|---:|---:|---:|\n";
  for (const SceneRun& run : runs) {
    const eval::TradeReport& r = run.report;
    auto cell = [&](const std::string& name) -> std::string {
      for (const eval::TradeRow& row : r.rows) {
        bool match = row.config.name == name;
        for (const auto& a : row.config.aliases) match |= a == name;
        if (!match) continue;
        char buf[128];
        if (name == "scene") {
          std::snprintf(buf, sizeof buf, "%.1f ms / %.4f / %.4f%s", row.total_ms,
                        row.error.mean_rel, row.error.rel_rmse, row.within_noise ? " ~" : "");
        } else {
          std::snprintf(buf, sizeof buf, "%.2fx (%.2f-%.2f)%s / %.4f / %.4f%s", row.cost_ratio,
                        row.cost_lo, row.cost_hi, row.same_cost ? " same" : "", row.error.mean_rel,
                        row.error.rel_rmse, row.within_noise ? " ~" : "");
        }
        return buf;
      }
      return "-";
    };
    o << "| " << stem(run.path) << " | " << r.width << "x" << r.height << " | " << cell("scene")
      << " | " << cell("preset=fast") << " | " << cell("preset=balanced") << " | "
      << cell("preset=accurate") << " | " << cell("exact") << " |\n";
  }
  o << "\n";
  const fs::path doc_dir = fs::absolute(fs::path(file)).parent_path();
  for (const SceneRun& run : runs) {
    std::string prefix = fs::relative(fs::absolute(run.dir), doc_dir).generic_string();
    if (!prefix.empty() && prefix.back() != '/') prefix += "/";
    o << tradeMarkdown(run.report, prefix, 2) << "\n";
  }
  if (fs::absolute(file).has_parent_path()) fs::create_directories(doc_dir);
  writeFileAtomic(file, o.str());
}
// The command line of `halfvec trade`, parsed.
struct TradeArgs {
  std::vector<std::string> scenes;
  std::vector<std::pair<std::string, std::pair<int, int>>> sizes_for;
  std::string report, doc;
  eval::TradeOptions opt;
  bool size_given = false, help = false;
  int visibility = -1;  // --visibility: 1 on, 0 off, -1 per scene (on with a shadowed light)
};

// --max-error, --max-ms: a bound of 0 admits nothing.
double positiveNumber(const std::string& option, const std::string& v) {
  return numberInRange(option, v, 1e-9, HUGE_VAL);
}

TradeArgs parseTradeArgs(const Args& args) {
  TradeArgs t;
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    auto value = [&] { return optionValue(args, i); };
    if (a == "--help" || a == "-h") {
      t.help = true;
      return t;
    } else if (a == "--report") {
      t.report = value();
    } else if (a == "--doc") {
      t.doc = value();
    } else if (a == "--size") {
      parseSize(value(), t.opt.width, t.opt.height);
      t.size_given = true;
    } else if (a == "--size-for") {
      const std::string v = value();
      const size_t eq = v.find('=');
      if (eq == std::string::npos || eq == 0) throw UsageError{"--size-for expects NAME=WxH"};
      int w = 0, h = 0;
      parseSize(v.substr(eq + 1), w, h);
      t.sizes_for.push_back({stem(v.substr(0, eq)), {w, h}});
    } else if (a == "--frames") {
      t.opt.frames = positiveInt(a, value());
    } else if (a == "--rounds") {
      t.opt.rounds = positiveInt(a, value());
    } else if (a == "--samples") {
      t.opt.samples = positiveInt(a, value());
    } else if (a == "--max-error") {
      t.opt.max_error = positiveNumber(a, value());
    } else if (a == "--max-ms") {
      t.opt.max_ms = positiveNumber(a, value());
    } else if (a == "--heatmaps") {
      const std::string v = value();
      if (v == "all") {
        t.opt.heatmaps = eval::TradeOptions::Heatmaps::All;
      } else if (v == "presets") {
        t.opt.heatmaps = eval::TradeOptions::Heatmaps::Presets;
      } else if (v == "none") {
        t.opt.heatmaps = eval::TradeOptions::Heatmaps::None;
      } else {
        throw UsageError{"--heatmaps expects all, presets or none, got '" + v + "'"};
      }
    } else if (a == "--no-cache") {
      t.opt.use_cache = false;
    } else if (a == "--cache") {
      t.opt.cache_dir = value();
    } else if (a == "--threads") {
      t.opt.threads = positiveInt(a, value());
    } else if (a == "--visibility") {
      const std::string v = value();
      if (v != "on" && v != "off")
        throw UsageError{"--visibility expects on or off, got '" + v + "'"};
      t.visibility = v == "on" ? 1 : 0;
    } else if (!a.empty() && a[0] == '-') {
      throw UsageError{"unknown option '" + a + "'"};
    } else {
      t.scenes.push_back(a);
    }
  }
  return t;
}
}  // namespace

int cmdTrade(const Args& args) {
  TradeArgs t = parseTradeArgs(args);
  if (t.help) {
    std::fputs(kHelp, stdout);
    return 0;
  }
  const std::vector<std::string>& scenes = t.scenes;
  const std::string &report = t.report, &doc = t.doc;
  eval::TradeOptions& opt = t.opt;
  if (scenes.empty()) throw UsageError{"no scene file given"};
  if (!doc.empty() && report.empty()) throw UsageError{"--doc needs --report"};
  std::string command = "halfvec trade";
  for (const std::string& a : args) command += " " + a;

  // Load every scene first: a bad file fails before any rendering.
  std::vector<Scene> loaded;
  for (const std::string& s : scenes) loaded.push_back(loadScene(s));
  auto ctx = createHeadlessContext();
  opt.progress = [](const std::string& line) { std::fprintf(stderr, "trade: %s\n", line.c_str()); };
  std::vector<SceneRun> runs;
  using Clock = std::chrono::steady_clock;
  const auto t_start = Clock::now();
  for (size_t k = 0; k < scenes.size(); ++k) {
    eval::TradeOptions o = opt;
    if (!t.size_given) o.height = 0;
    for (const auto& [name, wh] : t.sizes_for) {
      if (name == stem(scenes[k])) o.width = wh.first, o.height = wh.second;
    }
    SceneRun run;
    run.path = scenes[k];
    if (!report.empty())
      run.dir = scenes.size() > 1 ? (fs::path(report) / stem(scenes[k])).string() : report;
    o.report_dir = run.dir;
    const bool shadowed = std::any_of(loaded[k].lights.begin(), loaded[k].lights.end(),
                                      [](const Light& l) { return l.shadows; });
    o.visibility = t.visibility < 0 ? shadowed : t.visibility == 1;
    const double elapsed = std::chrono::duration<double>(Clock::now() - t_start).count();
    std::string left;  // from the scenes done so far
    if (k > 0)
      left = ", about " + std::to_string(int(elapsed / double(k) * double(scenes.size() - k))) +
             " s left";
    std::fprintf(stderr, "trade: scene %zu of %zu: %s, visibility %s (%.0f s elapsed%s)\n", k + 1,
                 scenes.size(), scenes[k].c_str(), o.visibility ? "on" : "off", elapsed,
                 left.c_str());
    run.report = eval::runTrade(loaded[k], o);
    if (run.dir.empty()) {
      std::fputs(tradeMarkdown(run.report, "", 1).c_str(), stdout);
    } else {
      writeTradeReport(run.report, run.dir);
      std::printf("%s: %s/trade.md, trade.csv, plot.png\n", scenes[k].c_str(), run.dir.c_str());
    }
    runs.push_back(std::move(run));
  }
  if (!doc.empty()) {
    writeDoc(doc, command, ctx->renderer(), runs, opt);
    std::printf("wrote %s\n", doc.c_str());
  }
  return 0;
}

}  // namespace hv::app
