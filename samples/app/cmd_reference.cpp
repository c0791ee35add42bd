// `halfvec reference`: CPU Monte Carlo ground truth over the GPU's own G-buffer.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>

#include "app/commands.hpp"
#include "halfvec/core/output_files.hpp"
#include "halfvec/platform/context.hpp"
#include "halfvec/reference/reference.hpp"
#include "halfvec/render/renderer.hpp"
#include "halfvec/scene/scene_loader.hpp"
#include "halfvec/shading/shading.hpp"

namespace hv::app {

namespace {
constexpr const char* kHelp = R"(Usage: halfvec reference SCENE.json [options]

Renders the scene's G-buffer on the GPU, reads it back, and computes the exact lighting integral
per pixel by Monte Carlo (same BRDF terms as the engine; shadows and environment occlusion traced
against the scene's triangles unless --visibility off; no interreflection; see
docs/reference.md). Prints its own standard error and the visibility rays traced.

Options:
  --size WxH           output size (default: the scene's)
  --samples N          samples per pixel and estimator (default 256)
  --target-error E     stop a pixel once its relative standard error is below E
  --hdr FILE.pfm       the reference radiance (compare with `halfvec render --hdr`)
  --out FILE.png       tone-mapped with the engine's output transform (no dither)
  --aov DIR            direct_diffuse, direct_specular, ambient_diffuse, ambient_specular and
                       ambient_occlusion .pfm
  --visibility on|off  trace shadow and environment visibility rays (default on); off: the
                       shading integral alone, nothing occludes (as the accuracy sweeps)
  --ao-distance D      ambient occlusion counts occluders within D (default: any distance)
  --set PATH=VALUE     scene override, as for render
  --threads N          worker threads (default: all cores)
)";

// --visibility on|off.
bool parseOnOff(const std::string& option, const std::string& v) {
  if (v != "on" && v != "off") throw UsageError{option + " expects on or off, got '" + v + "'"};
  return v == "on";
}

void printSummary(const ReferenceResult& r, int w, int h) {
  std::printf("reference: %dx%d, %zu lit pixels, %llu samples, %.1f s\n", w, h, r.stats.lit_pixels,
              static_cast<unsigned long long>(r.stats.total_samples), r.stats.seconds);
  std::printf("Monte Carlo relative standard error: mean %.4f, max %.4f\n", r.stats.mean_rel_error,
              r.stats.max_rel_error);
  if (r.stats.visibility) {
    std::printf("visibility: %llu rays against %zu triangles, %.3g rays per second of the run\n",
                static_cast<unsigned long long>(r.stats.rays), r.stats.triangles,
                r.stats.seconds > 0.0 ? double(r.stats.rays) / r.stats.seconds : 0.0);
  } else {
    std::printf("visibility: off (nothing occludes)\n");
  }
}

// The engine's own output transform (shaders/common/tonemap.glsl, default Reinhard + 2.2).
ImageRGBA8 toneMapped(const ImageRGBf& image, float exposure) {
  ImageRGBA8 ldr = makeImageRGBA8(image.width, image.height);
  for (size_t i = 0; i < image.px.size(); ++i) {
    const glm::vec3 c = glsl::outputTransform(image.px[i] * exposure);
    for (int k = 0; k < 3; ++k) ldr.px[4 * i + k] = uint8_t(std::lround(c[k] * 255.0f));
    ldr.px[4 * i + 3] = 255;
  }
  return ldr;
}
}  // namespace

int cmdReference(const Args& args) {
  std::string scene_path, hdr, out, aov;
  std::vector<std::string> overrides;
  int w = 0, h = 0;
  ReferenceOptions opt;
  opt.progress = true;
  opt.visibility = true;  // a scene's reference: shadows and environment occlusion
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    auto value = [&] { return optionValue(args, i); };
    if (a == "--help" || a == "-h") {
      std::fputs(kHelp, stdout);
      return 0;
    } else if (a == "--size") {
      parseSize(value(), w, h);
    } else if (a == "--samples") {
      opt.samples = positiveInt(a, value());
    } else if (a == "--target-error") {
      opt.target_rel_error = floatInRange(a, value(), 0.0f, 1e6f);  // 0: off
    } else if (a == "--threads") {
      opt.threads = intInRange(a, value(), 0, 4096);
    } else if (a == "--visibility") {
      opt.visibility = parseOnOff(a, value());
    } else if (a == "--ao-distance") {
      opt.ao_distance =
          float(numberInRange(a, value(), 1e-6, std::numeric_limits<double>::infinity()));
    } else if (a == "--hdr") {
      hdr = value();
    } else if (a == "--out") {
      out = value();
    } else if (a == "--aov") {
      aov = value();
    } else if (a == "--set") {
      overrides.push_back(value());
    } else {
      takeScenePath(a, scene_path);
    }
  }
  if (scene_path.empty()) throw UsageError{"no scene file given"};
  Scene scene = loadScene(scene_path, overrides);
  // Every output reserved before the (long) reference render: an unwritable path fails now, and
  // nothing appears unless all were written.
  OutputFiles files;
  SceneOpenOptions open;
  open.overrides = overrides;
  protectSceneInputs(files, scene_path, open, scene);  // --out scene.json: refused
  const std::filesystem::path hdr_tmp = hdr.empty() ? "" : files.add(hdr);
  const std::filesystem::path out_tmp = out.empty() ? "" : files.add(out);
  std::vector<std::filesystem::path> aov_tmp;
  if (!aov.empty()) {
    std::filesystem::create_directories(aov);
    for (int k = 0; k < kReferenceAovCount; ++k) {
      const auto which = static_cast<ReferenceAov>(k);
      aov_tmp.push_back(
          files.add(std::filesystem::path(aov) / (std::string(toString(which)) + ".pfm")));
    }
    aov_tmp.push_back(files.add(std::filesystem::path(aov) / "ambient_occlusion.pfm"));
  }
  if (!w) {
    w = scene.settings.width;
    h = scene.settings.height;
  }
  auto ctx = createHeadlessContext();
  render::Renderer renderer;
  renderer.setScene(scene);
  renderer.render(w, h);
  const GBufferReadback g = renderer.readGBuffer();
  const ReferenceResult r = renderReference(scene, g, opt);
  printSummary(r, w, h);
  if (!hdr.empty()) writePfm(hdr_tmp.string(), r.image);
  if (!out.empty()) writePng(out_tmp.string(), toneMapped(r.image, scene.settings.exposure));
  for (int k = 0; k < kReferenceAovCount && k < int(aov_tmp.size()); ++k) {
    writePfm(aov_tmp[size_t(k)].string(), r[static_cast<ReferenceAov>(k)]);
  }
  if (!aov_tmp.empty()) writePfm(aov_tmp.back().string(), r.ao);
  files.commit();
  return 0;
}

}  // namespace hv::app
