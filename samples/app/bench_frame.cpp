// `halfvec bench --frame`: every pass of every sample scene (or of --scene FILE) as a multiple of
// the floor pass timed in the same frames (halfvec/eval/bench.hpp); with --shaders, one column
// set per shader tree, frames interleaved.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "app/bench_report.hpp"
#include "app/commands.hpp"
#include "halfvec/core/output_files.hpp"
#include "halfvec/eval/bench.hpp"
#include "halfvec/platform/context.hpp"
#include "halfvec/render/renderer.hpp"
#include "halfvec/render/variant_key.hpp"
#include "halfvec/scene/model_scene.hpp"
#include "halfvec/scene/render_settings.hpp"
#include "halfvec/scene/scene_loader.hpp"

namespace hv::app {

namespace {
void printCost(const eval::FrameCost& c) {
  std::printf("%s (%dx%d, %d frames; floor %.3g ms)\n", c.scene.c_str(), c.width, c.height,
              c.frames, c.floor_ms);
  std::printf("  %-12s %9s %9s  %s\n", "pass", "ms", "x floor", "95% interval of x floor");
  auto row = [](const eval::PassCost& p) {
    std::printf("  %-12s %9.2f %9.2f  %.2f - %.2f\n", p.pass.c_str(), p.ms, p.floor_ratio.median,
                p.floor_ratio.lo, p.floor_ratio.hi);
  };
  for (const eval::PassCost& p : c.passes) row(p);
  row(c.frame);
  std::fflush(stdout);
}

// The shadows' cost (docs/lights.md, "Shadows"), for a scene with shadowed lights: three
// renderers of it, frames interleaved: as it is (the maps cached since the warm-up frame),
// without shadows (no shadow code), and with every shadowed light moved by 1e-4 m each frame
// (its maps rendered again every frame). Each ratio is per frame, against that frame's floor.
void printShadowCost(const Scene& scene, int w, int h, int frames) {
  Scene none = scene, moving = scene;
  size_t shadowed = 0;
  for (Light& l : none.lights) {
    shadowed += l.shadows;
    l.shadows = false;
  }
  if (shadowed == 0) return;
  render::DebugOptions d;
  d.floor_pass = true;
  d.finish_each_pass = true;
  render::Renderer cached, plain, rerendered;
  const Scene* scenes[3] = {&scene, &none, &moving};
  render::Renderer* rs[3] = {&cached, &plain, &rerendered};
  for (int i = 0; i < 3; ++i) {
    rs[i]->setDebugOptions(d);
    rs[i]->setScene(*scenes[i]);
    rs[i]->render(w, h);  // warm-up: compiles, renders the maps
  }
  eval::PassSeries s[3];
  size_t faces = 0, maps = 0;
  for (int f = 0; f < frames; ++f) {
    for (Light& l : moving.lights) {
      if (l.shadows) l.position.x += (f % 2 ? -1e-4f : 1e-4f);
    }
    rerendered.updateLights();
    for (int i = 0; i < 3; ++i) {
      const render::FrameStats st = rs[i]->render(w, h);
      if (i == 2) faces = 6 * st.shadow_maps_rendered;
      if (i == 0) maps = st.shadow_maps;
      s[i].add(st);
    }
  }
  auto total = [](const eval::PassSeries& p, size_t k) {
    double t = 0.0;
    for (const std::string& pass : p.order) {
      if (pass != "floor" && k < p.of(pass).size()) t += p.of(pass)[k];
    }
    return t;
  };
  std::vector<double> lookup, frame, pass, per_face;
  for (size_t k = 0; k < size_t(frames); ++k) {
    const double floor = s[0].of("floor").at(k), floor2 = s[2].of("floor").at(k);
    lookup.push_back((s[0].of("light").at(k) - s[1].of("light").at(k)) / floor);
    frame.push_back((total(s[0], k) - total(s[1], k)) / floor);
    pass.push_back(s[2].of("shadows").at(k) / floor2);
    per_face.push_back(s[2].of("shadows").at(k) / double(std::max<size_t>(faces, 1)) /
                       s[2].of("gbuffer").at(k));
  }
  auto row = [](const char* what, const std::vector<double>& v, const char* unit) {
    const eval::MedianInterval m = eval::medianInterval(v);
    std::printf("  %-48s %7.2f%s  (%.2f - %.2f)\n", what, m.median, unit, m.lo, m.hi);
  };
  std::printf(
      "  shadows: %zu shadowed light%s, %zu map%s; interleaved with the scene without "
      "shadows and with the maps re-rendered every frame\n",
      shadowed, shadowed == 1 ? "" : "s", maps, maps == 1 ? "" : "s");
  row("shadow lookup in the light pass (cached maps)", lookup, "x floor");
  row("whole frame, cached maps, over no shadows", frame, "x floor");
  row("shadow-map pass, all maps re-rendered", pass, "x floor");
  row("shadow-map pass per cube face, over the G-buffer pass", per_face, "x");
  std::printf(
      "  (light pass %.2f ms with shadows, %.2f ms without; shadow-map pass %.2f ms for "
      "%zu faces; G-buffer %.2f ms)\n",
      s[0].median("light"), s[1].median("light"), s[2].median("shadows"), faces,
      s[2].median("gbuffer"));
  std::fflush(stdout);
}

// --shadow-sweep (docs/lights.md, "Shadows"): one renderer of the scene with shadows off and one
// per filter and number k of shadowed lights (the first k of the scene's, the others off), all
// frames interleaved so that the load hits them alike. Per configuration: the light pass's and
// the whole frame's extra ms over the scene without shadows, per frame over that frame's floor,
// and the shadow maps rendered in the measured frames (0: the cached maps were reused).
void printShadowSweep(const Scene& scene, int w, int h, int frames) {
  std::vector<size_t> shadowed;
  for (size_t i = 0; i < scene.lights.size(); ++i) {
    if (scene.lights[i].shadows) shadowed.push_back(i);
  }
  if (shadowed.empty()) {
    std::printf("  no shadowed light: nothing to sweep\n");
    return;
  }
  struct Config {
    std::string name;
    Scene scene;
    render::Renderer renderer;
    eval::PassSeries series;
    size_t rendered = 0;
  };
  std::vector<std::unique_ptr<Config>> cs;
  auto add = [&](const std::string& name, ShadowFilter f, size_t k,
                 ShadowResolution r = ShadowResolution::Full) {
    auto c = std::make_unique<Config>();
    c->name = name;
    c->scene = scene;
    c->scene.settings.shadow_filter = f;
    c->scene.settings.shadow_resolution = r;
    for (size_t j = 0; j < shadowed.size(); ++j) c->scene.lights[shadowed[j]].shadows = j < k;
    cs.push_back(std::move(c));
  };
  add("no shadows", ShadowFilter::Pcss, 0);
  const std::pair<const char*, ShadowFilter> filters[] = {
      {"hard", ShadowFilter::Hard}, {"pcf", ShadowFilter::Pcf}, {"pcss", ShadowFilter::Pcss}};
  for (const ShadowResolution r : {ShadowResolution::Full, ShadowResolution::Half}) {
    for (const auto& [label, f] : filters) {
      for (size_t k = 1; k <= shadowed.size(); ++k) {
        add(std::string(label) + (r == ShadowResolution::Half ? " half" : "") + ", " +
                std::to_string(k) + " light" + (k == 1 ? "" : "s"),
            f, k, r);
      }
    }
  }
  render::DebugOptions d;
  d.floor_pass = true;
  d.finish_each_pass = true;
  for (auto& c : cs) {
    c->renderer.setDebugOptions(d);
    c->renderer.setScene(c->scene);
    c->renderer.render(w, h);  // warm-up: compiles, renders the maps
  }
  for (int f = 0; f < frames; ++f) {
    for (auto& c : cs) {
      const render::FrameStats st = c->renderer.render(w, h);
      c->rendered += st.shadow_maps_rendered;
      c->series.add(st);
    }
  }
  auto total = [](const eval::PassSeries& p, size_t k) {
    double t = 0.0;
    for (const std::string& pass : p.order) {
      if (pass != "floor" && k < p.of(pass).size()) t += p.of(pass)[k];
    }
    return t;
  };
  // The shadows' cost in the light pass, and with shadow_resolution half in the shadow mask
  // pass before it ("light + mask").
  auto lighting = [](const eval::PassSeries& p, size_t k) {
    double t = p.of("light").at(k);
    if (std::find(p.order.begin(), p.order.end(), "shadow_mask") != p.order.end()) {
      t += p.of("shadow_mask").at(k);
    }
    return t;
  };
  std::printf(
      "  shadow sweep, %d interleaved frames: extra cost over no shadows, x floor of the same "
      "frame (95%% interval)\n  %-22s %22s %22s %10s %14s\n",
      frames, "configuration", "light + mask passes", "whole frame", "ms", "maps rendered");
  const eval::PassSeries& none = cs[0]->series;
  std::printf("  %-22s %22s %22s %10.2f %14zu\n", cs[0]->name.c_str(), "", "", none.median("light"),
              cs[0]->rendered);
  for (size_t i = 1; i < cs.size(); ++i) {
    const eval::PassSeries& s = cs[i]->series;
    std::vector<double> light, frame, ms;
    for (size_t k = 0; k < size_t(frames); ++k) {
      const double floor = s.of("floor").at(k);
      ms.push_back(lighting(s, k));
      light.push_back((lighting(s, k) - none.of("light").at(k)) / floor);
      frame.push_back((total(s, k) - total(none, k)) / floor);
    }
    const eval::MedianInterval l = eval::medianInterval(light), fr = eval::medianInterval(frame);
    char lc[64], fc[64];
    std::snprintf(lc, sizeof lc, "%.2f (%.2f - %.2f)", l.median, l.lo, l.hi);
    std::snprintf(fc, sizeof fc, "%.2f (%.2f - %.2f)", fr.median, fr.lo, fr.hi);
    std::printf("  %-22s %22s %22s %10.2f %14zu\n", cs[i]->name.c_str(), lc, fc,
                eval::medianInterval(ms).median, cs[i]->rendered);
  }
  std::printf("  (floor %.3g ms, median of the no-shadows renderer)\n", none.median("floor"));
  std::fflush(stdout);
}

// --vs-brute: one line per scene, and the markdown table for --report.
std::string tiledVsBrute(const std::vector<Scene>& scenes, const std::vector<std::string>& paths,
                         const FrameBenchOptions& o) {
  std::printf("%-30s %6s %9s %6s %11s %11s %14s  %s\n", "scene", "lights", "per tile", "auto",
              "tiled ms", "brute ms", "tiled / brute", "95% interval");
  std::string md =
      "| scene | lights | lights per tile | auto | tiled frame ms | brute-force frame ms | "
      "tiled / brute (95% interval) |\n"
      "|---|---:|---:|---|---:|---:|---:|\n";
  for (size_t i = 0; i < scenes.size(); ++i) {
    const std::string name = std::filesystem::path(paths[i]).stem().string();
    const eval::TiledVsBrute r =
        eval::measureTiledVsBruteForce(scenes[i], name, o.width, o.height, o.frames);
    // What culling: auto picks for the scene (the coverage at its camera, render::chooseCulling).
    const render::CullingChoice c = render::chooseCulling(scenes[i]);
    const char* pick = c.culling == Culling::BruteForce ? "brute" : "tiled";
    std::printf("%-30s %6zu %9.2f %6s %11.2f %11.2f %14.2f  %.2f - %.2f\n", name.c_str(), c.lights,
                c.coverage, pick, r.tiled_ms, r.brute_ms, r.ratio.median, r.ratio.lo, r.ratio.hi);
    std::fflush(stdout);
    char row[320];
    std::snprintf(row, sizeof row, "| %s | %zu | %.2f | %s | %.1f | %.1f | %.2f (%.2f - %.2f) |\n",
                  name.c_str(), c.lights, c.coverage, pick, r.tiled_ms, r.brute_ms, r.ratio.median,
                  r.ratio.lo, r.ratio.hi);
    md += row;
  }
  return md;
}

// --settings: the scene as it is, then once per set (its overrides as --set gives them); none
// without sets.
std::vector<Scene> settingsVariants(const std::string& path, const Scene& scene,
                                    const std::vector<std::string>& sets,
                                    std::vector<std::string>& names) {
  std::vector<Scene> variants;
  if (sets.empty()) return variants;
  variants.push_back(scene);
  names.push_back("scene's own settings");
  for (const std::string& set : sets) {
    SceneOpenOptions open;
    std::stringstream list(set);
    for (std::string kv; std::getline(list, kv, ',');) {
      if (!kv.empty()) open.overrides.push_back("settings." + kv);
    }
    variants.push_back(openScene(path, open));
    names.push_back(set);
  }
  return variants;
}

}  // namespace

std::vector<std::string> sampleScenePaths() {
  std::vector<std::string> files;
  for (const auto& e : std::filesystem::directory_iterator(HV_SAMPLES_DIR)) {
    if (e.path().extension() == ".json") files.push_back(e.path().string());
  }
  std::sort(files.begin(), files.end());
  return files;
}

int benchFrame(const FrameBenchOptions& o) {
  OutputFiles outputs;
  std::filesystem::path report_tmp;  // reserved now: a report that cannot be written fails early
  if (!o.report.empty()) report_tmp = outputs.add(o.report);
  const std::vector<std::string> scenes =
      o.scene.empty() ? sampleScenePaths() : std::vector<std::string>{o.scene};
  if (o.shadow_sweep && (o.vs_brute || !o.shader_dirs.empty() || !o.report.empty())) {
    throw UsageError{"--shadow-sweep takes no --vs-brute, --shaders or --report"};
  }
  if (!o.shader_dirs.empty() && scenes.size() != 1) {
    throw UsageError{"--frame --shaders needs --scene FILE"};
  }
  if (!o.settings_sets.empty() && (scenes.size() != 1 || !o.shader_dirs.empty())) {
    throw UsageError{"--frame --settings needs --scene FILE and takes no --shaders"};
  }
  std::vector<Scene> loaded;
  for (const std::string& s : scenes) loaded.push_back(loadScene(s));  // fail before rendering
  std::vector<std::string> variant_names;
  const std::vector<Scene> variants =
      settingsVariants(scenes[0], loaded[0], o.settings_sets, variant_names);
  auto ctx = createHeadlessContext();
  std::printf(
      "renderer: %s, %dx%d; x floor = median over frames of (pass ms / floor pass ms of "
      "the same frame)\n\n",
      ctx->renderer().c_str(), o.width, o.height);
  std::string md = "Renderer: " + ctx->renderer() + ", " + std::to_string(o.width) + "x" +
                   std::to_string(o.height) + ", " + std::to_string(o.frames) +
                   " frames per scene after a warm-up frame; ";
  if (o.vs_brute) {
    if (!o.shader_dirs.empty()) throw UsageError{"--vs-brute does not take --shaders"};
    md += "whole-frame GPU ms, medians; ratio: median over interleaved rounds.\n\n" +
          tiledVsBrute(loaded, scenes, o);
  }
  std::vector<eval::FrameCost> costs;
  for (size_t i = 0; i < scenes.size() && !o.vs_brute; ++i) {
    const std::string name = std::filesystem::path(scenes[i]).stem().string();
    if (o.shadow_sweep) {
      std::printf("%s (%dx%d)\n", name.c_str(), o.width, o.height);
      printShadowSweep(loaded[i], o.width, o.height, o.frames);
    } else if (!variants.empty()) {
      for (const auto& c :
           eval::measureFrameCostScenes(variants, variant_names, o.width, o.height, o.frames)) {
        costs.push_back(c);
        printCost(c);
      }
    } else if (o.shader_dirs.empty()) {
      costs.push_back(
          eval::measureFrameCost(loaded[i], name, o.width, o.height, o.frames, o.cull_stages));
      printCost(costs.back());
      printShadowCost(loaded[i], o.width, o.height, o.frames);
    } else {
      for (const auto& c : eval::measureFrameCostTrees(loaded[i], o.shader_dirs, o.width, o.height,
                                                       o.frames, o.cull_stages)) {
        costs.push_back(c);
        printCost(c);
      }
    }
    std::printf("\n");
  }
  if (!o.report.empty()) {
    if (!o.vs_brute) {
      md +=
          "each cell: median GPU ms (median over frames of pass ms / floor ms of the same "
          "frame).\n\n" +
          frameCostMarkdown(costs);
    }
    std::ofstream(report_tmp) << md;
    outputs.commit();
    std::printf("wrote %s\n", o.report.c_str());
  }
  return 0;
}

}  // namespace hv::app
