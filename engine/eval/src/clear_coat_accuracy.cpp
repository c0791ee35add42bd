// The clear-coat section of `halfvec accuracy` (docs/accuracy-clear-coat.md): a coated sphere
// under each light type and the sky, engine against the reference's integral of both lobes
// (clear_coat.glsl), beside the same sphere without its coat.
#include <chrono>
#include <cstdio>
#include <stdexcept>

#include "halfvec/eval/accuracy_report.hpp"
#include "halfvec/reference/reference.hpp"
#include "halfvec/render/renderer.hpp"
#include "halfvec/scene/primitives.hpp"
#include "lit_stats.hpp"

namespace hv::eval {

Scene clearCoatScene(const std::string& light, float coat, float coat_roughness) {
  Scene s;
  s.camera.position = {0.0f, 1.6f, 3.2f};
  s.camera.target = {0.0f, 0.55f, 0.0f};
  Material floor;
  floor.base_color = {0.5f, 0.5f, 0.5f};
  floor.roughness = 0.7f;
  addMeshObject(s, makePlane(6.0f, 6.0f), floor, glm::vec3(0.0f));
  Material paint;
  paint.base_color = {0.6f, 0.5f, 0.4f};
  paint.roughness = 0.6f;
  paint.clearcoat = coat;
  paint.clearcoat_roughness = coat_roughness;
  paint.model = coat > 0.0f ? ShadingModel::ClearCoat : ShadingModel::DefaultLit;
  addMeshObject(s, makeSphere(0.55f, 64, 32), paint, {0.0f, 0.55f, 0.0f});
  s.environment.kind = light == "sky" ? EnvironmentKind::Sky : EnvironmentKind::None;
  // The sky's sun in the cube: the sky rows measure the coat's split-sum lobe (a directional
  // light, as sky_sun: light draws the sun, is the "sun" rows' case).
  s.settings.sky_sun = SkySun::Environment;
  s.settings.falloff_plus_one = false;
  if (light == "sky") return s;
  Light l;
  l.position = {1.2f, 2.2f, 2.0f};
  l.intensity = 8.0f;
  l.range = 20.0f;
  if (light == "sphere") {
    l.type = LightType::Sphere;
    l.radius = 0.15f;
  } else if (light == "tube") {
    l.type = LightType::Tube;
    l.radius = 0.05f;
    l.length = 0.8f;
    l.axis = glm::normalize(glm::vec3(1.0f, 0.0f, -0.5f));
  } else if (light == "sun") {
    l.type = LightType::Directional;
    l.direction = glm::normalize(glm::vec3(-0.4f, -1.0f, -0.7f));
    l.intensity = 3.0f;
  } else if (light != "point") {
    throw std::invalid_argument("clearCoatScene: unknown light '" + light + "'");
  }
  s.lights.push_back(l);
  return s;
}

namespace {

struct Method {
  const char* name;
  void (*apply)(RenderSettings&);
};

}  // namespace

ClearCoatAccuracy measureClearCoat(const AccuracyOptions& o) {
  const auto t0 = std::chrono::steady_clock::now();
  ClearCoatAccuracy a;
  a.width = o.quick ? 64 : 160;
  a.height = o.quick ? 48 : 120;
  a.samples = o.quick ? 16 : 256;
  const std::vector<float> roughness =
      o.quick ? std::vector<float>{0.1f} : std::vector<float>{0.03f, 0.1f, 0.3f};
  const Method rp{"representative point", [](RenderSettings& s) {
                    s.sphere_specular = SphereSpecular::RepresentativePoint;
                    s.tube_specular = TubeSpecular::ClosestPointEq19;
                  }};
  const Method ltc{"ltc", [](RenderSettings& s) {
                     s.sphere_specular = SphereSpecular::Ltc;
                     s.tube_specular = TubeSpecular::Ltc;
                   }};
  const Method ltc_diffuse{"ltc, ltc diffuse", [](RenderSettings& s) {
                             s.tube_specular = TubeSpecular::Ltc;
                             s.tube_diffuse = TubeDiffuse::Ltc;
                           }};
  const Method split{"split sum", [](RenderSettings&) {}};
  const struct {
    const char* light;
    std::vector<Method> methods;
  } lights[] = {{"sphere", {rp, ltc}},
                {"tube", {rp, ltc, ltc_diffuse}},
                {"sun", {rp, ltc}},
                {"sky", {split}}};
  ReferenceOptions ro;
  ro.samples = a.samples;
  ro.threads = o.threads;
  ro.visibility = false;
  // Renders scene s with method m; the engine's image, its G-buffer and the reference on it.
  struct Shot {
    ImageRGBf engine;
    GBufferReadback g;
  };
  auto shoot = [&](Scene s, const Method& m) {
    m.apply(s.settings);
    render::Renderer r;
    r.setScene(s);
    r.render(a.width, a.height);
    return Shot{r.readHdr(), r.readGBuffer()};
  };
  for (const auto& l : lights) {
    // Without the coat: the base alone, per method, over the pixels the coat covers below.
    std::vector<Shot> bare;
    for (const Method& m : l.methods) bare.push_back(shoot(clearCoatScene(l.light, 0.0f, 0.0f), m));
    const ReferenceResult bare_ref =
        renderReference(clearCoatScene(l.light, 0.0f, 0.0f), bare[0].g, ro);
    for (float cr : roughness) {
      const Scene s = clearCoatScene(l.light, 1.0f, cr);
      ReferenceResult ref;
      for (size_t k = 0; k < l.methods.size(); ++k) {
        const Shot e = shoot(s, l.methods[k]);
        if (k == 0) ref = renderReference(s, e.g, ro);
        const GBufferReadback& g = e.g;
        const PixelMask coated = [&g](size_t i) {
          return g.model[i] == uint32_t(ShadingModel::ClearCoat);
        };
        ClearCoatAccuracy::Row row;
        row.light = l.light;
        row.method = l.methods[k].name;
        row.coat_roughness = cr;
        row.coated = litStats(e.engine, ref.image, ref.std_error, coated);
        row.bare = litStats(bare[k].engine, bare_ref.image, bare_ref.std_error, coated);
        a.rows.push_back(row);
        std::fprintf(stderr, "accuracy: clear coat %zu: %s, %s, coat roughness %.2f\n",
                     a.rows.size(), row.light.c_str(), row.method.c_str(), double(cr));
      }
    }
  }
  a.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return a;
}

}  // namespace hv::eval
