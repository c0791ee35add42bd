// Measurements behind `halfvec bench`: GPU time per pass from timer queries, frames of several
// renderers interleaved so that the load of a shared machine hits them alike, and ratios taken
// within one frame or one round. Returns data; the app prints it. Needs a current GL context.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "halfvec/render/renderer.hpp"
#include "halfvec/scene/scene.hpp"

namespace hv::eval {

// The median of `v` with a distribution-free confidence interval for it: order statistics
// x_(j) <= median <= x_(n+1-j) with j the largest rank whose binomial(n, 1/2) tail keeps the
// coverage >= `confidence` (with few values, [min, max] and its smaller coverage, stated in
// `coverage`). Makes no assumption on the distribution, so a machine's occasional slow frame
// widens the interval but cannot drag the median.
struct MedianInterval {
  double median = 0.0, lo = 0.0, hi = 0.0;
  double coverage = 0.0;  // probability that [lo, hi] holds the true median
  size_t n = 0;
  bool contains(double x) const { return lo <= x && x <= hi; }
};
MedianInterval medianInterval(std::vector<double> values, double confidence = 0.95);

// Per-pass GPU ms of consecutive frames of one renderer.
struct PassSeries {
  std::vector<std::string> order;                 // pass names, in frame order
  std::map<std::string, std::vector<double>> ms;  // per pass, one value per frame
  void add(const render::FrameStats& stats);
  const std::vector<double>& of(const std::string& pass) const;  // empty if never run
  double median(const std::string& pass) const;
  double fastest(const std::string& pass) const;
};

// One scene rendered by one renderer, frame after frame.
class FrameRunner {
 public:
  FrameRunner(const Scene& scene, int width, int height, const render::DebugOptions& debug = {});
  void frame();  // renders one frame and records its pass times
  render::Renderer& renderer() { return renderer_; }
  const PassSeries& series() const { return series_; }

 private:
  render::Renderer renderer_;
  int width_, height_;
  PassSeries series_;
};

// Renders `frames` rounds of one frame of each runner in turn (A B C A B C ...).
void runInterleaved(const std::vector<std::unique_ptr<FrameRunner>>& runners, int frames);

// ---- bench --frame
// ------------------------------------------------------------------------------- Every pass of a
// scene's frame as a multiple of the floor pass (render::DebugOptions::floor_pass) timed in the
// same frames: the median over frames of (pass ms / floor ms of that frame), with its interval.
struct PassCost {
  std::string pass;
  double ms = 0.0;             // median GPU ms
  MedianInterval floor_ratio;  // per-frame pass / floor
};
struct FrameCost {
  std::string scene;  // a name for the table
  int width = 0, height = 0, frames = 0;
  double floor_ms = 0.0;         // median GPU ms of the floor pass
  std::vector<PassCost> passes;  // the frame's passes in order (the floor not among them)
  PassCost frame;                // their sum per frame ("frame")
};
// Renders `frames` frames after a warm-up frame; with `cull_stages`, the culling timed per stage
// (render::DebugOptions::cull_stage_timers).
FrameCost measureFrameCost(const Scene& scene, const std::string& name, int width, int height,
                           int frames, bool cull_stages = false);
// The same scene rendered with one renderer per shader tree (each a copy of shaders/ with a
// change, compiled through HV_SHADER_DIR), frames interleaved: one FrameCost per tree, named by
// its folder. For A/B tests of shader changes against the floor.
std::vector<FrameCost> measureFrameCostTrees(const Scene& scene,
                                             const std::vector<std::string>& dirs, int width,
                                             int height, int frames, bool cull_stages = false);
// Several scenes (one scene with different settings), one renderer each, frames interleaved: one
// FrameCost per scene, named by `names`.
std::vector<FrameCost> measureFrameCostScenes(const std::vector<Scene>& scenes,
                                              const std::vector<std::string>& names, int width,
                                              int height, int frames);
// ---- bench --frame --vs-brute
// The scene's whole frame with tiled culling against the same scene with Culling::BruteForce
// (no culling pass; the light pass loops over every light at every pixel: a minimal brute-force
// deferred renderer with the same G-buffer, shading and ambient), frames interleaved.
struct TiledVsBrute {
  std::string scene;
  int frames = 0;
  double tiled_ms = 0.0, brute_ms = 0.0;  // median whole-frame GPU ms
  MedianInterval ratio;                   // per round: tiled frame ms / brute-force frame ms
};
TiledVsBrute measureTiledVsBruteForce(const Scene& scene, const std::string& name, int width,
                                      int height, int frames);

}  // namespace hv::eval
