// `halfvec accuracy`: measures each approximation of the engine against the reference
// (engine/eval accuracy_report.hpp) and writes docs/accuracy.md and its heat maps
// (accuracy_markdown.cpp formats them).
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "app/accuracy_markdown.hpp"
#include "app/commands.hpp"
#include "halfvec/core/output_files.hpp"
#include "halfvec/image/image.hpp"
#include "halfvec/platform/context.hpp"
#include "halfvec/scene/scene_loader.hpp"

namespace hv::app {

namespace fs = std::filesystem;

namespace {

constexpr const char* kHelp = R"(Usage: halfvec accuracy [options]

Measures the engine's approximations against the reference (docs/reference.md) and writes the
tables to a markdown file, with heat maps in a folder next to it (<out stem>/*.png):
  - point light: GPU render vs the reference (exact for points);
  - sphere lights: representative point with/without the (alpha/alpha')^2 normalization, ltc,
    both sphere-diffuse modes, over roughness x radius/distance x elevation (per shading
    configuration, on the CPU: the engine's formula vs the integral over the emitter);
  - directional lights: the same sweep with a disk of the sphere's cone, from the sun's size;
  - tube lights: eq. 19 vs eq. 18, with/without normalization, ltc; karis_eq16 and ltc diffuse,
    over roughness x length x radius x orientation;
  - the ltc modes with another V or D term than the fitted lobe's;
  - clear coat: a coated sphere under a sphere, tube and directional light and the sky, per
    coat roughness and method, beside the same sphere without the coat;
  - ambient: split sum (table and EnvBRDFApprox) and SH9 vs the reference over roughness, for a
    uniform environment and each .hdr in $HV_ASSETS_DIR/env; EnvBRDFApprox vs the table;
  - shadows: each shadow filter against the reference with visibility rays, a sphere occluder
    over a floor under a sphere or capsule light, light radius x occluder height;
  - the sample scenes: engine vs reference heat maps.

Options:
  --out FILE.md     output (default docs/accuracy.md; required with --only, which writes a
                    report of that section alone and so must not replace the whole one)
  --quick           small grids and images, few samples (a smoke test; seconds)
  --threads N       CPU threads (default: all cores)
  --only SECTION    measure and write only that section (minutes, not hours): shadows (the
                    shadow filters against the traced reference), occlusion (screen-space AO),
                    directional (the directional-light sweep), clearcoat (the clear coat),
                    budget (the error budget's prediction), spheres (the sphere sweep and its
                    goals, straddling spheres included) or tubes (the tube sweep and capsules
                    straddling the horizon)
  -h, --help        this text
)";

struct Options {
  std::string out;  // empty: docs/accuracy.md, the full report's place (not for --only)
  eval::AccuracyOptions eval;
  std::string only;  // "shadows", "occlusion", ...: measure and write that section alone
};

Options parseArgs(const Args& args) {
  Options o;
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a == "--out") {
      o.out = optionValue(args, i);
      if (o.out.empty()) throw UsageError{"--out needs a file name"};
    } else if (a == "--quick") {
      o.eval.quick = true;
    } else if (a == "--threads") {
      o.eval.threads = intInRange(a, optionValue(args, i), 0, 4096);
    } else if (a == "--only") {
      o.only = optionValue(args, i);
      if (o.only != "shadows" && o.only != "occlusion" && o.only != "directional" &&
          o.only != "clearcoat" && o.only != "budget" && o.only != "spheres" && o.only != "tubes") {
        throw UsageError{
            "--only: expected 'shadows', 'occlusion', 'directional', 'clearcoat', 'budget', "
            "'spheres' or 'tubes', got '" +
            o.only + "'"};
      }
    } else {
      throw UsageError{"unknown argument '" + a + "'"};
    }
  }
  // A section alone is not the whole report: it goes only where it is told to go.
  if (o.out.empty() && !o.only.empty()) {
    throw UsageError{"--only " + o.only +
                     " needs --out FILE.md (it does not replace docs/accuracy.md)"};
  }
  if (o.out.empty()) o.out = "docs/accuracy.md";
  // The shared assets folder (the CLI sets its default), empty when HV_ASSETS_DIR is not set: the
  // sections that need it say they were skipped.
  const char* env = std::getenv("HV_ASSETS_DIR");
  o.eval.assets_dir = env ? env : "";
  o.eval.scenes_dir = HV_SAMPLES_DIR;
  return o;
}

// Runs each measurement with a progress line; returns the document's body.
struct Measured {
  eval::PointLightAccuracy point;
  eval::SphereAccuracy sphere;
  eval::SphereAccuracy directional;
  eval::BudgetAccuracy budget;
  eval::ClearCoatAccuracy clear_coat;
  eval::TubeAccuracy tube;
  eval::TubeStraddlingAccuracy tube_straddling;
  eval::AmbientAccuracy ambient;
  eval::ShadowAccuracy shadows;
  std::vector<eval::SceneAccuracy> scenes;
  eval::OcclusionAccuracy occlusion;
};

Measured measure(const eval::AccuracyOptions& o, const std::string& only) {
  Measured m;
  auto step = [](const char* what) { std::fprintf(stderr, "accuracy: %s...\n", what); };
  if (only == "shadows") {
    step("shadows");
    m.shadows = eval::measureShadows(o);
    return m;
  }
  if (only == "occlusion") {
    step("occlusion");
    m.occlusion = eval::measureOcclusion(o);
    return m;
  }
  if (only == "directional") {
    step("directional lights");
    m.directional = eval::measureDirectionalLights(o);
    return m;
  }
  if (only == "clearcoat") {
    step("clear coat");
    m.clear_coat = eval::measureClearCoat(o);
    return m;
  }
  if (only == "budget") {
    step("error budget");
    m.budget = eval::measureBudget(o);
    return m;
  }
  if (only == "spheres") {
    step("sphere lights");
    m.sphere = eval::measureSphereLights(o);
    return m;
  }
  if (only == "tubes") {
    step("tube lights");
    m.tube = eval::measureTubeLights(o);
    step("tube lights straddling the horizon");
    m.tube_straddling = eval::measureTubeStraddling(o);
    return m;
  }
  step("point lights");
  m.point = eval::measurePointLights(o);
  step("sphere lights");
  m.sphere = eval::measureSphereLights(o);
  step("directional lights");
  m.directional = eval::measureDirectionalLights(o);
  step("error budget");
  m.budget = eval::measureBudget(o);
  step("tube lights");
  m.tube = eval::measureTubeLights(o);
  m.tube_straddling = eval::measureTubeStraddling(o);
  step("clear coat");
  m.clear_coat = eval::measureClearCoat(o);
  step("ambient");
  m.ambient = eval::measureAmbient(o);
  step("shadows");
  m.shadows = eval::measureShadows(o);
  step("sample scenes");
  m.scenes = eval::measureScenes(o);
  step("occlusion");
  m.occlusion = eval::measureOcclusion(o);
  return m;
}

std::string document(const Options& o, const Measured& m, double secs, const std::string& gpu) {
  const std::string cmd = std::string("halfvec accuracy") + (o.eval.quick ? " --quick" : "") +
                          (o.only.empty() ? std::string() : " --only " + o.only);
  std::ostringstream md;
  if (o.only == "shadows") {
    md << "<!-- Generated by `" << cmd << " --out " << o.out << "` in " << fmtNum("%.0f", secs)
       << " s on " << gpu << " (samples/app/cmd_accuracy.cpp). -->\n\n"
       << shadowsMarkdown(m.shadows);
    return md.str();
  }
  md << "<!-- Generated by `" << cmd
     << "` (samples/app/cmd_accuracy.cpp); do not edit by hand, run the command again. -->\n\n"
     << "# Accuracy of the engine's approximations\n\n"
     << "Generated by `" << cmd << " --out " << o.out << "` in " << fmtNum("%.0f", secs) << " s on "
     << gpu
     << ". Every number below is measured against the CPU reference (docs/reference.md): the "
        "engine's own formulas against the exact integral of the same emitter and BRDF, so the "
        "difference is the error of the approximation alone. Tests asserting these findings: "
        "tests/eval/test_accuracy.cpp, tests/eval/test_ltc_lights.cpp.\n\n";
  if (o.only == "occlusion") {
    md << occlusionMarkdown(m.occlusion);
    return md.str();
  }
  if (o.only == "directional") {
    md << directionalMarkdown(m.directional);
    return md.str();
  }
  if (o.only == "clearcoat") {
    md << clearCoatMarkdown(m.clear_coat);
    return md.str();
  }
  if (o.only == "budget") {
    md << budgetMarkdown(m.budget);
    return md.str();
  }
  if (o.only == "spheres") {
    md << sphereGoalsMarkdown(m.sphere) << sphereMarkdown(m.sphere);
    return md.str();
  }
  if (o.only == "tubes") {
    md << tubeMarkdown(m.tube) << tubeStraddlingMarkdown(m.tube_straddling);
    return md.str();
  }
  md << summaryMarkdown(m.sphere, m.tube, m.point, m.ambient) << pointLightMarkdown(m.point)
     << sphereMarkdown(m.sphere) << budgetMarkdown(m.budget) << directionalMarkdown(m.directional)
     << tubeMarkdown(m.tube) << tubeStraddlingMarkdown(m.tube_straddling)
     << otherBrdfMarkdown(m.sphere, m.tube) << clearCoatMarkdown(m.clear_coat)
     << ambientMarkdown(m.ambient) << shadowsMarkdown(m.shadows)
     << scenesMarkdown(m.scenes, fs::path(o.out).stem().string()) << occlusionMarkdown(m.occlusion);
  return md.str();
}

}  // namespace

int cmdAccuracy(const Args& args) {
  for (const auto& a : args) {
    if (a == "--help" || a == "-h") {
      std::fputs(kHelp, stdout);
      return 0;
    }
  }
  const Options o = parseArgs(args);
  const fs::path out = o.out;
  const fs::path heat_dir = out.parent_path() / out.stem();
  if (o.only.empty()) fs::create_directories(heat_dir);  // the sample scenes' heat maps
  OutputFiles outputs;
  const fs::path md_tmp = outputs.add(out);  // fails now if the folder is not writable
  const auto t0 = std::chrono::steady_clock::now();
  auto ctx = createHeadlessContext();
  const Measured m = measure(o.eval, o.only);
  for (const auto& s : m.scenes)
    writePng(outputs.add(heat_dir / (s.name + ".png")).string(), s.heat_map);
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  {
    std::ofstream f(md_tmp, std::ios::binary);
    f << document(o, m, secs, ctx->renderer());
    if (!f) throw OutputError("cannot write " + md_tmp.string());
  }
  outputs.commit();
  std::printf("accuracy: wrote %s (%.1f s)\n", out.string().c_str(), secs);
  return 0;
}

}  // namespace hv::app
