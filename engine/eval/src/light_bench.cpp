#include "halfvec/eval/light_bench.hpp"

#include <algorithm>
#include <memory>
#include <random>

#include "halfvec/scene/primitives.hpp"

namespace hv::eval {

constexpr float kFloor = kBenchFloorSide;

Scene benchScene(int lights, float range, int type) {
  Scene s;
  s.camera.position = {0.0f, 18.0f, 22.0f};
  s.camera.target = {0.0f, 0.0f, 0.0f};
  s.camera.fov_y_deg = 60.0f;
  s.environment.kind = EnvironmentKind::None;
  Material m;
  m.base_color = glm::vec3(0.7f);
  m.roughness = 0.5f;
  s.materials.push_back(m);
  s.meshes.push_back(makePlane(kFloor, kFloor));
  Object o;
  o.meshes = {0};
  s.objects.push_back(o);
  std::mt19937 rng(1);
  std::uniform_real_distribution<float> u(-kFloor / 2, kFloor / 2), h(0.1f, 0.6f), c(0.3f, 1.0f);
  for (int i = 0; i < lights; ++i) {
    Light l;
    l.type = static_cast<LightType>(type < 0 ? i % 3 : type);
    l.position = {u(rng), h(rng), u(rng)};
    l.color = {c(rng), c(rng), c(rng)};
    l.intensity = 1.0f;
    l.range = range;
    l.radius = l.type == LightType::Point ? 0.0f : 0.05f;
    l.length = l.type == LightType::Tube ? 0.3f : 0.0f;
    l.axis = glm::normalize(glm::vec3(c(rng) - 0.65f, 0.0f, c(rng) - 0.65f) + glm::vec3(1e-3f));
    s.lights.push_back(l);
  }
  return s;
}

LightPassRunner::LightPassRunner(const Scene& scene, int w, int h, render::LightPassProbe probe) {
  render::DebugOptions debug;
  debug.light_probe = probe;
  debug.finish_each_pass = true;  // no pass timed with the previous one's deferred raster
  r.setDebugOptions(debug);
  r.setScene(scene);
  r.render(w, h);  // warm up: compiles the variants
}

void LightPassRunner::frame(int w, int h) {
  const auto st = r.render(w, h);
  for (auto& [name, ms] : st.passes) {
    if (name == "light_cull") cull.push_back(ms);
    if (name == "light") light.push_back(ms);
    auto it = std::find_if(fastest.begin(), fastest.end(),
                           [&](const auto& p) { return p.first == name; });
    if (it == fastest.end()) {
      fastest.emplace_back(name, ms);
    } else {
      it->second = std::min(it->second, ms);
    }
  }
}

LightPassResult LightPassRunner::result(bool fastest_frame) const {
  auto median = [fastest_frame](std::vector<double> v) {
    if (v.empty()) return 0.0;
    if (fastest_frame) return *std::min_element(v.begin(), v.end());
    std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
    return v[v.size() / 2];
  };
  LightPassResult res;
  res.cull_ms = median(cull);
  res.light_ms = median(light);
  const auto work = r.lightWork();
  res.evals = work.light_pixel_evaluations;
  res.lit = work.lit_pixels;
  return res;
}

double mevalsPerSecond(size_t evals, double ms) {
  return ms > 0 ? double(evals) / ms * 1e-3 : 0.0;
}

void runInterleaved(std::vector<std::unique_ptr<LightPassRunner>>& runs, int w, int h, int frames) {
  for (int f = 0; f < frames; ++f) {
    for (auto& run : runs) run->frame(w, h);
  }
}

LightPassResult measureLightPass(const Scene& scene, int w, int h, int frames) {
  LightPassRunner run(scene, w, h);
  for (int f = 0; f < frames; ++f) run.frame(w, h);
  return run.result();
}

std::vector<LightPassResult> measureLightPassInterleaved(const std::vector<const Scene*>& scenes,
                                                         int w, int h, int frames,
                                                         double* pair_ratio) {
  std::vector<std::unique_ptr<LightPassRunner>> runs;
  for (const Scene* s : scenes) runs.push_back(std::make_unique<LightPassRunner>(*s, w, h));
  runInterleaved(runs, w, h, frames);
  if (pair_ratio) {
    std::vector<double> ratios;
    const auto& a = runs.front()->light;
    const auto& b = runs.back()->light;
    for (size_t i = 0; i < std::min(a.size(), b.size()); ++i) {
      if (a[i] > 0) ratios.push_back(b[i] / a[i]);
    }
    std::sort(ratios.begin(), ratios.end());
    *pair_ratio = ratios.empty() ? 0.0 : ratios[ratios.size() / 2];
  }
  std::vector<LightPassResult> out;
  for (auto& run : runs) out.push_back(run->result());
  return out;
}

LightPassBreakdown measureLightPassBreakdown(const Scene& scene, int w, int h, int frames) {
  using Probe = render::LightPassProbe;
  std::vector<std::unique_ptr<LightPassRunner>> runs;
  for (Probe p : {Probe::Shade, Probe::FetchOnly, Probe::SetupOnly}) {
    runs.push_back(std::make_unique<LightPassRunner>(scene, w, h, p));
  }
  runInterleaved(runs, w, h, frames);
  return {runs[0]->result(), runs[1]->result(), runs[2]->result()};
}

}  // namespace hv::eval
