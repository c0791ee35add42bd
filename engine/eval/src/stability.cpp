#include "halfvec/eval/stability.hpp"

#include <cmath>

#include "halfvec/render/renderer.hpp"
#include "halfvec/scene/enums.hpp"
#include "halfvec/scene/primitives.hpp"

namespace hv::eval {

namespace {

// Four spheres: (metallic 0/1) x (base color black/white), all of one roughness, seen so that
// their silhouettes give N.V -> 0 and the light gives N.L from 1 to 0 (and below).
Scene baseScene(float roughness) {
  Scene s;
  s.camera.position = {0.0f, 0.0f, 7.0f};
  s.camera.target = {0.0f, 0.0f, 0.0f};
  s.camera.fov_y_deg = 50.0f;
  s.environment.kind = EnvironmentKind::None;
  const Mesh sphere = makeSphere(1.0f, 32, 16);
  int i = 0;
  for (float metallic : {0.0f, 1.0f}) {
    for (float base : {0.0f, 1.0f}) {
      Material m;
      m.base_color = glm::vec3(base);
      m.metallic = metallic;
      m.roughness = roughness;
      addMeshObject(s, sphere, m, {(i % 2) * 2.2f - 1.1f, (i / 2) * 2.2f - 1.1f, 0.0f});
      ++i;
    }
  }
  return s;
}

struct Geometry {
  std::string name;
  std::function<void(Light&)> apply;
};

// Light configurations relative to the sphere at (-1.1, -1.1, 0) (radius 1). Each geometry is
// applied to each light type; radius/length only matter for sphere/tube.
std::vector<Geometry> geometries() {
  const glm::vec3 c(-1.1f, -1.1f, 0.0f);
  return {
      {"front d=2", [c](Light& l) { l.position = c + glm::vec3(0, 0, 3); }},
      {"at surface (inside light)",
       [c](Light& l) {
         l.position = c + glm::vec3(0, 0, 1);
         l.radius = std::max(l.radius, 0.3f);
       }},
      {"at center of sphere", [c](Light& l) { l.position = c; }},
      {"distance 1e-6", [c](Light& l) { l.position = c + glm::vec3(0, 0, 1.000001f); }},
      {"distance 1e6",
       [c](Light& l) {
         l.position = c + glm::vec3(0, 0, 1e6f);
         l.range = 2e6f;
       }},
      {"grazing (N.L=0 at front)", [c](Light& l) { l.position = c + glm::vec3(3, 0, 0); }},
      {"radius 0, length 0",
       [c](Light& l) {
         l.position = c + glm::vec3(0, 0, 3);
         l.radius = 0;
         l.length = 0;
       }},
      {"intensity 1e6",
       [c](Light& l) {
         l.position = c + glm::vec3(0, 0, 1.5f);
         l.intensity = 1e6f;
       }},
      {"huge radius 10",
       [c](Light& l) {
         l.position = c + glm::vec3(0, 0, 3);
         l.radius = 10.0f;
       }},
  };
}

struct Option {
  std::string name;
  std::function<void(RenderSettings&)> apply;
  bool shadows = false;    // the light casts shadows (the spheres shadow each other)
  bool occlusion = false;  // the screen-space AO scene (addOcclusionScene)
  bool coat = false;       // every sphere under a full clear coat of the spheres' roughness
  bool sky = false;        // lit by the procedural sky (a sun in the environment) as well
};

// What screen-space AO needs to meet its edge cases: an environment to occlude, a floor the
// lower spheres rest on that runs out to the horizon (depths down to the far end of float
// precision beside the background's 0), and a sphere cut by the near plane at the image's edge
// (depths up to 1 and beyond).
void addOcclusionScene(Scene& s) {
  s.environment.kind = EnvironmentKind::Uniform;
  s.environment.color = glm::vec3(1.0f);
  s.environment.cube_size = 16;
  s.environment.prefilter_samples = 16;
  Material floor;
  floor.base_color = glm::vec3(0.8f);
  floor.roughness = 0.5f;
  addMeshObject(s, makePlane(1e5f, 1e5f), floor, {0.0f, -2.1f, 0.0f});
  Material near;
  near.metallic = 1.0f;
  near.roughness = 0.0f;
  // 1 cm across, its centre on the near plane in the upper right corner of the view: the plane
  // cuts it on screen.
  addMeshObject(s, makeSphere(0.01f, 32, 16), near,
                s.camera.position + glm::vec3(0.02f, 0.015f, -s.camera.near_plane));
}

void add(std::vector<Option>& o, std::string name, std::function<void(RenderSettings&)> f) {
  o.push_back({std::move(name), std::move(f)});
}

// Each BRDF term's other values (D, V, F, diffuse) and the roughness remap off.
void addBrdfOptions(std::vector<Option>& o) {
  for (auto d : {DistributionTerm::Beckmann, DistributionTerm::BlinnPhong}) {
    add(o, std::string("d=") + std::string(toString(d)), [d](RenderSettings& s) { s.d = d; });
  }
  for (int v = 1; v <= static_cast<int>(VisibilityTerm::Implicit); ++v) {
    const auto vt = static_cast<VisibilityTerm>(v);
    add(o, std::string("v=") + std::string(toString(vt)), [vt](RenderSettings& s) { s.v = vt; });
  }
  for (int f = 1; f <= static_cast<int>(FresnelTerm::SchlickF90Occlusion); ++f) {
    const auto ft = static_cast<FresnelTerm>(f);
    add(o, std::string("f=") + std::string(toString(ft)), [ft](RenderSettings& s) { s.f = ft; });
  }
  add(o, "diffuse=burley", [](RenderSettings& s) { s.diffuse = DiffuseTerm::Burley; });
  add(o, "remap_roughness=false", [](RenderSettings& s) { s.remap_roughness = false; });
}

// The light options one at a time (falloff, the sphere and tube methods, culling), then the
// three ltc modes together.
void addLightOptions(std::vector<Option>& o) {
  add(o, "falloff_plus_one=false", [](RenderSettings& s) { s.falloff_plus_one = false; });
  add(o, "sphere_diffuse=horizon_correct",
      [](RenderSettings& s) { s.sphere_diffuse = SphereDiffuse::HorizonCorrect; });
  add(o, "sphere_normalization=false", [](RenderSettings& s) { s.sphere_normalization = false; });
  add(o, "tube_specular=smallest_angle_eq18",
      [](RenderSettings& s) { s.tube_specular = TubeSpecular::SmallestAngleEq18; });
  add(o, "tube_normalization=false", [](RenderSettings& s) { s.tube_normalization = false; });
  add(o, "culling=brute_force", [](RenderSettings& s) { s.culling = Culling::BruteForce; });
  add(o, "sphere_specular=ltc", [](RenderSettings& s) { s.sphere_specular = SphereSpecular::Ltc; });
  add(o, "tube_specular=ltc", [](RenderSettings& s) { s.tube_specular = TubeSpecular::Ltc; });
  add(o, "tube_diffuse=ltc", [](RenderSettings& s) { s.tube_diffuse = TubeDiffuse::Ltc; });
  add(o, "ltc (all three)", [](RenderSettings& s) {
    s.sphere_specular = SphereSpecular::Ltc;
    s.tube_specular = TubeSpecular::Ltc;
    s.tube_diffuse = TubeDiffuse::Ltc;
  });
}

// Shadowed lights (docs/lights.md, "Shadows"): each filter, PCSS with the smallest maps (the
// largest texels, so the largest biases and filters), with the half-resolution mask and with the
// high quality search.
void addShadowOptions(std::vector<Option>& o) {
  for (ShadowFilter f : {ShadowFilter::Pcss, ShadowFilter::Pcf, ShadowFilter::Hard}) {
    o.push_back({"shadows, shadow_filter=" + std::string(toString(f)),
                 [f](RenderSettings& s) { s.shadow_filter = f; }, true});
  }
  o.push_back(
      {"shadows, shadow_map_size=16", [](RenderSettings& s) { s.shadow_map_size = 16; }, true});
  // The shadow mask: PCSS once per 2x2 pixels, upsampled (shadow_mask.glsl).
  o.push_back({"shadows, shadow_resolution=half",
               [](RenderSettings& s) { s.shadow_resolution = ShadowResolution::Half; }, true});
  // PCSS's 32-gather blocker search.
  o.push_back({"shadows, shadow_quality=high",
               [](RenderSettings& s) { s.shadow_quality = ShadowQuality::High; }, true});
}

// Screen-space AO (docs/ambient-occlusion.md) on its edge-case scene: each specular occlusion,
// full resolution with the multi-bounce fit, and radii far below and far above the scene.
void addOcclusionOptions(std::vector<Option>& o) {
  for (AoSpecular so :
       {AoSpecular::Cone, AoSpecular::Lagarde, AoSpecular::Traced, AoSpecular::None}) {
    o.push_back({"ao=gtao, ao_specular=" + std::string(toString(so)),
                 [so](RenderSettings& s) {
                   s.ao = AmbientOcclusion::Gtao;
                   s.ao_specular = so;
                 },
                 false, true});
  }
  o.push_back({"ao=gtao, full, high, multi-bounce",
               [](RenderSettings& s) {
                 s.ao = AmbientOcclusion::Gtao;
                 s.ao_resolution = AoResolution::Full;
                 s.ao_quality = AoQuality::High;
                 s.ao_multi_bounce = true;
               },
               false, true});
  for (float radius : {1e-4f, 1e4f}) {
    o.push_back({"ao=gtao, ao_radius=" + std::string(radius < 1.0f ? "1e-4" : "1e4"),
                 [radius](RenderSettings& s) {
                   s.ao = AmbientOcclusion::Gtao;
                   s.ao_radius = radius;
                 },
                 false, true});
  }
}

// Clear coat (clear_coat.glsl): the coat's lobe at the same extremes as the base's, with the
// representative-point and the LTC methods, and under screen-space AO (the coat's occlusion).
void addClearCoatOptions(std::vector<Option>& o) {
  o.push_back({"clear coat", [](RenderSettings&) {}, false, false, true});
  o.push_back({"clear coat, ltc (all three)",
               [](RenderSettings& s) {
                 s.sphere_specular = SphereSpecular::Ltc;
                 s.tube_specular = TubeSpecular::Ltc;
                 s.tube_diffuse = TubeDiffuse::Ltc;
               },
               false, false, true});
  o.push_back({"clear coat, ao=gtao, ao_specular=cone",
               [](RenderSettings& s) {
                 s.ao = AmbientOcclusion::Gtao;
                 s.ao_specular = AoSpecular::Cone;
               },
               false, true, true});
  o.push_back({"clear coat, ao=gtao, ao_specular=traced",
               [](RenderSettings& s) {
                 s.ao = AmbientOcclusion::Gtao;
                 s.ao_specular = AoSpecular::Traced;
               },
               false, true, true});
}

// The procedural sky: its sun as a directional light (sky_sun: light, the default) beside the
// geometry's own light, and in the cube (environment), the brightest texels the lobe-sampled
// ambient specular (ibl.glsl, sampledAmbientSpecular) meets; on the bare spheres (roughness 0 and
// 1, N.V down to 0 at their outlines) and under a clear coat (the coat's lobe sampled too).
void addIblOptions(std::vector<Option>& o) {
  auto sampled = [](RenderSettings& s) { s.ibl_specular = IblSpecular::Sampled; };
  auto sun_in_cube = [](RenderSettings& s) {
    s.ibl_specular = IblSpecular::Sampled;
    s.sky_sun = SkySun::Environment;
  };
  o.push_back({"sky, ibl_specular=sampled", sampled, false, false, false, true});
  o.push_back(
      {"sky, sky_sun=environment, ibl_specular=sampled", sun_in_cube, false, false, false, true});
  o.push_back({"clear coat, sky, ibl_specular=sampled", sampled, false, false, true, true});
  o.push_back({"sky, sky_sun=shadowed_light",
               [](RenderSettings& s) { s.sky_sun = SkySun::ShadowedLight; }, false, false, false,
               true});
}

// The error budget (error_budget.glsl): a budget that takes the LTC almost everywhere, one that
// splits pixels between the methods, and one that almost never does; on the clear coat's lobe
// too (its own Surface, the same choice).
void addBudgetOptions(std::vector<Option>& o) {
  for (const char* b : {"1e-6", "0.05", "1"}) {
    const float v = std::stof(b);
    o.push_back({std::string("max_error=") + b, [v](RenderSettings& s) { s.max_error = v; }});
  }
  o.push_back({"clear coat, max_error=0.05", [](RenderSettings& s) { s.max_error = 0.05f; }, false,
               false, true});
}

// CI: the options whose code paths differ most (physical falloff divides by d^2 alone).
std::vector<Option> ciSubset(const std::vector<Option>& all) {
  std::vector<Option> keep;
  for (const auto& x : all) {
    if (x.name == "default" || x.name == "falloff_plus_one=false" ||
        x.name == "v=smith_ggx_correlated" || x.name == "f=exact" ||
        x.name == "sphere_diffuse=horizon_correct" ||
        x.name == "tube_specular=smallest_angle_eq18" || x.name == "d=beckmann" ||
        x.name == "diffuse=burley" || x.name == "ltc (all three)" ||
        x.name == "shadows, shadow_filter=pcss" || x.name == "ao=gtao, ao_specular=cone" ||
        x.name == "clear coat, ltc (all three)" || x.name == "max_error=0.05" ||
        x.name == "sky, ibl_specular=sampled" ||
        x.name == "sky, sky_sun=environment, ibl_specular=sampled") {
      keep.push_back(x);
    }
  }
  return keep;
}

std::vector<Option> options(bool small) {
  std::vector<Option> o = {{"default", [](RenderSettings&) {}}};
  addBrdfOptions(o);
  addLightOptions(o);
  addShadowOptions(o);
  addOcclusionOptions(o);
  addClearCoatOptions(o);
  addIblOptions(o);
  addBudgetOptions(o);
  return small ? ciSubset(o) : o;
}

}  // namespace

std::vector<StabilityRow> runStabilitySweep(
    const StabilityOptions& opts, const std::function<void(const StabilityRow&)>& progress) {
  std::vector<StabilityRow> rows;
  render::Renderer renderer;
  for (const Option& opt : options(opts.small)) {
    for (LightType type : {LightType::Point, LightType::Sphere, LightType::Tube, LightType::Spot,
                           LightType::Directional}) {
      for (const Geometry& g : geometries()) {
        StabilityRow row{std::string(toString(type)), g.name, opt.name};
        for (float roughness : {0.0f, 1.0f}) {
          Scene scene = baseScene(roughness);
          if (opt.occlusion) addOcclusionScene(scene);
          if (opt.sky) {
            scene.environment.kind = EnvironmentKind::Sky;
            scene.environment.cube_size = 32;
            scene.environment.prefilter_samples = 16;
          }
          if (opt.coat) {
            for (Material& m : scene.materials) {
              m.model = ShadingModel::ClearCoat;
              m.clearcoat = 1.0f;
              m.clearcoat_roughness = roughness;
            }
          }
          opt.apply(scene.settings);
          Light l;
          l.type = type;
          l.intensity = 50.0f;
          l.range = 20.0f;
          l.radius = type == LightType::Point ? 0.0f : 0.2f;
          l.length = type == LightType::Tube ? 1.0f : 0.0f;
          l.axis = glm::normalize(glm::vec3(1, 1, 0));
          g.apply(l);
          if (type == LightType::Point) {
            l.radius = 0.0f;
            l.length = 0.0f;
          }
          if (type == LightType::Sphere) l.length = 0.0f;
          if (type == LightType::Spot) {
            // Aimed at the sphere's center (the default direction where it sits there), the
            // sphere across the cone's smooth edge; radius 0.2 (a sphere spot) unless the
            // geometry sets 0 (a point spot).
            const glm::vec3 to_center = glm::vec3(-1.1f, -1.1f, 0.0f) - l.position;
            if (glm::length(to_center) > 1e-3f) l.direction = glm::normalize(to_center);
            l.inner_cone_angle = 0.1f;
            l.outer_cone_angle = 0.4f;
            l.length = 0.0f;
          }
          if (type == LightType::Directional) {
            // From the geometry's light position toward the sphere's center, the disk as wide
            // as the geometry's sphere seen from there: 0 for radius 0, pi/2 (the largest) from
            // inside it or for the huge radius, the sun-like 4e-7 at distance 1e6.
            const glm::vec3 to_center = glm::vec3(-1.1f, -1.1f, 0.0f) - l.position;
            const float d = glm::length(to_center);
            l.direction = d > 1e-3f ? to_center / d : glm::vec3(0.0f, 0.0f, -1.0f);
            l.angular_diameter = l.radius <= 0.0f ? 0.0f
                                 : d > l.radius
                                     ? std::min(2.0f * std::asin(l.radius / d), kMaxAngularDiameter)
                                     : kMaxAngularDiameter;
          }
          l.shadows = opt.shadows;
          scene.lights.push_back(l);
          renderer.setScene(scene);
          renderer.render(opts.size, opts.size);
          const ImageRGBf hdr = renderer.readHdr();
          for (const auto& p : hdr.px) {
            bool nan = false, inf = false, neg = false;
            for (int k = 0; k < 3; ++k) {
              nan |= std::isnan(p[k]);
              inf |= std::isinf(p[k]);
              neg |= p[k] < 0.0f;
              if (std::isfinite(p[k])) row.max_value = std::max(row.max_value, p[k]);
            }
            row.nan += nan;
            row.inf += inf;
            row.negative += neg;
          }
        }
        if (progress) progress(row);
        rows.push_back(row);
      }
    }
  }
  return rows;
}

}  // namespace hv::eval
