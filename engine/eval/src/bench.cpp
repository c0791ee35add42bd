#include "halfvec/eval/bench.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>

namespace hv::eval {

MedianInterval medianInterval(std::vector<double> v, double confidence) {
  MedianInterval m;
  m.n = v.size();
  if (v.empty()) return m;
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  m.median = n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
  // P(B < j) for B ~ binomial(n, 1/2): the chance that fewer than j values lie below the median.
  // [x_(j), x_(n+1-j)] (1-based) covers the median with probability 1 - 2 P(B < j).
  auto tail = [n](size_t j) {
    double p = 0.0, c = 1.0;  // c = C(n, k)
    for (size_t k = 0; k < j; ++k) {
      p += c;
      c = c * double(n - k) / double(k + 1);
    }
    return p * std::pow(0.5, double(n));
  };
  size_t j = 1;
  while (j + 1 <= (n + 1) / 2 && 1.0 - 2.0 * tail(j + 1) >= confidence) ++j;
  m.lo = v[j - 1];
  m.hi = v[n - j];
  m.coverage = 1.0 - 2.0 * tail(j);
  return m;
}

void PassSeries::add(const render::FrameStats& stats) {
  for (const auto& [name, ms_] : stats.passes) {
    if (!ms.count(name)) order.push_back(name);
    ms[name].push_back(ms_);
  }
}

const std::vector<double>& PassSeries::of(const std::string& pass) const {
  static const std::vector<double> none;
  const auto it = ms.find(pass);
  return it == ms.end() ? none : it->second;
}

double PassSeries::median(const std::string& pass) const {
  return medianInterval(of(pass)).median;
}

double PassSeries::fastest(const std::string& pass) const {
  const auto& v = of(pass);
  return v.empty() ? 0.0 : *std::min_element(v.begin(), v.end());
}

FrameRunner::FrameRunner(const Scene& scene, int width, int height,
                         const render::DebugOptions& debug)
    : width_(width), height_(height) {
  renderer_.setDebugOptions(debug);
  renderer_.setScene(scene);
  renderer_.render(width_, height_);  // warm-up: compiles the variants
}

void FrameRunner::frame() {
  series_.add(renderer_.render(width_, height_));
}

void runInterleaved(const std::vector<std::unique_ptr<FrameRunner>>& runners, int frames) {
  for (int f = 0; f < frames; ++f) {
    for (const auto& r : runners) r->frame();
  }
}

namespace {
constexpr const char* kFloor = "floor";

FrameCost frameCostOf(const PassSeries& s, const std::string& name, int w, int h) {
  FrameCost c;
  c.scene = name;
  c.width = w;
  c.height = h;
  const std::vector<double>& floor = s.of(kFloor);
  c.frames = int(floor.size());
  c.floor_ms = s.median(kFloor);
  auto ratios = [&](const std::vector<double>& ms) {
    std::vector<double> r;
    for (size_t i = 0; i < std::min(ms.size(), floor.size()); ++i) {
      if (floor[i] > 0.0) r.push_back(ms[i] / floor[i]);
    }
    return medianInterval(r);
  };
  std::vector<double> total(floor.size(), 0.0);
  for (const std::string& pass : s.order) {
    if (pass == kFloor) continue;
    const std::vector<double>& ms = s.of(pass);
    c.passes.push_back({pass, s.median(pass), ratios(ms)});
    for (size_t i = 0; i < std::min(ms.size(), total.size()); ++i) total[i] += ms[i];
  }
  c.frame = {"frame", medianInterval(total).median, ratios(total)};
  return c;
}

render::DebugOptions withFloor() {
  render::DebugOptions d;
  d.floor_pass = true;
  d.finish_each_pass = true;  // each pass timed whole, none charged for the previous one's raster
  return d;
}
}  // namespace

FrameCost measureFrameCost(const Scene& scene, const std::string& name, int width, int height,
                           int frames, bool cull_stages) {
  render::DebugOptions d = withFloor();
  d.cull_stage_timers = cull_stages;
  FrameRunner run(scene, width, height, d);
  for (int f = 0; f < frames; ++f) run.frame();
  return frameCostOf(run.series(), name, width, height);
}

std::vector<FrameCost> measureFrameCostTrees(const Scene& scene,
                                             const std::vector<std::string>& dirs, int width,
                                             int height, int frames, bool cull_stages) {
  std::vector<std::unique_ptr<FrameRunner>> runs;
  render::DebugOptions debug = withFloor();
  debug.cull_stage_timers = cull_stages;
  const char* old = std::getenv("HV_SHADER_DIR");
  const std::string saved = old ? old : "";
  for (const std::string& d : dirs) {
    if (!std::filesystem::is_directory(d)) {
      throw std::invalid_argument("shader tree '" + d + "' is not a directory");
    }
    ::setenv("HV_SHADER_DIR", d.c_str(), 1);
    runs.push_back(std::make_unique<FrameRunner>(scene, width, height, debug));
  }
  if (old) {
    ::setenv("HV_SHADER_DIR", saved.c_str(), 1);
  } else {
    ::unsetenv("HV_SHADER_DIR");
  }
  runInterleaved(runs, frames);
  std::vector<FrameCost> out;
  for (size_t i = 0; i < runs.size(); ++i) {
    out.push_back(frameCostOf(runs[i]->series(), dirs[i], width, height));
  }
  return out;
}

std::vector<FrameCost> measureFrameCostScenes(const std::vector<Scene>& scenes,
                                              const std::vector<std::string>& names, int width,
                                              int height, int frames) {
  std::vector<std::unique_ptr<FrameRunner>> runs;
  for (const Scene& s : scenes) {
    runs.push_back(std::make_unique<FrameRunner>(s, width, height, withFloor()));
  }
  runInterleaved(runs, frames);
  std::vector<FrameCost> out;
  for (size_t i = 0; i < runs.size(); ++i) {
    out.push_back(frameCostOf(runs[i]->series(), names.at(i), width, height));
  }
  return out;
}

TiledVsBrute measureTiledVsBruteForce(const Scene& scene, const std::string& name, int width,
                                      int height, int frames) {
  Scene tiled = scene, brute = scene;  // the renderers keep pointers: both outlive them
  tiled.settings.culling = Culling::Tiled;
  brute.settings.culling = Culling::BruteForce;
  render::DebugOptions d;
  d.finish_each_pass = true;  // as bench --frame: each pass timed whole
  std::vector<std::unique_ptr<FrameRunner>> runs;
  runs.push_back(std::make_unique<FrameRunner>(tiled, width, height, d));
  runs.push_back(std::make_unique<FrameRunner>(brute, width, height, d));
  runInterleaved(runs, frames);
  auto totals = [](const PassSeries& s) {
    std::vector<double> t;
    for (const std::string& pass : s.order) {
      const std::vector<double>& ms = s.of(pass);
      if (t.size() < ms.size()) t.resize(ms.size(), 0.0);
      for (size_t i = 0; i < ms.size(); ++i) t[i] += ms[i];
    }
    return t;
  };
  const std::vector<double> a = totals(runs[0]->series()), b = totals(runs[1]->series());
  std::vector<double> ratios;
  for (size_t i = 0; i < std::min(a.size(), b.size()); ++i) {
    if (b[i] > 0.0) ratios.push_back(a[i] / b[i]);
  }
  TiledVsBrute r;
  r.scene = name;
  r.frames = frames;
  r.tiled_ms = medianInterval(a).median;
  r.brute_ms = medianInterval(b).median;
  r.ratio = medianInterval(ratios);
  return r;
}

}  // namespace hv::eval
