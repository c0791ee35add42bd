#include "halfvec/eval/occlusion_accuracy.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>

#include "halfvec/eval/engine_aov.hpp"
#include "halfvec/ibl/sky_sun.hpp"
#include "halfvec/reference/reference.hpp"
#include "halfvec/render/renderer.hpp"
#include "halfvec/scene/primitives.hpp"
#include "halfvec/scene/scene_loader.hpp"

namespace hv::eval {

namespace fs = std::filesystem;

namespace {

Material grey(float albedo = 0.5f, float roughness = 1.0f, float metallic = 0.0f) {
  Material m;
  m.base_color = glm::vec3(albedo);
  m.roughness = roughness;
  m.metallic = metallic;
  return m;
}

Scene uniformScene(glm::vec3 eye, glm::vec3 target) {
  Scene s;
  s.camera.position = eye;
  s.camera.target = target;
  s.camera.fov_y_deg = 45.0f;
  s.environment.kind = EnvironmentKind::Uniform;
  s.environment.color = glm::vec3(1.0f);
  s.environment.cube_size = 32;
  s.environment.prefilter_samples = 64;
  addMeshObject(s, makePlane(40.0f, 40.0f), grey(), glm::vec3(0.0f));
  return s;
}

// A sphere of radius 0.5 m resting on the floor, seen from 3 m away and 2.5 m up.
Scene restingSphere() {
  Scene s = uniformScene({0.0f, 2.5f, 3.0f}, {0.0f, 0.3f, 0.0f});
  addMeshObject(s, makeSphere(0.5f, 96, 48), grey(0.5f, 0.3f), {0.0f, 0.5f, 0.0f});
  return s;
}

// Two 2 m walls meeting the floor and each other at a right angle (the concave corner at the
// origin), a glossy dielectric floor.
Scene boxCorner() {
  Scene s = uniformScene({2.2f, 1.6f, 2.2f}, {-0.4f, 0.4f, -0.4f});
  s.materials[0] = grey(0.5f, 0.4f);
  addMeshObject(s, makeBox({2.0f, 1.0f, 0.1f}), grey(), {1.0f, 1.0f, -0.1f});
  addMeshObject(s, makeBox({0.1f, 1.0f, 2.0f}), grey(), {-0.1f, 1.0f, 1.0f});
  return s;
}

// Five steps of 0.2 m rise and 0.3 m run, seen from the front and above.
Scene stairs() {
  Scene s = uniformScene({1.8f, 1.8f, 2.4f}, {0.0f, 0.4f, -0.6f});
  for (int k = 0; k < 5; ++k) {
    const float h = 0.2f * float(k + 1);
    addMeshObject(s, makeBox({1.0f, 0.5f * h, 0.15f}), grey(0.5f, 0.6f),
                  {0.0f, 0.5f * h, -0.3f * float(k)});
  }
  return s;
}

struct Case {
  std::string name;
  Scene scene;
  std::string skipped;
};

std::vector<Case> cases(const AccuracyOptions& o) {
  std::vector<Case> out = {{"resting sphere", restingSphere(), ""},
                           {"box corner", boxCorner(), ""},
                           {"stairs", stairs(), ""}};
  const fs::path helmet =
      fs::path(o.assets_dir) / "gltf" / "DamagedHelmet" / "glTF-Binary" / "DamagedHelmet.glb";
  for (const char* env : {"venice_sunset_1k.hdr", "studio_small_03_1k.hdr"}) {
    const fs::path hdr = fs::path(o.assets_dir) / "env" / env;
    Case c{std::string("DamagedHelmet, ") + fs::path(env).stem().string(), Scene{}, ""};
    std::error_code ec;
    if (o.assets_dir.empty() || !fs::exists(helmet, ec) || !fs::exists(hdr, ec)) {
      c.skipped = "needs " + helmet.string() + " and " + hdr.string() + " (set HV_ASSETS_DIR)";
    } else {
      // helmet_sunset's camera and helmet, the environment alone (no lights).
      c.scene = loadScene((fs::path(o.scenes_dir) / "helmet_sunset.json").string());
      c.scene.lights.clear();
      c.scene.environment.kind = EnvironmentKind::HdrFile;
      c.scene.environment.path = hdr.string();
      if (o.quick) c.scene.environment.cube_size = 64;
    }
    out.push_back(std::move(c));
  }
  return out;
}

double relError(const ImageRGBf& e, const ImageRGBf& r, const std::vector<bool>& use,
                bool signed_error) {
  double num = 0.0, den = 0.0;
  for (size_t i = 0; i < r.px.size(); ++i) {
    if (!use[i]) continue;
    for (int c = 0; c < 3; ++c) {
      const double d = double(e.px[i][c]) - r.px[i][c];
      num += signed_error ? d : std::abs(d);
      den += r.px[i][c];
    }
  }
  return den > 0.0 ? num / den : 0.0;
}

ImageRGBf sum(const ImageRGBf& a, const ImageRGBf& b) {
  ImageRGBf out = a;
  for (size_t i = 0; i < out.px.size(); ++i) out.px[i] += b.px[i];
  return out;
}

double aoPassMs(render::Renderer& r, int w, int h) {
  const render::FrameStats st = r.render(w, h);
  for (const auto& [name, ms] : st.passes) {
    if (name == "ao") return ms;
  }
  return 0.0;
}

// The environment's light in term `diffuse` or specular: its ambient term plus the direct term,
// which in these scenes (no lights) holds only the environment's sun where settings.sky_sun draws
// it as a light (the reference books the sun's part of its samples there too).
ImageRGBf environmentTerm(const std::array<ImageRGBf, kReferenceAovCount>& aov, bool diffuse) {
  const auto a = size_t(diffuse ? ReferenceAov::AmbientDiffuse : ReferenceAov::AmbientSpecular);
  const auto d = size_t(diffuse ? ReferenceAov::DirectDiffuse : ReferenceAov::DirectSpecular);
  return sum(aov[a], aov[d]);
}

void measureCase(const AccuracyOptions& o, Case& c, OcclusionScene& out) {
  const auto AD = size_t(ReferenceAov::AmbientDiffuse);
  out.width = o.quick ? 48 : 160;
  out.height = out.width;
  out.samples = o.quick ? 16 : 1024;
  render::Renderer r;
  Scene& s = c.scene;
  const auto configs = occlusionConfigs(s.settings, environmentHasSun(s.environment));
  s.settings = configs[0].second;
  r.setScene(s);
  const auto none = renderEngineAovs(r, out.width, out.height);
  const GBufferReadback g = r.readGBuffer();
  std::vector<bool> lit(g.model.size());
  for (size_t i = 0; i < lit.size(); ++i) {
    lit[i] = isLit(ShadingModel(g.model[i]));
    out.lit_pixels += lit[i];
  }
  ReferenceOptions ro;
  ro.samples = out.samples;
  ro.threads = o.threads;
  ro.visibility = true;
  ro.ao_distance = RenderSettings{}.ao_radius;
  const ReferenceResult ref = renderReference(s, g, ro);
  const ImageRGBf ref_diffuse = environmentTerm(ref.aov, true);
  const ImageRGBf ref_specular = environmentTerm(ref.aov, false);
  const ImageRGBf ref_env = sum(ref_diffuse, ref_specular);
  const ImageRGBf ref_se =
      sum(environmentTerm(ref.aov_std_error, true), environmentTerm(ref.aov_std_error, false));
  double se = 0.0, rs = 0.0;
  for (size_t i = 0; i < lit.size(); ++i) {
    if (!lit[i]) continue;
    se += ref_se.px[i].x + ref_se.px[i].y + ref_se.px[i].z;
    rs += ref_env.px[i].x + ref_env.px[i].y + ref_env.px[i].z;
  }
  out.reference_noise = rs > 0.0 ? se / rs : 0.0;
  // The shading alone: `ao none` against the reference without visibility (nothing occludes).
  ReferenceOptions open = ro;
  open.visibility = false;
  const ReferenceResult unoccluded = renderReference(s, g, open);
  out.shading_only =
      relError(sum(environmentTerm(none, true), environmentTerm(none, false)),
               sum(environmentTerm(unoccluded.aov, true), environmentTerm(unoccluded.aov, false)),
               lit, false);
  for (const auto& [name, settings] : configs) {
    s.settings = settings;
    r.setScene(s);
    const auto aov = renderEngineAovs(r, out.width, out.height);
    OcclusionRow row;
    row.config = name;
    double ao_abs = 0.0, ao_signed = 0.0;
    size_t n = 0;
    for (size_t i = 0; i < lit.size(); ++i) {
      const double open_px = none[AD].px[i].y;
      if (!lit[i] || open_px <= 1e-6) continue;
      const double d = std::clamp(aov[AD].px[i].y / open_px, 0.0, 1.0) - ref.ao.px[i].x;
      ao_abs += std::abs(d);
      ao_signed += d;
      ++n;
    }
    row.ao_mean_abs = n ? ao_abs / double(n) : 0.0;
    row.ao_bias = n ? ao_signed / double(n) : 0.0;
    const ImageRGBf diffuse = environmentTerm(aov, true), specular = environmentTerm(aov, false);
    const ImageRGBf env = sum(diffuse, specular);
    row.ambient = relError(env, ref_env, lit, false);
    row.ambient_bias = relError(env, ref_env, lit, true);
    row.diffuse = relError(diffuse, ref_diffuse, lit, false);
    row.specular = relError(specular, ref_specular, lit, false);
    row.ms = settings.ao == AmbientOcclusion::None ? 0.0 : aoPassMs(r, out.width, out.height);
    out.rows.push_back(row);
  }
}

}  // namespace

std::vector<std::pair<std::string, RenderSettings>> occlusionConfigs(const RenderSettings& base,
                                                                     bool sun) {
  std::vector<std::pair<std::string, RenderSettings>> out;
  RenderSettings none = base;
  none.ao = AmbientOcclusion::None;
  out.push_back({"ao none", none});
  RenderSettings gtao = none;
  gtao.ao = AmbientOcclusion::Gtao;
  out.push_back({"gtao", gtao});
  auto variant = [&](const std::string& n, auto&& change) {
    RenderSettings v = gtao;
    change(v);
    out.push_back({"gtao, " + n, v});
  };
  variant("ao_specular=lagarde", [](RenderSettings& v) { v.ao_specular = AoSpecular::Lagarde; });
  variant("ao_specular=none", [](RenderSettings& v) { v.ao_specular = AoSpecular::None; });
  variant("ao_specular=cone", [](RenderSettings& v) { v.ao_specular = AoSpecular::Cone; });
  variant("ao_specular=traced", [](RenderSettings& v) { v.ao_specular = AoSpecular::Traced; });
  variant("ao_resolution=full", [](RenderSettings& v) { v.ao_resolution = AoResolution::Full; });
  variant("ao_quality=high", [](RenderSettings& v) { v.ao_quality = AoQuality::High; });
  variant("ao_radius=2", [](RenderSettings& v) { v.ao_radius = 2.0f; });
  if (sun) {
    // The environment's sun: in the prefiltered cube, or a light with its shadow.
    variant("sky_sun=environment", [](RenderSettings& v) { v.sky_sun = SkySun::Environment; });
    variant("sky_sun=shadowed_light", [](RenderSettings& v) { v.sky_sun = SkySun::ShadowedLight; });
  }
  return out;
}

OcclusionAccuracy measureOcclusion(const AccuracyOptions& o) {
  const auto t0 = std::chrono::steady_clock::now();
  OcclusionAccuracy a;
  for (Case& c : cases(o)) {
    OcclusionScene out;
    out.name = c.name;
    out.skipped = c.skipped;
    if (c.skipped.empty()) measureCase(o, c, out);
    a.scenes.push_back(std::move(out));
  }
  a.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return a;
}

}  // namespace hv::eval
