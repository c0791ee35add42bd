// `halfvec render`: headless render of a scene file.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "app/commands.hpp"
#include "halfvec/core/output_files.hpp"
#include "halfvec/ibl/ibl.hpp"
#include "halfvec/eval/engine_aov.hpp"
#include "halfvec/platform/context.hpp"
#include "halfvec/render/renderer.hpp"
#include "halfvec/scene/enums.hpp"
#include "halfvec/scene/scene_loader.hpp"

namespace hv::app {

namespace {
constexpr const char* kRenderHelp = R"(Usage: halfvec render SCENE [options]

Renders SCENE headless (EGL) and writes the tone-mapped image. SCENE is a scene file (.json,
docs/scene-format.md) or a glTF model (.gltf, .glb): a model is framed from a three-quarter view
under the procedural sky with a default key light (docs/scene-format.md, "Models opened by path").

Options:
  --size WxH            output size (default: the scene's settings.width x settings.height)
  --out FILE.png        tone-mapped 8-bit image (default: out/<scene name>.png)
  --hdr FILE.pfm        linear radiance before tone mapping (PFM)
  --stats FILE.json     per-pass GPU times, renderer, sizes, light counts, compiled variants
  --set PATH=VALUE      override a scene field before validation, e.g. --set settings.exposure=2
                        or --set lights.0.intensity=50 (repeatable; VALUE is JSON)
  --env FILE.hdr        replace the scene's environment with this equirectangular HDR
  --camera N            a model's own camera N (glTF cameras, in node order) instead of framing
  --print-scene         print the scene JSON (for a model: the one made for it; --set,
                        --look and the camera options applied) and exit
  --camera-position X,Y,Z  camera position (= --set camera.position=[X,Y,Z])
  --camera-target X,Y,Z    camera target (= --set camera.target=[X,Y,Z])
  --fov DEG             vertical field of view in degrees (= --set camera.fov_y_deg=DEG)
  --no-key-light        a model without the default key light (image-based lighting only)
  --look gltf|scene     gltf: the glTF viewers' conventions (no key light, PBR Neutral tone
                        map, sRGB output, no dither; --set applies after it); default scene
  --aa fxaa|none        post-process anti-aliasing of the 8-bit image (default fxaa; the HDR
                        image of --hdr is never anti-aliased)
  --emitters on|off     draw sphere and tube lights as emissive geometry of their color (default
                        on; --hdr then holds them too: use off to compare with the reference)
  --view NAME           debug view: basecolor|metallic|roughness|cavity|normal|depth|
                        shading_model|lights_per_tile (G-buffer and culling, shown as stored),
                        or one term, tone-mapped as the normal image (--hdr writes the term):
                        direct_diffuse|direct_specular|ambient_diffuse|ambient_specular|emissive;
                        predicted_error: the error budget's predicted relative error of the
                        direct light per pixel, 0.1% blue .. 3% green .. 100% red (docs/lights.md)
  --frames N            render N frames and report the median pass times (default 1)
  --uber                compile every feature in, chosen at run time (= --set settings.uber=true);
                        default: programs specialized to the scene (docs/variants.md)
  --no-binary-cache     neither read nor write the on-disk program binary cache
  --aov DIR             also write the engine's direct_diffuse, direct_specular, ambient_diffuse
                        and ambient_specular .pfm (lit pixels only, no emissive; one re-render
                        per term with HV_DIRECT_TERMS / HV_AMBIENT_TERMS), named as the
                        reference's AOVs so `halfvec compare` pairs them
  -h, --help            this text
)";

struct RenderArgs {
  std::string scene, out, hdr, stats, aov;
  SceneOpenOptions open;
  int width = 0, height = 0, frames = 1;
  bool binary_cache = true, print_scene = false;
  render::ViewOptions view_options{render::PostAA::Fxaa, true, -1};
  render::DebugView view = render::DebugView::None;
};

RenderArgs parse(const Args& args) {
  RenderArgs r;
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    auto value = [&] { return optionValue(args, i); };
    if (takeSceneOption(args, i, r.open, r.print_scene)) {
      continue;
    } else if (a == "--size") {
      parseSize(value(), r.width, r.height);
    } else if (a == "--out") {
      r.out = value();
    } else if (a == "--hdr") {
      r.hdr = value();
    } else if (a == "--stats") {
      r.stats = value();
    } else if (a == "--aov") {
      r.aov = value();
    } else if (a == "--frames") {
      r.frames = intInRange(a, value(), 1, 1000);
    } else if (a == "--aa") {
      const std::string v = value();
      const auto aa = render::postAAFromString(v);
      if (!aa) throw UsageError{"--aa expects fxaa or none, got '" + v + "'"};
      r.view_options.aa = *aa;
    } else if (a == "--emitters") {
      const std::string v = value();
      if (v != "on" && v != "off")
        throw UsageError{"--emitters expects on or off, got '" + v + "'"};
      r.view_options.emitters = v == "on";
    } else if (a == "--uber") {
      r.open.overrides.push_back("settings.uber=true");
    } else if (a == "--no-binary-cache") {
      r.binary_cache = false;
    } else if (a == "--view") {
      const std::string v = value();
      auto dv = render::debugViewFromString(v);
      if (!dv) throw UsageError{"unknown --view '" + v + "'" + debugViewSuggestion(v)};
      r.view = *dv;
    } else {
      takeScenePath(a, r.scene);
    }
  }
  if (r.scene.empty()) throw UsageError{"no scene file given"};
  return r;
}

nlohmann::ordered_json manifestJson(const render::Manifest& m) {
  nlohmann::ordered_json j;
  j["key"] = m.key;
  j["binary_cache"] = m.binary_cache;
  j["binary_cache_hits"] = m.binary_hits;
  j["binary_cache_misses"] = m.binary_misses;
  nlohmann::ordered_json progs = nlohmann::ordered_json::array();
  for (const auto& v : m.programs) {
    nlohmann::ordered_json p;
    p["program"] = v.name;
    p["stages"] = v.stages;
    p["key"] = v.defines;
    p["reasons"] = v.reasons;
    p["compile_ms"] = v.compile_ms;
    p["link_ms"] = v.link_ms;
    p["from_binary_cache"] = v.from_binary_cache;
    p["cache_load_ms"] = v.cache_load_ms;
    progs.push_back(p);
  }
  j["programs"] = progs;
  return j;
}

// The files a render writes, reserved before the render: every folder is checked (and --out's
// and --aov's created) first, so an unwritable path fails before any GL work, and nothing of a
// run appears unless every output was written (hv::OutputFiles).
struct RenderOutputs {
  OutputFiles files;
  std::filesystem::path out, hdr, stats;
  std::vector<std::filesystem::path> aov;  // kReferenceAovCount files when --aov is given
};

void reserveOutputs(const RenderArgs& ra, const Scene& scene, RenderOutputs& o) {
  protectSceneInputs(o.files, ra.scene, ra.open, scene);  // --out scene.json: refused
  const auto out_dir = std::filesystem::path(ra.out).parent_path();
  if (!out_dir.empty()) std::filesystem::create_directories(out_dir);
  o.out = o.files.add(ra.out);
  if (!ra.hdr.empty()) o.hdr = o.files.add(ra.hdr);
  if (!ra.stats.empty()) o.stats = o.files.add(ra.stats);
  if (!ra.aov.empty()) {
    std::filesystem::create_directories(ra.aov);
    for (int k = 0; k < kReferenceAovCount; ++k) {
      const auto which = static_cast<ReferenceAov>(k);
      o.aov.push_back(
          o.files.add(std::filesystem::path(ra.aov) / (std::string(toString(which)) + ".pfm")));
    }
  }
}

// Median per pass over the frames.
render::FrameStats medianStats(const std::vector<render::FrameStats>& frames) {
  render::FrameStats stats = frames.back();
  for (size_t p = 0; p < stats.passes.size(); ++p) {
    std::vector<double> v;
    for (auto& fr : frames) v.push_back(fr.passes[p].second);
    std::nth_element(v.begin(), v.begin() + long(v.size() / 2), v.end());
    stats.passes[p].second = v[v.size() / 2];
  }
  stats.total_ms = 0;
  for (auto& [n, ms] : stats.passes) stats.total_ms += ms;
  return stats;
}

struct RenderReport {
  const RenderArgs& ra;
  const Scene& scene;
  int w, h;
  const render::FrameStats& stats;
  double setup_ms;
  size_t triangles;
};

void printReport(const RenderReport& r, const Context& ctx, const render::Renderer& renderer) {
  std::printf("renderer: %s (%s)\n", ctx.renderer().c_str(), ctx.platform().c_str());
  std::printf("scene: %s, %dx%d, %zu lights, %zu triangles\n", r.ra.scene.c_str(), r.w, r.h,
              r.scene.lights.size(), r.triangles);
  std::printf("%-14s %10s\n", "pass", "GPU ms");
  for (auto& [name, ms] : r.stats.passes) std::printf("%-14s %10.3f\n", name.c_str(), ms);
  std::printf("%-14s %10.3f\n", "total", r.stats.total_ms);
  std::printf("setup (upload + environment bake): %.1f ms\n", r.setup_ms);
  if (const BakeTimings* bake = renderer.environmentTimings()) {
    std::printf(
        "environment bake (%s): load %.1f, convert %.1f, prefilter %.1f, env BRDF %.1f, "
        "SH9 %.1f, irradiance %.1f, cache %.1f, total %.1f ms\n",
        bake->cache_hit ? "cache hit" : "computed", bake->load_ms, bake->convert_ms,
        bake->prefilter_ms, bake->env_brdf_ms, bake->sh_ms, bake->irradiance_ms, bake->cache_ms,
        bake->total_ms);
  }
  const render::Manifest manifest = renderer.manifest();
  double compile_ms = 0.0;
  for (const auto& v : manifest.programs) compile_ms += v.compile_ms + v.link_ms + v.cache_load_ms;
  std::printf("programs: %zu (%s), %.1f ms compile+link, binary cache %zu hits / %zu misses\n",
              manifest.programs.size(), manifest.key.c_str(), compile_ms, manifest.binary_hits,
              manifest.binary_misses);
}

nlohmann::ordered_json statsJson(const RenderReport& r, const Context& ctx,
                                 const render::Renderer& renderer) {
  nlohmann::ordered_json j;
  j["renderer"] = ctx.renderer();
  j["platform"] = ctx.platform();
  j["gl_version"] = ctx.version();
  j["scene"] = r.ra.scene;
  j["width"] = r.w;
  j["height"] = r.h;
  j["frames"] = r.ra.frames;
  nlohmann::ordered_json passes;
  for (auto& [name, ms] : r.stats.passes) passes[name] = ms;
  j["passes"] = passes;
  j["total_ms"] = r.stats.total_ms;
  j["setup_ms"] = r.setup_ms;
  j["gbuffer_bytes_per_pixel"] = render::gbufferBytesPerPixel(renderer.variantKey().clear_coat);
  j["triangles"] = r.triangles;
  if (const BakeTimings* bake = renderer.environmentTimings()) {
    j["environment_bake_ms"] = {{"cache_hit", bake->cache_hit},
                                {"load", bake->load_ms},
                                {"convert", bake->convert_ms},
                                {"prefilter", bake->prefilter_ms},
                                {"env_brdf", bake->env_brdf_ms},
                                {"sh9", bake->sh_ms},
                                {"irradiance", bake->irradiance_ms},
                                {"cache", bake->cache_ms},
                                {"total", bake->total_ms}};
  }
  nlohmann::ordered_json counts;
  for (auto t : {LightType::Point, LightType::Sphere, LightType::Tube, LightType::Spot,
                 LightType::Directional}) {
    counts[std::string(toString(t))] = std::count_if(r.scene.lights.begin(), r.scene.lights.end(),
                                                     [&](const Light& l) { return l.type == t; });
  }
  j["light_counts"] = counts;
  j["tile_light_entries"] = r.stats.tile_light_entries;
  j["tile_list_capacity"] = renderer.tileListCapacity();  // sized from the CPU bound
  j["tile_list_readbacks"] = renderer.tileListReadbacks();
  nlohmann::ordered_json vars = nlohmann::ordered_json::array();
  for (const auto& v : renderer.programs().variants()) {
    vars.push_back({{"program", v.name}, {"defines", v.defines}, {"compile_ms", v.compile_ms}});
  }
  j["program_variants"] = vars;
  j["manifest"] = manifestJson(renderer.manifest());
  return j;
}

}  // namespace

int cmdRender(const Args& args) {
  for (const auto& a : args) {
    if (a == "--help" || a == "-h") {
      std::fputs(kRenderHelp, stdout);
      return 0;
    }
  }
  RenderArgs ra = parse(args);
  if (ra.print_scene) return printScene(ra.scene, ra.open);
  // Load and validate everything before any GL work: bad input renders nothing.
  Scene scene = openScene(ra.scene, ra.open);
  const int w = ra.width ? ra.width : scene.settings.width;
  const int h = ra.height ? ra.height : scene.settings.height;
  if (ra.out.empty()) {
    ra.out = "out/" + std::filesystem::path(ra.scene).stem().string() + ".png";
  }
  RenderOutputs outputs;
  reserveOutputs(ra, scene, outputs);

  auto ctx = createHeadlessContext();
  render::Renderer renderer;
  if (!ra.binary_cache) renderer.programs().setBinaryCacheDir({});
  renderer.setViewOptions(ra.view_options);
  const auto t0 = std::chrono::steady_clock::now();
  renderer.setScene(scene);
  const double setup_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  std::vector<render::FrameStats> frames;
  for (int f = 0; f < ra.frames; ++f) frames.push_back(renderer.render(w, h, ra.view));
  const render::FrameStats stats = medianStats(frames);

  writePng(outputs.out.string(), renderer.readLdr());
  if (!ra.hdr.empty()) writePfm(outputs.hdr.string(), renderer.readHdr());
  if (!ra.aov.empty()) {
    const auto aovs = eval::renderEngineAovs(renderer, w, h);
    for (int k = 0; k < kReferenceAovCount; ++k) {
      writePfm(outputs.aov[size_t(k)].string(), aovs[size_t(k)]);
    }
  }
  size_t triangles = 0;
  for (const Object& o : scene.objects) {
    for (int m : o.meshes) triangles += scene.meshes[size_t(m)].indices.size() / 3;
  }
  const RenderReport report{ra, scene, w, h, stats, setup_ms, triangles};
  printReport(report, *ctx, renderer);
  if (!ra.stats.empty()) {
    std::ofstream f(outputs.stats);
    f << statsJson(report, *ctx, renderer).dump(2) << "\n";
    if (!f.flush()) throw OutputError(ra.stats + ": cannot write");
  }
  outputs.files.commit();
  std::printf("image: %s\n", std::filesystem::absolute(ra.out).string().c_str());
  if (!ra.hdr.empty()) std::printf("hdr: %s\n", std::filesystem::absolute(ra.hdr).string().c_str());
  if (!ra.aov.empty()) std::printf("aov: %s\n", std::filesystem::absolute(ra.aov).string().c_str());
  if (!ra.stats.empty()) {
    std::printf("stats: %s\n", std::filesystem::absolute(ra.stats).string().c_str());
  }
  return 0;
}

}  // namespace hv::app
