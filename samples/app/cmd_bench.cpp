// `halfvec bench`: light-pass scaling tables and the performance targets of docs/performance.md.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>
#include <memory>
#include <random>
#include <utility>
#include <vector>

#include "app/commands.hpp"
#include "halfvec/eval/light_bench.hpp"
#include "halfvec/platform/context.hpp"
#include "halfvec/render/renderer.hpp"
#include "halfvec/scene/enums.hpp"
#include "halfvec/scene/primitives.hpp"
#include "halfvec/scene/scene_loader.hpp"

namespace hv::app {

// The measurements live in engine/eval (light_bench.hpp); this file parses and prints.
using Result = eval::LightPassResult;
using Runner = eval::LightPassRunner;
using Breakdown = eval::LightPassBreakdown;
using eval::benchScene;
using eval::mevalsPerSecond;
using eval::runInterleaved;

namespace {
constexpr const char* kHelp =
    R"(Usage: halfvec bench [--size WxH] [--frames N] [--max-lights N] [--quick] [--types T]
                    [--lights N [--range R] [--shaders DIR,DIR...]]

Light-pass benchmark on a 40 m x 40 m floor seen from above at an angle, lights of mixed types
(point, sphere, tube) scattered just above it. Prints, per light count from 64 up:
  (a) constant density: the lights' range shrinks as 1/sqrt(N) so a lit pixel sees about the
      same number of lights whatever N;
  (b) fixed scene: the range stays 2 m, so the work grows with N;
the median light_cull and light pass GPU ms over N frames and light-pixel evaluations per
second (evaluations = sum over lit pixels of the lights in the pixel's tile list), then tiled vs
brute force at 1,024 lights, then (c) the 1,024-light row per light type, (d) where the light
pass's time goes at 1,024 lights (see --breakdown), then the three targets of docs/performance.md with the measured value and
met/MISSED (the 256 -> 16384 growth re-measured with the two scenes' frames interleaved, so load
from other processes hits both alike, and judged on the median of the per-round ratios). Light counts: 64, 256, 1024, 4096, 16384 (--quick: 64, 256, 1024, 16384 for (a),
64, 1024, 16384 for (b)), up to --max-lights. --lights N: only the row of table (a) at N lights
(for profiling one change at a time), with --range R the lights' range in m instead. Absolute times are noisy on a shared machine: compare
ratios.

  --types T    the lights' types: mixed (default: point, sphere, tube in turn), point, sphere
               or tube; evaluations per second depend on the type (a tube costs most)
  --shaders D1,D2,...  with --lights: the same scene rendered by one renderer per shader tree
               (HV_SHADER_DIR, a copy of shaders/ with a change), frames interleaved D1 D2 D1 D2
               so that load from other processes hits them alike; prints the median and the
               fastest frame of each (culling and light pass). For A/B tests of shader changes.
  --scene FILE with --shaders: that scene file instead of the bench floor (no --lights needed);
               prints every pass's fastest frame per shader tree

  --breakdown  instead: table (d) alone at 1024 lights (or --lights N), per type: the light pass
               split into per-pixel setup, walking the lists and fetching the lights, and the
               shading arithmetic, each measured by a probe build of the pass with frames
               interleaved (render::LightPassProbe); "if only shading" is the rate the pass
               would reach were setup and fetching free
  --methods    instead: table (e) alone: sphere and tube light pass per method (representative
               point, ltc) at 1024 lights (or --lights N), interleaved, and ltc / it
  --frame      instead: every pass of every sample scene (or of --scene FILE) in ms and as a
               multiple of the floor pass (a compute pass that reads the G-buffer and writes an
               RGBA16F target) timed in the same frames, median over --frames (default 9) with
               its 95% interval; with --shaders DIR,... one set per shader tree, frames
               interleaved; --report FILE.md also writes the table as markdown;
               --vs-brute: instead, each scene's whole frame with tiled culling against the
               same scene with culling brute_force (every pixel loops over every light),
               frames interleaved, as the median ratio with its 95% interval, with each
               scene's lights, their coverage (lights per tile) and what culling auto picks;
               --cull-stages: the culling pass timed per stage (bounds, bin, tiles);
               --settings K=V,K=V (repeatable, with --scene): instead of --shaders, the scene
               as it is and once per set of settings overrides (keys under "settings", JSON
               values, e.g. --settings max_error=0.05 --settings sphere_specular=ltc), frames
               interleaved, each set's passes against its own floor;
               --shadow-sweep: instead, the light pass's (with shadow_resolution half, plus
               the shadow mask pass's) and frame's extra cost over shadows off per filter,
               resolution and number of shadowed lights (the scene's first 1, 2, ...), frames
               interleaved, and the maps rendered meanwhile (0: cached)
  --variants   instead: programs specialized to the scene vs the uber build, GPU ms per pass on
               every scene of samples/scenes, as a markdown table (--quick: at most 640x360)
)";

void printRow(int n, float range, const Result& r) {
  std::printf("%8d %8.2f %10.3f %10.3f %12.1f %14.1f\n", n, range, r.cull_ms, r.light_ms,
              r.lit ? double(r.evals) / double(r.lit) : 0.0, mevalsPerSecond(r.evals, r.light_ms));
  std::fflush(stdout);
}

// --shaders: one renderer per shader tree, frames interleaved; median and fastest pass ms.
int compareShaderTrees(const Scene& scene, const std::vector<std::string>& dirs, int w, int h,
                       int frames, bool scene_file) {
  std::vector<std::unique_ptr<Runner>> runs;
  const char* old = std::getenv("HV_SHADER_DIR");
  const std::string saved = old ? old : "";
  for (const std::string& d : dirs) {
    if (!std::filesystem::is_directory(d)) throw UsageError{"--shaders: no directory '" + d + "'"};
    ::setenv("HV_SHADER_DIR", d.c_str(), 1);
    runs.push_back(std::make_unique<Runner>(scene, w, h));  // compiles from d
  }
  if (old) {
    ::setenv("HV_SHADER_DIR", saved.c_str(), 1);
  } else {
    ::unsetenv("HV_SHADER_DIR");
  }
  runInterleaved(runs, w, h, frames);
  std::printf("%-32s %10s %10s %10s %10s %14s\n", "shader tree", "cull ms", "fastest", "light ms",
              "fastest", "Mevals/s (fast)");
  for (size_t i = 0; i < runs.size(); ++i) {
    if (scene_file) {  // a scene file: every pass, fastest frame
      std::printf("%-32s", dirs[i].c_str());
      for (const auto& [name, ms] : runs[i]->fastest) std::printf(" %s %.3f", name.c_str(), ms);
      std::printf("\n");
      continue;
    }
    const Result med = runs[i]->result(), fast = runs[i]->result(true);
    std::printf("%-32s %10.3f %10.3f %10.3f %10.3f %14.1f\n", dirs[i].c_str(), med.cull_ms,
                fast.cull_ms, med.light_ms, fast.light_ms,
                mevalsPerSecond(fast.evals, fast.light_ms));
  }
  return 0;
}

void breakdownHeader() {
  std::printf("%8s %9s %9s %12s %11s %10s %14s\n", "type", "light ms", "setup ms", "lists+fetch",
              "shading ms", "Mevals/s", "if only shading");
}
void breakdownRow(const char* type, const Breakdown& b) {
  std::printf("%8s %9.2f %9.2f %12.2f %11.2f %10.1f %14.1f\n", type, b.full.light_ms,
              b.setup_only.light_ms, b.fetch(), b.shading(),
              mevalsPerSecond(b.full.evals, b.full.light_ms), b.shadingOnlyRate());
  std::fflush(stdout);
}

void header() {
  std::printf("%8s %8s %10s %10s %12s %14s\n", "lights", "range m", "cull ms", "light ms",
              "lights/px", "Mevals/s");
}

}  // namespace

namespace {
// The command line of `halfvec bench`, parsed.
struct BenchArgs {
  int w = 1280, h = 720, frames = 5, max_lights = 16384, only = 0;
  float only_range = 0.0f;
  bool quick = false, variants = false, show_breakdown = false, frame_mode = false;
  bool vs_brute = false, frames_given = false, methods = false, cull_stages = false;
  bool shadow_sweep = false;
  std::string report;
  int types = -1;  // --types: -1 mixed, else a hv::LightType
  std::vector<std::string> shader_dirs;
  std::vector<std::string> settings_sets;  // --settings: one set of --set overrides each
  std::string scene_path;
  bool help = false;
};

BenchArgs parseBenchArgs(const Args& args) {
  BenchArgs b;
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    auto value = [&] { return optionValue(args, i); };
    if (a == "--help" || a == "-h") {
      b.help = true;
      return b;
    } else if (a == "--size") {
      parseSize(value(), b.w, b.h);
    } else if (a == "--frames") {
      b.frames = positiveInt(a, value());
      b.frames_given = true;
    } else if (a == "--max-lights") {
      b.max_lights = positiveInt(a, value());
    } else if (a == "--lights") {
      b.only = positiveInt(a, value());
    } else if (a == "--range") {
      // A light range in metres, as a scene's (kPositive there): "2m" or 1e300 are refused.
      b.only_range = floatInRange(a, value(), 1e-6f, 1e6f);
    } else if (a == "--quick") {
      b.quick = true;
    } else if (a == "--types") {
      const std::string t = value();
      if (t == "mixed") {
        b.types = -1;
      } else if (t == "point" || t == "sphere" || t == "tube") {
        b.types = t == "point" ? 0 : t == "sphere" ? 1 : 2;  // hv::LightType
      } else {
        throw UsageError{"--types expects mixed, point, sphere or tube, got '" + t + "'"};
      }
    } else if (a == "--scene") {
      b.scene_path = value();
    } else if (a == "--shaders") {
      std::stringstream list(value());
      for (std::string d; std::getline(list, d, ',');) {
        if (!d.empty()) b.shader_dirs.push_back(d);
      }
    } else if (a == "--settings") {
      b.settings_sets.push_back(value());
    } else if (a == "--variants") {
      b.variants = true;
    } else if (a == "--breakdown") {
      b.show_breakdown = true;
    } else if (a == "--methods") {
      b.methods = true;
    } else if (a == "--frame") {
      b.frame_mode = true;
    } else if (a == "--vs-brute") {
      b.vs_brute = true;
    } else if (a == "--cull-stages") {
      b.cull_stages = true;
    } else if (a == "--shadow-sweep") {
      b.shadow_sweep = true;
    } else if (a == "--report") {
      b.report = value();
    } else {
      throw UsageError{"unknown option '" + a + "'"};
    }
  }
  if (b.vs_brute && !b.frame_mode) throw UsageError{"--vs-brute goes with --frame"};
  if (b.cull_stages && !b.frame_mode) throw UsageError{"--cull-stages goes with --frame"};
  if (b.shadow_sweep && !b.frame_mode) throw UsageError{"--shadow-sweep goes with --frame"};
  return b;
}

constexpr float kDensity = 24.0f;  // target lights overlapping a floor point in table (a)
float densityRange(int n) {
  return std::sqrt(kDensity * eval::kBenchFloorSide * eval::kBenchFloorSide /
                   (3.14159265f * float(n)));
}
// The light counts of a table: 64, 256, ... up to --max-lights, or with --quick those given.
std::vector<int> lightCounts(const BenchArgs& b, const std::vector<int>& quick_counts) {
  std::vector<int> v;
  if (b.quick) {
    for (int n : quick_counts) {
      if (n <= b.max_lights) v.push_back(n);
    }
  } else {
    for (int n = 64; n <= b.max_lights; n *= 4) v.push_back(n);
  }
  return v;
}

// Table (d): where the light pass's time goes, per type (mixed first unless --types).
Breakdown breakdownTable(const BenchArgs& b, int n) {
  const int w = b.w, h = b.h, frames = b.frames, types = b.types;
  std::printf(
      "\n(d) where the light pass's time goes, %d lights, constant density (median ms of %d "
      "interleaved frames per probe; light = setup + lists+fetch + shading)\n",
      n, frames);
  breakdownHeader();
  Breakdown mixed;
  for (int t = types < 0 ? -1 : types; t < (types < 0 ? 3 : types + 1); ++t) {
    const Breakdown row =
        eval::measureLightPassBreakdown(benchScene(n, densityRange(n), t), w, h, frames);
    if (t < 0) mixed = row;
    breakdownRow(t < 0 ? "mixed" : t == 0 ? "point" : t == 1 ? "sphere" : "tube", row);
  }
  return mixed;
}

// Tables (a), (b) and (c); returns the rows of (a).
std::vector<std::pair<int, Result>> scalingTables(const BenchArgs& b) {
  const int w = b.w, h = b.h, frames = b.frames, types = b.types;
  std::printf("(a) constant density (about %.0f lights per floor point)\n", kDensity);
  header();
  std::vector<std::pair<int, Result>> table_a;
  for (int n : lightCounts(b, {64, 256, 1024, 16384})) {
    Scene s = benchScene(n, densityRange(n), types);
    table_a.emplace_back(n, eval::measureLightPass(s, w, h, frames));
    printRow(n, densityRange(n), table_a.back().second);
  }
  std::printf("\n(b) fixed scene (range 2 m)\n");
  header();
  for (int n : lightCounts(b, {64, 1024, 16384})) {
    Scene s = benchScene(n, 2.0f, types);
    printRow(n, 2.0f, eval::measureLightPass(s, w, h, frames));
  }
  if (types < 0) {
    // What one evaluation costs per type: a tube light is several times a point light.
    std::printf(
        "\n(c) one light type, 1024 lights, constant density (row (a) at 1024 is the mix)\n");
    std::printf("%8s", "type");
    header();
    for (int t = 0; t < 3; ++t) {
      Scene st = benchScene(1024, densityRange(1024), t);
      std::printf("%8s", t == 0 ? "point" : t == 1 ? "sphere" : "tube");
      printRow(1024, densityRange(1024), eval::measureLightPass(st, w, h, frames));
    }
  }
  return table_a;
}

// Tiled vs brute force at 1,024 lights, then docs/performance.md's targets checked on the numbers
// above.
void benchTargets(const BenchArgs& b, const std::vector<std::pair<int, Result>>& table_a,
                  double shading_only_rate) {
  const int w = b.w, h = b.h, frames = b.frames, types = b.types, max_lights = b.max_lights;
  std::printf("\ntiled vs brute force, 1024 lights, constant-density range\n");
  header();
  const float range = densityRange(1024);
  Scene s = benchScene(1024, range, types);
  const Result tiled = eval::measureLightPass(s, w, h, frames);
  printRow(1024, range, tiled);
  s.settings.culling = Culling::BruteForce;
  const Result brute = eval::measureLightPass(s, w, h, std::min(frames, 2));
  printRow(1024, range, brute);
  const double tiled_total = tiled.cull_ms + tiled.light_ms;
  const double speedup = tiled_total > 0 ? brute.light_ms / tiled_total : 0.0;
  std::printf("speedup (brute light ms / tiled cull+light ms): %.1fx\n", speedup);

  // docs/performance.md's three performance targets, checked on the numbers above.
  std::printf("\ntargets (docs/performance.md)\n");
  std::printf("%-52s %10s %10s  %s\n", "check", "target", "measured", "result");
  auto check = [](const char* what, const char* target, double measured, bool met) {
    std::printf("%-52s %10s %10.2f  %s\n", what, target, measured, met ? "met" : "MISSED");
  };
  double min_rate = 0.0;
  for (size_t i = 0; i < table_a.size(); ++i) {
    const Result& r = table_a[i].second;
    const double rate = mevalsPerSecond(r.evals, r.light_ms);
    min_rate = i == 0 ? rate : std::min(min_rate, rate);
  }
  if (!table_a.empty()) {
    check("light-pixel evals/s, M (slowest row of (a))", ">= 300", min_rate, min_rate >= 300.0);
    if (shading_only_rate > 0.0) {
      std::printf("  shading arithmetic alone, mixed, 1024 lights (d): %.1f M evals/s\n",
                  shading_only_rate);
    }
  }
  if (max_lights >= 16384) {
    // Re-measured interleaved (see eval::measureLightPassInterleaved): the table rows above ran
    // minutes apart.
    const Scene s256 = benchScene(256, densityRange(256), types);
    const Scene s16k = benchScene(16384, densityRange(16384), types);
    // Judged on the median of the per-round ratios: each round renders one frame of each scene
    // back to back, so a slow stretch of the machine (other processes, the host) hits both.
    double growth = 0.0;
    const auto pair =
        eval::measureLightPassInterleaved({&s256, &s16k}, w, h, std::max(frames, 15), &growth);
    check("light pass ms growth 256 -> 16384 lights, (a)*", "<= 1.5x", growth, growth <= 1.5);
    std::printf(
        "  * median of per-round ratios over %d interleaved rounds; median light ms %.1f (256) vs "
        "%.1f (16384); %.1f vs %.1f lights/px\n",
        std::max(frames, 15), pair[0].light_ms, pair[1].light_ms,
        pair[0].lit ? double(pair[0].evals) / double(pair[0].lit) : 0.0,
        pair[1].lit ? double(pair[1].evals) / double(pair[1].lit) : 0.0);
  } else {
    std::printf("%-52s %10s %10s  %s\n", "light pass ms growth 256 -> 16384 lights, (a)", "<= 1.5x",
                "-", "not run (needs --max-lights >= 16384)");
  }
  check("tiled speedup over brute force, 1024 lights", ">= 20x", speedup, speedup >= 20.0);
}

}  // namespace

int cmdBench(const Args& args) {
  const BenchArgs b = parseBenchArgs(args);
  if (b.help) {
    std::fputs(kHelp, stdout);
    return 0;
  }
  if (b.frame_mode) {
    FrameBenchOptions o;
    o.width = b.w;
    o.height = b.h;
    if (b.frames_given) o.frames = b.frames;
    o.scene = b.scene_path;
    o.shader_dirs = b.shader_dirs;
    o.settings_sets = b.settings_sets;
    o.report = b.report;
    o.vs_brute = b.vs_brute;
    o.cull_stages = b.cull_stages;
    o.shadow_sweep = b.shadow_sweep;
    return benchFrame(o);
  }
  if (b.variants)
    return b.quick ? benchVariants(std::min(b.w, 640), std::min(b.h, 360), b.frames)
                   : benchVariants(b.w, b.h, b.frames);
  auto ctx = createHeadlessContext();
  std::printf("renderer: %s, %dx%d, median of %d frames\n\n", ctx->renderer().c_str(), b.w, b.h,
              b.frames);
  if (!b.scene_path.empty()) {
    if (b.shader_dirs.empty()) throw UsageError{"--scene goes with --shaders"};
    Scene sc = loadScene(b.scene_path);
    return compareShaderTrees(sc, b.shader_dirs, b.w, b.h, b.frames, true);
  }
  if (b.show_breakdown) {
    if (!b.shader_dirs.empty()) throw UsageError{"--breakdown does not take --shaders"};
    breakdownTable(b, b.only > 0 ? b.only : 1024);
    return 0;
  }
  auto methods = [&](int n) {
    methodsTable([&](LightType t) { return benchScene(n, densityRange(n), int(t)); }, n, b.w, b.h,
                 b.frames);
  };
  if (b.methods) {
    methods(b.only > 0 ? b.only : 1024);
    return 0;
  }
  if (b.only > 0) {
    std::printf("(a) constant density (about %.0f lights per floor point)\n", kDensity);
    header();
    const float r = b.only_range > 0.0f ? b.only_range : densityRange(b.only);
    Scene s = benchScene(b.only, r, b.types);
    if (!b.shader_dirs.empty())
      return compareShaderTrees(s, b.shader_dirs, b.w, b.h, b.frames, false);
    printRow(b.only, r, eval::measureLightPass(s, b.w, b.h, b.frames));
    return 0;
  }
  const std::vector<std::pair<int, Result>> table_a = scalingTables(b);
  double shading_only_rate = 0.0;
  if (b.types < 0) shading_only_rate = breakdownTable(b, 1024).shadingOnlyRate();
  if (b.types < 0) methods(1024);
  benchTargets(b, table_a, shading_only_rate);
  return 0;
}

}  // namespace hv::app
