// Rules of the variant key (docs/variants.md), without GL: which material features a material
// needs, which settings change code in which scene, which keys are valid, and the defines (with
// their reasons) each pass gets.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>

#include "halfvec/render/variant_key.hpp"
#include "halfvec/scene/primitives.hpp"

using namespace hv;
using namespace hv::render;

namespace {

Light light(LightType t) {
  Light l;
  l.type = t;
  l.radius = t == LightType::Point ? 0.0f : 0.1f;
  l.length = t == LightType::Tube ? 0.5f : 0.0f;
  return l;
}

// Materials drawn by one plane each (in order); no lights, environment none.
Scene sceneWith(const std::vector<Material>& mats) {
  Scene s;
  s.environment.kind = EnvironmentKind::None;
  for (size_t i = 0; i < mats.size(); ++i) {
    s.materials.push_back(mats[i]);
    s.meshes.push_back(makePlane(1.0f, 1.0f));
    s.meshes.back().material = int(i);
    Object o;
    o.meshes = {int(i)};
    s.objects.push_back(o);
  }
  return s;
}

TextureRef tex(int texcoord = 0) {
  TextureRef t;
  t.image = 0;
  t.texcoord = texcoord;
  return t;
}

std::map<std::string, KeyDefine> byName(const std::vector<KeyDefine>& defs) {
  std::map<std::string, KeyDefine> m;
  for (const auto& d : defs) m[d.name] = d;
  return m;
}

}  // namespace

TEST(VariantKey, MaterialFeaturesFollowTheMaterial) {
  Material plain;
  EXPECT_EQ(materialFeatures(plain), MaterialFeatures{});
  EXPECT_EQ(materialFeatures(plain).text(), "none");

  Material m;
  m.base_color_tex = tex();
  m.normal_tex = tex();
  m.alpha_mode = AlphaMode::Mask;
  m.double_sided = true;
  const MaterialFeatures f = materialFeatures(m);
  EXPECT_TRUE(f.base_color_map);
  EXPECT_TRUE(f.normal_map);
  EXPECT_TRUE(f.alpha_mask);
  EXPECT_TRUE(f.double_sided);
  EXPECT_FALSE(f.metal_rough_map);
  EXPECT_FALSE(f.occlusion_map);
  EXPECT_FALSE(f.emissive);
  EXPECT_FALSE(f.uv1);
  EXPECT_EQ(f.text(), "base_color_map+normal_map+alpha_mask+double_sided");

  // Blend is drawn as opaque: no alpha test.
  Material blend;
  blend.alpha_mode = AlphaMode::Blend;
  EXPECT_FALSE(materialFeatures(blend).alpha_mask);
}

TEST(VariantKey, MaterialRulesDropCodeThatChangesNothing) {
  // An emissive map multiplies the emissive constant: with a zero constant it is dropped, and
  // so is the second UV set only that map read.
  Material m;
  m.emissive_tex = tex(1);
  MaterialFeatures f = materialFeatures(m);
  EXPECT_FALSE(f.emissive);
  EXPECT_FALSE(f.emissive_map);
  EXPECT_FALSE(f.uv1);
  m.emissive = {1.0f, 0.5f, 0.0f};
  f = materialFeatures(m);
  EXPECT_TRUE(f.emissive);
  EXPECT_TRUE(f.emissive_map);
  EXPECT_TRUE(f.uv1);

  // Occlusion strength 0 leaves Cavity unchanged: no occlusion code.
  Material o;
  o.occlusion_tex = tex(1);
  o.occlusion_tex.scale = 0.0f;
  EXPECT_FALSE(materialFeatures(o).occlusion_map);
  EXPECT_FALSE(materialFeatures(o).uv1);
  o.occlusion_tex.scale = 0.7f;
  EXPECT_TRUE(materialFeatures(o).occlusion_map);
  EXPECT_TRUE(materialFeatures(o).uv1);
}

TEST(VariantKey, DerivedFromTheScene) {
  Material a, b, c, unused;
  a.name = "a";
  b.name = "b";
  b.normal_tex = tex();
  c.name = "c";
  c.model = ShadingModel::Unlit;
  unused.normal_tex = tex();
  unused.emissive = glm::vec3(1.0f);
  unused.model = ShadingModel::Unlit;
  Scene s = sceneWith({a, b, c});
  s.materials.push_back(unused);  // no mesh uses it
  s.lights = {light(LightType::Point), light(LightType::Tube), light(LightType::Tube)};
  s.environment.kind = EnvironmentKind::Sky;

  const VariantKey k = deriveVariantKey(s);
  EXPECT_TRUE(k.point_lights);
  EXPECT_FALSE(k.sphere_lights);
  EXPECT_TRUE(k.tube_lights);
  EXPECT_TRUE(k.default_lit);
  EXPECT_TRUE(k.unlit);
  EXPECT_EQ(k.environment, EnvironmentKind::Sky);
  EXPECT_TRUE(k.directional_lights);  // the sky's sun (settings.sky_sun: light, the default)
  EXPECT_FALSE(k.uber);
  // a and c have the same features (the shading model is data, not code): one program; b its own.
  ASSERT_EQ(k.material_variants.size(), 2u);
  EXPECT_EQ(k.material_variant[0], k.material_variant[2]);
  EXPECT_NE(k.material_variant[0], k.material_variant[1]);
  EXPECT_EQ(k.material_variant[3], -1);  // not drawn
  EXPECT_TRUE(k.material_variants[size_t(k.material_variant[1])].normal_map);
  EXPECT_TRUE(validateKey(k).empty());
  EXPECT_EQ(k.text(),
            "lights point+tube+directional; models default_lit+unlit; environment sky; 2 material "
            "variants; specialized");

  // Only unlit materials: no default_lit, so no ambient IBL code even with an environment.
  Scene u = sceneWith({c});
  u.environment.kind = EnvironmentKind::Uniform;
  const VariantKey ku = deriveVariantKey(u);
  EXPECT_FALSE(ku.default_lit);
  EXPECT_TRUE(ku.unlit);
  EXPECT_FALSE(ku.ambientIbl());
}

// A spot compiles its shape's code (a point, radius 0, or a sphere) and the cone; a scene without
// spots gets HV_HAS_SPOT_LIGHTS=0, so its light code is that of a scene before spots existed.
TEST(VariantKey, SpotIsItsShapeAndItsCone) {
  Material a;
  Scene s = sceneWith({a});
  Light spot = light(LightType::Spot);
  spot.radius = 0.0f;
  s.lights = {spot};
  VariantKey k = deriveVariantKey(s);
  EXPECT_TRUE(k.point_lights && k.spot_lights);
  EXPECT_FALSE(k.sphere_lights || k.tube_lights);
  EXPECT_EQ(k.text().substr(0, 18), "lights point+spot;");
  auto l = byName(lightDefines(k, s));
  EXPECT_EQ(l.at("HV_HAS_SPOT_LIGHTS").value, "1");
  EXPECT_EQ(l.at("HV_HAS_SPOT_LIGHTS").why, "1 spot light");
  EXPECT_EQ(l.at("HV_HAS_POINT_LIGHTS").why, "1 point light");
  s.lights[0].radius = 0.2f;  // a sphere spot: the sphere code, whose settings then count
  k = deriveVariantKey(s);
  EXPECT_TRUE(k.sphere_lights && k.spot_lights);
  EXPECT_FALSE(k.point_lights);
  s.lights[0].type = LightType::Sphere;
  k = deriveVariantKey(s);
  EXPECT_FALSE(k.spot_lights);
  l = byName(lightDefines(k, s));
  EXPECT_EQ(l.at("HV_HAS_SPOT_LIGHTS").value, "0");
  EXPECT_EQ(l.at("HV_HAS_SPOT_LIGHTS").why, "no spot lights");
}

// A directional light compiles its own loop and evaluation (HV_HAS_DIRECTIONAL_LIGHTS) and no
// other light type; it keeps the sphere settings, which govern it (a sphere at infinity), and
// with shadows: true compiles the shadow lookup (its orthographic map).
TEST(VariantKey, DirectionalKeepsTheSphereSettings) {
  Material a;
  Scene s = sceneWith({a});
  Light sun;
  sun.type = LightType::Directional;
  sun.shadows = true;
  s.lights = {sun};
  s.settings.sphere_specular = SphereSpecular::Ltc;
  s.settings.sphere_diffuse = SphereDiffuse::HorizonCorrect;
  VariantKey k = deriveVariantKey(s);
  EXPECT_TRUE(k.directional_lights && k.hasLights());
  EXPECT_FALSE(k.point_lights || k.sphere_lights || k.tube_lights || k.spot_lights);
  EXPECT_TRUE(k.shadows);
  EXPECT_EQ(k.text().substr(0, 19), "lights directional;");
  EXPECT_EQ(k.settings.sphere_specular, SphereSpecular::Ltc);
  EXPECT_EQ(k.settings.sphere_diffuse, SphereDiffuse::HorizonCorrect);
  EXPECT_TRUE(validateKey(k).empty());
  auto l = byName(lightDefines(k, s));
  EXPECT_EQ(l.at("HV_HAS_DIRECTIONAL_LIGHTS").value, "1");
  EXPECT_EQ(l.at("HV_HAS_DIRECTIONAL_LIGHTS").why, "1 directional light");
  EXPECT_EQ(l.at("HV_SHADOWS").value, "1");
  // Without it: HV_HAS_DIRECTIONAL_LIGHTS=0, and the sphere settings reset (no sphere either).
  s.lights[0].type = LightType::Point;
  s.lights[0].shadows = false;
  k = deriveVariantKey(s);
  EXPECT_FALSE(k.directional_lights);
  EXPECT_EQ(k.settings.sphere_specular, SphereSpecular::RepresentativePoint);
  l = byName(lightDefines(k, s));
  EXPECT_EQ(l.at("HV_HAS_DIRECTIONAL_LIGHTS").value, "0");
  EXPECT_EQ(l.at("HV_HAS_DIRECTIONAL_LIGHTS").why, "no directional lights");
}

TEST(VariantKey, UberTurnsEveryFeatureOn) {
  Material a;
  Scene s = sceneWith({a, a});
  s.settings.uber = true;
  const VariantKey k = deriveVariantKey(s);
  EXPECT_TRUE(k.uber);
  EXPECT_TRUE(k.point_lights && k.sphere_lights && k.tube_lights && k.spot_lights &&
              k.directional_lights);
  EXPECT_TRUE(k.unlit && k.default_lit);
  ASSERT_EQ(k.material_variants.size(), 1u);
  EXPECT_EQ(k.material_variants[0], allMaterialFeatures());
  EXPECT_EQ(k.material_variant, (std::vector<int>{0, 0}));
  EXPECT_TRUE(validateKey(k).empty());
  const auto g = byName(gbufferDefines(k, 0, s));
  EXPECT_EQ(g.at("HV_MAT_RUNTIME_FLAGS").value, "1");
  EXPECT_EQ(g.at("HV_MAT_NORMAL_MAP").value, "1");
  const auto l = byName(lightDefines(k, s));
  EXPECT_EQ(l.at("HV_HAS_TUBE_LIGHTS").value, "1");
  EXPECT_EQ(l.at("HV_HAS_TUBE_LIGHTS").why, "uber build (no tube lights)");
  // Without an environment the uber ambient program still has the IBL code, checked at run time.
  const auto a_defs = byName(ambientDefines(k, s));
  EXPECT_EQ(a_defs.at("HV_ENVIRONMENT").value, "1");
  EXPECT_EQ(a_defs.at("HV_ENV_RUNTIME_CHECK").value, "1");
}

TEST(VariantKey, RemapOnlyWithSchlickGGX) {
  EXPECT_TRUE(remapMeaningful(VisibilityTerm::SchlickGGX));
  EXPECT_FALSE(remapMeaningful(VisibilityTerm::SmithGGXCorrelated));
  EXPECT_FALSE(remapMeaningful(VisibilityTerm::SmithBeckmannSeparable));
  EXPECT_FALSE(remapMeaningful(VisibilityTerm::CookTorrance));
  EXPECT_FALSE(remapMeaningful(VisibilityTerm::Implicit));
  Scene s = sceneWith({Material{}});
  s.lights = {light(LightType::Point)};
  s.settings.v = VisibilityTerm::Implicit;
  s.settings.remap_roughness = true;
  const VariantKey k = deriveVariantKey(s);
  EXPECT_FALSE(k.settings.remap_roughness);
  const auto l = byName(lightDefines(k, s));
  EXPECT_EQ(l.at("HV_REMAP_ROUGHNESS").value, "0");
  EXPECT_NE(l.at("HV_REMAP_ROUGHNESS").why.find("Schlick-GGX only"), std::string::npos);
}

TEST(VariantKey, SettingsWithoutCodeAreCanonical) {
  // Two scenes that differ only in settings that change no code get the same defines.
  Scene a = sceneWith({Material{}});
  a.lights = {light(LightType::Point)};
  Scene b = a;
  b.settings.tube_specular = TubeSpecular::SmallestAngleEq18;  // no tubes
  b.settings.tube_normalization = false;
  b.settings.sphere_diffuse = SphereDiffuse::HorizonCorrect;  // no spheres
  b.settings.irradiance = Irradiance::Cubemap;                // no environment
  b.settings.energy_compensation = true;
  const VariantKey ka = deriveVariantKey(a), kb = deriveVariantKey(b);
  auto values = [](const std::vector<KeyDefine>& d) {
    std::vector<std::pair<std::string, std::string>> v;
    for (const auto& x : d) v.emplace_back(x.name, x.value);
    return v;
  };
  EXPECT_EQ(values(lightDefines(ka, a)), values(lightDefines(kb, b)));
  EXPECT_EQ(values(ambientDefines(ka, a)), values(ambientDefines(kb, b)));
  // ... and the reason says the setting was reset.
  const auto l = byName(lightDefines(kb, b));
  EXPECT_NE(l.at("HV_TUBE_SPECULAR").why.find("no tube lights"), std::string::npos);
  const auto am = byName(ambientDefines(kb, b));
  EXPECT_EQ(am.at("HV_IRRADIANCE_CUBEMAP").value, "0");
  EXPECT_NE(am.at("HV_IRRADIANCE_CUBEMAP").why.find("no environment"), std::string::npos);
  EXPECT_EQ(am.at("HV_ENVIRONMENT").value, "0");

  // With the lights and environment present the same settings do change code.
  b.lights = {light(LightType::Sphere), light(LightType::Tube)};
  b.environment.kind = EnvironmentKind::Sky;
  const VariantKey kc = deriveVariantKey(b);
  const auto l2 = byName(lightDefines(kc, b));
  EXPECT_EQ(l2.at("HV_TUBE_SPECULAR").value, "1");
  EXPECT_EQ(l2.at("HV_TUBE_SPECULAR").why, "settings.tube_specular = smallest_angle_eq18");
  EXPECT_EQ(l2.at("HV_SPHERE_DIFFUSE").value, "1");
  EXPECT_EQ(l2.at("HV_HAS_POINT_LIGHTS").value, "0");
  EXPECT_EQ(l2.at("HV_HAS_TUBE_LIGHTS").why, "1 tube light");
  EXPECT_EQ(byName(ambientDefines(kc, b)).at("HV_IRRADIANCE_CUBEMAP").value, "1");
}

// ibl_specular: sampled compiles the lobe's samples where the environment varies, and the split
// sum under a uniform one (every sample would read its radiance); sky_sun has no define, only
// the sun's directional light where the environment is the procedural sky.
TEST(VariantKey, SampledSpecularAndSkySunWhereTheEnvironmentHasThem) {
  Scene s = sceneWith({Material{}});
  s.settings.ibl_specular = IblSpecular::Sampled;
  s.environment.kind = EnvironmentKind::Sky;
  const VariantKey sky = deriveVariantKey(s);
  EXPECT_EQ(byName(ambientDefines(sky, s)).at("HV_IBL_SPECULAR").value, "1");
  EXPECT_TRUE(sky.directional_lights);
  s.environment.kind = EnvironmentKind::Uniform;
  const VariantKey uniform = deriveVariantKey(s);
  const auto u = byName(ambientDefines(uniform, s));
  EXPECT_EQ(u.at("HV_IBL_SPECULAR").value, "0");
  EXPECT_EQ(uniform.settings.ibl_specular, IblSpecular::SplitSum) << "reset in the key";
  EXPECT_NE(u.at("HV_IBL_SPECULAR").why.find("uniform environment"), std::string::npos);
  EXPECT_FALSE(uniform.directional_lights);
  EXPECT_EQ(uniform.settings.sky_sun, SkySun::Light) << "the default, which changes no code here";
  EXPECT_TRUE(validateKey(uniform).empty());
}

TEST(VariantKey, ValidationRejectsImpossibleCombinations) {
  VariantKey k;  // no lights, no environment, no materials: valid
  EXPECT_TRUE(validateKey(k).empty());

  auto expectInvalid = [](const VariantKey& key, const std::string& fragment) {
    const auto bad = validateKey(key);
    const bool found = std::any_of(bad.begin(), bad.end(), [&](const std::string& s) {
      return s.find(fragment) != std::string::npos;
    });
    EXPECT_TRUE(found) << "expected a violation containing '" << fragment << "'";
  };
  VariantKey a = k;
  a.settings.irradiance = Irradiance::Cubemap;
  expectInvalid(a, "irradiance cubemap without an environment");
  VariantKey b = k;
  b.point_lights = true;
  b.settings.v = VisibilityTerm::CookTorrance;
  b.settings.remap_roughness = true;
  expectInvalid(b, "roughness remap");
  VariantKey c = k;
  c.point_lights = true;
  c.settings.tube_normalization = false;
  expectInvalid(c, "tube-light options without tube lights");
  VariantKey d = k;
  MaterialFeatures f;
  f.emissive_map = true;
  d.material_variants = {f};
  expectInvalid(d, "emissive map without emissive");
  VariantKey e = k;
  MaterialFeatures g;
  g.uv1 = true;
  e.material_variants = {g, g};
  expectInvalid(e, "second UV set without any map");
  expectInvalid(e, "duplicate feature set");
  VariantKey h = k;
  h.material_variant = {3};
  expectInvalid(h, "out of range");
  VariantKey u = k;
  u.uber = true;
  expectInvalid(u, "uber key without every light type");

  // Every derived key is valid, whatever the settings ask for.
  for (int env = 0; env < 2; ++env) {
    for (int types = 0; types < 16; ++types) {
      Material m;
      m.emissive_tex = tex(1);
      Scene s = sceneWith({m});
      s.environment.kind = env ? EnvironmentKind::Sky : EnvironmentKind::None;
      if (types & 1) s.lights.push_back(light(LightType::Point));
      if (types & 2) s.lights.push_back(light(LightType::Sphere));
      if (types & 4) s.lights.push_back(light(LightType::Tube));
      if (types & 8) s.lights.push_back(light(LightType::Spot));  // a sphere spot
      s.settings.v = VisibilityTerm::CookTorrance;
      s.settings.irradiance = Irradiance::Cubemap;
      s.settings.sphere_diffuse = SphereDiffuse::HorizonCorrect;
      s.settings.tube_specular = TubeSpecular::SmallestAngleEq18;
      s.settings.d = DistributionTerm::Beckmann;
      const auto bad = validateKey(deriveVariantKey(s));
      EXPECT_TRUE(bad.empty()) << "env " << env << " types " << types << ": " << bad.front();
    }
  }
}

TEST(VariantKey, GBufferReasonsNameTheMaterials) {
  Material x, y, z;
  x.name = "brick";
  x.normal_tex = tex();
  y.name = "tile";
  y.normal_tex = tex();
  z.name = "plaster";
  Scene s = sceneWith({x, y, z});
  const VariantKey k = deriveVariantKey(s);
  ASSERT_EQ(k.material_variants.size(), 2u);
  const size_t v = size_t(k.material_variant[0]);
  const auto g = byName(gbufferDefines(k, v, s));
  EXPECT_EQ(g.at("HV_MAT_NORMAL_MAP").value, "1");
  EXPECT_EQ(g.at("HV_MAT_NORMAL_MAP").why, "materials brick, tile");
  EXPECT_EQ(g.at("HV_MAT_RUNTIME_FLAGS").value, "0");
  EXPECT_EQ(g.at("HV_MAT_EMISSIVE").value, "0");
  const auto g2 = byName(gbufferDefines(k, size_t(k.material_variant[2]), s));
  EXPECT_EQ(g2.at("HV_MAT_NORMAL_MAP").value, "0");
  EXPECT_EQ(g2.at("HV_MAT_NORMAL_MAP").why, "no material of this variant uses it");
}

// culling: auto (chooseCulling): brute force where culling would save at most
// kAutoCullingSavedLights evaluations per pixel among at most kAutoCullingMaxLights lights.
// Coverage is exact here: a light whose culling sphere holds the camera covers every tile (1 per
// light), one behind the camera beyond its range covers none (0).
TEST(VariantKey, AutoCullingBruteForceOnlyBelowTheCrossover) {
  Scene s = sceneWith({Material{}});
  const glm::vec3 eye = s.camera.position;
  const glm::vec3 back = glm::normalize(s.camera.position - s.camera.target);
  auto around = [&](int n) {  // n point lights whose spheres contain the eye
    std::vector<Light> ls(size_t(n), light(LightType::Point));
    for (Light& l : ls) {
      l.position = eye;
      l.range = 50.0f;
    }
    return ls;
  };
  auto behind = [&](int n) {  // n point lights behind the eye, out of range: on no tile
    std::vector<Light> ls(size_t(n), light(LightType::Point));
    for (Light& l : ls) {
      l.position = eye + 100.0f * back;
      l.range = 1.0f;
    }
    return ls;
  };
  ASSERT_EQ(RenderSettings{}.culling, Culling::Auto);  // the default

  s.lights = around(int(kAutoCullingMaxLights));  // every light on every tile: nothing to save
  CullingChoice c = chooseCulling(s);
  EXPECT_EQ(c.lights, kAutoCullingMaxLights);
  EXPECT_DOUBLE_EQ(c.coverage, double(kAutoCullingMaxLights));
  EXPECT_EQ(c.culling, Culling::BruteForce);
  VariantKey k = deriveVariantKey(s);
  EXPECT_EQ(k.settings.culling, Culling::BruteForce);
  EXPECT_TRUE(validateKey(k).empty());
  auto d = byName(lightDefines(k, s));
  EXPECT_EQ(d.at("HV_CULLING_BRUTE_FORCE").value, "1");
  EXPECT_EQ(
      d.at("HV_CULLING_BRUTE_FORCE").why.find("settings.culling = auto: brute_force; 2 lights"), 0u)
      << d.at("HV_CULLING_BRUTE_FORCE").why;

  s.lights = around(int(kAutoCullingMaxLights) + 1);  // one light more than the cap
  EXPECT_EQ(chooseCulling(s).culling, Culling::Tiled);
  k = deriveVariantKey(s);
  EXPECT_EQ(k.settings.culling, Culling::Tiled);
  d = byName(lightDefines(k, s));
  EXPECT_EQ(d.at("HV_CULLING_BRUTE_FORCE").value, "0");
  EXPECT_NE(d.at("HV_CULLING_BRUTE_FORCE").why.find("auto: tiled"), std::string::npos);

  // Directional lights are in no tile list: they do not count, and with nothing else to cull
  // there is no culling pass.
  Light sun;
  sun.type = LightType::Directional;
  s.lights = around(int(kAutoCullingMaxLights) + 1);
  s.lights.push_back(sun);
  EXPECT_EQ(chooseCulling(s).lights, kAutoCullingMaxLights + 1);
  s.lights = {sun, sun};
  c = chooseCulling(s);
  EXPECT_EQ(c.lights, 0u);
  EXPECT_EQ(c.culling, Culling::BruteForce);
  EXPECT_NE(c.why.find("directional lights only"), std::string::npos) << c.why;

  // An off-screen light costs brute force an evaluation per pixel that culling saves.
  ASSERT_LT(kAutoCullingSavedLights, 1.0);
  s.lights = behind(1);
  c = chooseCulling(s);
  EXPECT_DOUBLE_EQ(c.coverage, 0.0);
  EXPECT_EQ(c.culling, Culling::Tiled);
  s.lights.insert(s.lights.end(), 1, around(1).front());  // and one on every tile
  c = chooseCulling(s);
  EXPECT_NEAR(c.coverage, 1.0, 1e-12);
  EXPECT_EQ(c.culling, Culling::Tiled);  // 1 evaluation per pixel saved
  s.lights = around(1);
  EXPECT_EQ(chooseCulling(s).culling, Culling::BruteForce);

  // An explicit choice is kept; no lights: tiled (nothing runs), the default's reason.
  s.settings.culling = Culling::Tiled;
  s.lights = around(2);
  EXPECT_EQ(deriveVariantKey(s).settings.culling, Culling::Tiled);
  EXPECT_EQ(byName(lightDefines(deriveVariantKey(s), s)).at("HV_CULLING_BRUTE_FORCE").why,
            "settings.culling = tiled");
  s.settings.culling = Culling::Auto;
  s.lights.clear();
  k = deriveVariantKey(s);
  EXPECT_EQ(k.settings.culling, Culling::Tiled);
  EXPECT_TRUE(validateKey(k).empty());
  VariantKey unresolved = k;
  unresolved.settings.culling = Culling::Auto;
  EXPECT_FALSE(validateKey(unresolved).empty());
}
