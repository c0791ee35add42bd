#include "halfvec/eval/light_methods.hpp"

#include <algorithm>
#include <memory>

#include "halfvec/render/renderer.hpp"

namespace hv::eval {

std::vector<TimedMethod> lightMethodsFor(LightType type, const RenderSettings& base) {
  std::vector<TimedMethod> m;
  if (type == LightType::Point) return m;
  m.push_back({"lists + fetch only (probe)", base, true});
  m.push_back({"representative_point (default)", base, false});
  RenderSettings ltc = base;
  if (type == LightType::Sphere) {
    ltc.sphere_specular = SphereSpecular::Ltc;
    m.push_back({"ltc", ltc, false});
  } else {
    ltc.tube_specular = TubeSpecular::Ltc;
    m.push_back({"ltc specular", ltc, false});
    ltc.tube_diffuse = TubeDiffuse::Ltc;
    m.push_back({"ltc specular + ltc diffuse", ltc, false});
  }
  return m;
}

std::vector<MethodTiming> timeLightMethods(const Scene& scene,
                                           const std::vector<TimedMethod>& methods, int width,
                                           int height, int frames) {
  struct Run {
    Scene scene;
    render::Renderer r;
    std::vector<double> light_ms;
  };
  std::vector<std::unique_ptr<Run>> runs;
  for (const TimedMethod& m : methods) {
    auto run = std::make_unique<Run>();
    run->scene = scene;
    run->scene.settings = m.settings;
    render::DebugOptions debug;
    if (m.fetch_only) debug.light_probe = render::LightPassProbe::FetchOnly;
    debug.finish_each_pass = true;  // as bench: no pass timed with the previous one's raster
    run->r.setDebugOptions(debug);
    run->r.setScene(run->scene);
    run->r.render(width, height);  // warm-up: compiles the programs
    runs.push_back(std::move(run));
  }
  for (int f = 0; f < frames; ++f) {
    for (auto& run : runs) {
      for (const auto& [name, ms] : run->r.render(width, height).passes) {
        if (name == "light") run->light_ms.push_back(ms);
      }
    }
  }
  std::vector<MethodTiming> out;
  for (size_t i = 0; i < runs.size(); ++i) {
    MethodTiming t;
    t.name = methods[i].name;
    std::vector<double> v = runs[i]->light_ms;
    if (!v.empty()) {
      std::nth_element(v.begin(), v.begin() + long(v.size() / 2), v.end());
      t.light_ms = v[v.size() / 2];
    }
    t.evaluations = runs[i]->r.lightWork().light_pixel_evaluations;
    t.mevals_per_s = t.light_ms > 0.0 ? double(t.evaluations) / t.light_ms * 1e-3 : 0.0;
    out.push_back(t);
  }
  return out;
}

}  // namespace hv::eval
