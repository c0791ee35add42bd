// The light-pass measurements behind `halfvec bench`'s scaling tables (a)-(c), the breakdown
// table (d) and the shader-tree A/B runs: light_cull and light pass GPU ms over frames, light-pixel
// evaluations, and several renderers' frames interleaved so that the load of a shared machine
// hits them alike. Returns data; the app prints it. Needs a current GL context.
#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "halfvec/render/renderer.hpp"
#include "halfvec/scene/scene.hpp"

namespace hv::eval {

// Side of the bench floor, m.
inline constexpr float kBenchFloorSide = 40.0f;

// The bench floor: a 40 m x 40 m plane seen from above at an angle, no environment, `lights`
// lights of range `range` scattered just above it; type -1: mixed (point, sphere, tube in turn),
// else that hv::LightType for all. The same positions and colors for every call (seed 1).
Scene benchScene(int lights, float range, int type = -1);

// Median (or fastest) light_cull and light pass ms, and the work of one frame.
struct LightPassResult {
  double cull_ms = 0, light_ms = 0;
  size_t evals = 0, lit = 0;  // light-pixel evaluations, lit pixels
};

// One scene's renderer and its per-frame pass times.
struct LightPassRunner {
  render::Renderer r;
  std::vector<double> cull, light;
  std::vector<std::pair<std::string, double>> fastest;  // per pass, the fastest frame's ms
  // Compiles the scene's programs (with `probe`) and renders one warm-up frame.
  LightPassRunner(const Scene& scene, int w, int h,
                  render::LightPassProbe probe = render::LightPassProbe::Shade);
  void frame(int w, int h);
  LightPassResult result(bool fastest = false) const;  // medians, or the fastest frames
};

// Light-pixel evaluations per second, in millions, of `evals` evaluations in `ms` milliseconds.
double mevalsPerSecond(size_t evals, double ms);

// Renders `frames` rounds of one frame of each runner in turn (A B A B ...).
void runInterleaved(std::vector<std::unique_ptr<LightPassRunner>>& runs, int w, int h, int frames);

// `frames` frames of one scene; the medians.
LightPassResult measureLightPass(const Scene& scene, int w, int h, int frames);

// Frames of several scenes alternated (A B A B ...), so that load from other processes on a
// shared machine hits every scene alike; for the ratio checks.
// `pair_ratio`, if given: the median over frames of (light ms of the last scene / light ms of the
// first) within the same round, which cancels drifts of the machine's speed between rounds.
std::vector<LightPassResult> measureLightPassInterleaved(const std::vector<const Scene*>& scenes,
                                                         int w, int h, int frames,
                                                         double* pair_ratio = nullptr);

// The light pass of one scene three times, frames interleaved: the real pass, the FetchOnly probe
// (lists walked, lights fetched, no shading) and the SetupOnly probe (no light loop); see
// render::LightPassProbe. Differences of medians give the time of per-pixel setup, of walking the
// lists and fetching the lights, and of the shading arithmetic; "if only shading" is the
// evaluation rate the pass would reach were the other two free.
struct LightPassBreakdown {
  LightPassResult full, fetch_only, setup_only;  // medians of the real pass and the two probes
  double fetch() const { return fetch_only.light_ms - setup_only.light_ms; }
  double shading() const { return full.light_ms - fetch_only.light_ms; }
  double shadingOnlyRate() const { return mevalsPerSecond(full.evals, shading()); }
};
LightPassBreakdown measureLightPassBreakdown(const Scene& scene, int w, int h, int frames);

}  // namespace hv::eval
