// `halfvec bench --variants`: programs specialized to the scene (docs/variants.md) against the
// uber build, per pass, on every scene of samples/scenes.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>

#include "app/commands.hpp"
#include "halfvec/platform/context.hpp"
#include "halfvec/render/renderer.hpp"
#include "halfvec/scene/scene_loader.hpp"

namespace hv::app {

namespace {

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}

struct Side {
  std::unique_ptr<render::Renderer> r;
  std::map<std::string, std::vector<double>> ms;  // pass -> per-frame GPU ms
  std::vector<std::string> order;                 // pass order
  size_t programs = 0;
  double compile_ms = 0.0;
};

void record(Side& s, const render::FrameStats& st) {
  for (auto& [name, ms] : st.passes) {
    if (!s.ms.count(name)) s.order.push_back(name);
    s.ms[name].push_back(ms);
  }
}

}  // namespace

int benchVariants(int w, int h, int frames) {
  auto ctx = createHeadlessContext();
  std::printf(
      "renderer: %s, %dx%d, median of %d frames (specialized and uber frames interleaved; "
      "binary cache off)\n",
      ctx->renderer().c_str(), w, h, frames);
  std::printf(
      "Absolute times are noisy on a shared machine: compare the ratios. Compile times "
      "may come from the driver's own shader cache (Mesa: MESA_SHADER_CACHE_DISABLE=true "
      "for cold compiles).\n\n");
  std::vector<std::filesystem::path> files;
  for (const auto& e : std::filesystem::directory_iterator(HV_SAMPLES_DIR)) {
    if (e.path().extension() == ".json") files.push_back(e.path());
  }
  std::sort(files.begin(), files.end());
  std::printf("| scene | pass | specialized ms | uber ms | uber / specialized |\n");
  std::printf("| --- | --- | ---: | ---: | ---: |\n");
  std::vector<std::string> notes;
  for (const auto& f : files) {
    const std::string name = f.stem().string();
    Scene spec_scene, uber_scene;
    try {
      spec_scene = loadScene(f.string(), {});
      uber_scene = loadScene(f.string(), {"settings.uber=true"});
    } catch (const std::exception& e) {
      notes.push_back(name + ": skipped (" + e.what() + ")");
      continue;
    }
    Side spec, uber;
    spec.r = std::make_unique<render::Renderer>();
    uber.r = std::make_unique<render::Renderer>();
    for (Side* s : {&spec, &uber}) s->r->programs().setBinaryCacheDir({});
    spec.r->setScene(spec_scene);
    uber.r->setScene(uber_scene);
    spec.r->render(w, h);  // warm up: compiles the variants
    uber.r->render(w, h);
    for (Side* s : {&spec, &uber}) {
      const render::Manifest m = s->r->manifest();
      s->programs = m.programs.size();
      for (const auto& v : m.programs) s->compile_ms += v.compile_ms + v.link_ms;
    }
    for (int i = 0; i < frames; ++i) {
      record(spec, spec.r->render(w, h));
      record(uber, uber.r->render(w, h));
    }
    // Image agreement: largest 8-bit difference of the tone-mapped images.
    const ImageRGBA8 a = spec.r->readLdr(), b = uber.r->readLdr();
    int max_diff = 0;
    for (size_t i = 0; i < a.px.size(); ++i) {
      max_diff = std::max(max_diff, std::abs(int(a.px[i]) - int(b.px[i])));
    }
    double st = 0.0, ut = 0.0;
    for (const auto& pass : spec.order) {
      const double sm = median(spec.ms[pass]), um = median(uber.ms[pass]);
      st += sm;
      ut += um;
      std::printf("| %s | %s | %.3f | %.3f | %.2f |\n", name.c_str(), pass.c_str(), sm, um,
                  sm > 0 ? um / sm : 0.0);
    }
    std::printf("| %s | **total** | %.3f | %.3f | %.2f |\n", name.c_str(), st, ut,
                st > 0 ? ut / st : 0.0);
    notes.push_back(name + ": " + spec.r->variantKey().text() + "; programs " +
                    std::to_string(spec.programs) + " specialized (" +
                    std::to_string(int(std::lround(spec.compile_ms))) + " ms compile+link) vs " +
                    std::to_string(uber.programs) + " uber (" +
                    std::to_string(int(std::lround(uber.compile_ms))) +
                    " ms); max 8-bit difference of the images: " + std::to_string(max_diff));
    std::fflush(stdout);
  }
  std::printf("\n");
  for (const auto& n : notes) std::printf("- %s\n", n.c_str());
  return 0;
}

}  // namespace hv::app
