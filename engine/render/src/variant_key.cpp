#include "halfvec/render/variant_key.hpp"

#include <algorithm>
#include <cstdio>
#include <map>
#include <type_traits>

#include "halfvec/render/frame_data.hpp"
#include "halfvec/ibl/sky_sun.hpp"
#include "halfvec/render/shadows.hpp"
#include "halfvec/scene/enums.hpp"
#include "halfvec/shading/brdf.hpp"
#include "halfvec/shading/light_gpu.hpp"
#include "halfvec/shading/shading.hpp"

namespace hv::render {

// Karis 2013 eq. 4: whether the Disney (roughness+1)/2 remap changes anything for V term v is
// brdf.glsl's rule (remapAppliesTo), the one the shaders and the C++ BRDF use.
bool remapMeaningful(VisibilityTerm v) {
  return glsl::remapAppliesTo(true, static_cast<int>(v));
}

namespace {

// The rules of the settings table's feature and supersede columns (render_settings.hpp).
bool featurePresent(SettingFeature f, const VariantKey& k) {
  switch (f) {
    case SettingFeature::Frame:
      return true;
    case SettingFeature::Lights:
      return k.hasLights();
    case SettingFeature::SphereLights:  // a directional light is shaded as a sphere at infinity
      return k.sphere_lights || k.directional_lights;
    case SettingFeature::TubeLights:
      return k.tube_lights;
    case SettingFeature::AmbientIbl:
      return k.ambientIbl();
    case SettingFeature::ShadowedLights:
      return k.shadows;
    case SettingFeature::ScreenSpaceAo:
      return k.ao;
    case SettingFeature::EnvironmentSun:
      return k.environment_sun;
    case SettingFeature::VaryingAmbient:
      return k.ambientIbl() && (k.environment != EnvironmentKind::Uniform || k.uber);
  }
  return true;
}

// Why a setting of an absent feature changes no code (the manifest's reason).
std::string featureAbsentReason(SettingFeature f, const VariantKey& k) {
  switch (f) {
    case SettingFeature::Frame:
      return "";
    case SettingFeature::Lights:
      return "no lights";
    case SettingFeature::SphereLights:
      return "no sphere or directional lights";
    case SettingFeature::TubeLights:
      return "no tube lights";
    case SettingFeature::AmbientIbl:
      return k.hasEnvironment() ? "no default_lit material" : "no environment";
    case SettingFeature::ShadowedLights:
      return "no shadowed lights";
    case SettingFeature::ScreenSpaceAo:
      return k.ambientIbl() ? "ao is none" : "no ambient IBL";
    case SettingFeature::EnvironmentSun:
      return "the environment has no sun (not the procedural sky, no sun found in its HDR)";
    case SettingFeature::VaryingAmbient:
      // Every prefiltered texel of a uniform environment is its radiance (Ibl.FurnaceUniform).
      return k.ambientIbl() ? "uniform environment: every lookup reads the same radiance"
                            : featureAbsentReason(SettingFeature::AmbientIbl, k);
  }
  return "";
}

// validateKey's complaint about a key that holds a non-default setting of an absent feature.
const char* featureInvalid(SettingFeature f) {
  switch (f) {
    case SettingFeature::Frame:
      return "";
    case SettingFeature::Lights:
      return "BRDF or light options without lights";
    case SettingFeature::SphereLights:
      return "sphere-light options without sphere or directional lights";
    case SettingFeature::TubeLights:
      return "tube-light options without tube lights";
    case SettingFeature::AmbientIbl:
      return "ambient IBL options without ambient IBL (no environment or no lit material)";
    case SettingFeature::ShadowedLights:
      return "shadow options without shadowed lights";
    case SettingFeature::ScreenSpaceAo:
      return "ambient occlusion options without ao: gtao";
    case SettingFeature::EnvironmentSun:
      return "sun options without an environment that has a sun";
    case SettingFeature::VaryingAmbient:
      return "options of a varying environment under a uniform one or without ambient IBL";
  }
  return "";
}

bool superseded(Supersede r, const RenderSettings& s) {
  switch (r) {
    case Supersede::None:
      return false;
    case Supersede::RemapInapplicable:
      return !remapMeaningful(s.v);
    case Supersede::SphereLtc:
      return s.sphere_specular == SphereSpecular::Ltc;
    case Supersede::TubeLtc:
      return s.tube_specular == TubeSpecular::Ltc;
    case Supersede::Gtao:
      return s.ao == AmbientOcclusion::Gtao;
  }
  return false;
}

const char* supersedeReason(Supersede r) {
  switch (r) {
    case Supersede::None:
      return "";
    case Supersede::RemapInapplicable:
      return "the remap applies to Schlick-GGX only (Karis eq. 4)";
    case Supersede::SphereLtc:
      return "the LTC sphere specular has none";
    case Supersede::TubeLtc:
      return "the LTC tube specular has none";
    case Supersede::Gtao:
      return "with ao gtao, ao_specular occludes the ambient specular";
  }
  return "";
}

const char* supersedeInvalid(Supersede r) {
  switch (r) {
    case Supersede::None:
      return "";
    case Supersede::RemapInapplicable:
      return "roughness remap with a visibility term other than Schlick-GGX";
    case Supersede::SphereLtc:
      return "sphere normalization with the LTC sphere specular";
    case Supersede::TubeLtc:
      return "tube normalization with the LTC tube specular";
    case Supersede::Gtao:
      return "cavity specular occlusion with ao gtao";
  }
  return "";
}

}  // namespace

RenderSettings canonicalSettings(const RenderSettings& s, const VariantKey& key) {
  const RenderSettings d;  // defaults
  RenderSettings c = s;
  // First the features, then what supersedes a setting (its rule reads the reset values).
  forEachSetting([&](const auto& row) {
    if (!featurePresent(row.info.feature, key)) c.*row.member = d.*row.member;
  });
  forEachSetting([&](const auto& row) {
    using T = typename std::decay_t<decltype(row)>::Type;
    if constexpr (std::is_same_v<T, bool>) {
      if (superseded(row.info.superseded_by, c)) c.*row.member = row.info.superseded_value;
    }
  });
  if (c.culling == Culling::Auto) c.culling = key.auto_culling.culling;
  return c;
}

CullingChoice chooseCulling(const Scene& scene) {
  CullingChoice c;
  // Directional lights are in no tile list (every lit pixel shades them): the others count.
  const std::vector<Light> lights = renderedLights(scene);
  size_t directional = 0;
  for (const Light& l : lights) directional += l.type == LightType::Directional;
  c.lights = lights.size() - directional;
  if (c.lights == 0) {  // directional lights only: no culling pass, the brute-force loop
    if (directional) c.culling = Culling::BruteForce;
    c.why = directional ? "no lights to cull (directional lights only: every pixel shades them)"
                        : "no lights";
    return c;
  }
  const FrameBlock f = makeFrameBlock(scene, scene.settings.width, scene.settings.height);
  const glm::ivec2 tiles(f.viewport.z, f.viewport.w);
  double covered = 0.0;
  for (const Light& l : scene.lights) {
    if (l.type == LightType::Directional) continue;
    const glm::vec4 sphere = glsl::lightCullSphere(toGlsl(packLight(l)));
    const glm::vec3 center = glm::vec3(f.view * glm::vec4(glm::vec3(sphere), 1.0f));
    glm::ivec4 r;
    if (glsl::sphereTileRect(center, sphere.w, glm::vec2(f.proj[0][0], f.proj[1][1]),
                             f.frame_params.x, glm::vec2(f.viewport.x, f.viewport.y), tiles,
                             glm::vec2(kTileSize, kTileHeight), r)) {
      covered += double(r.z - r.x + 1) * double(r.w - r.y + 1);
    }
  }
  c.coverage = covered / (double(tiles.x) * double(tiles.y));
  const double saved = double(c.lights) - c.coverage;
  const bool brute = c.lights <= kAutoCullingMaxLights && saved <= kAutoCullingSavedLights;
  c.culling = brute ? Culling::BruteForce : Culling::Tiled;
  char why[256];
  std::snprintf(why, sizeof why,
                "%zu light%s, %.2f per tile at the scene's camera: culling would save %.2f "
                "evaluations per pixel; brute force at most %zu lights and %.1f saved "
                "(docs/performance.md)",
                c.lights, c.lights == 1 ? "" : "s", c.coverage, saved, kAutoCullingMaxLights,
                kAutoCullingSavedLights);
  c.why = why;
  return c;
}

std::string VariantKey::text() const {
  std::string lights;
  if (point_lights) lights += "point";
  if (sphere_lights) lights += std::string(lights.empty() ? "" : "+") + "sphere";
  if (tube_lights) lights += std::string(lights.empty() ? "" : "+") + "tube";
  if (spot_lights) lights += std::string(lights.empty() ? "" : "+") + "spot";
  if (directional_lights) lights += std::string(lights.empty() ? "" : "+") + "directional";
  std::string models;
  if (default_lit) models += "default_lit";
  if (clear_coat) models += std::string(models.empty() ? "" : "+") + "clear_coat";
  if (unlit) models += std::string(models.empty() ? "" : "+") + "unlit";
  return "lights " + (lights.empty() ? std::string("none") : lights) + "; models " +
         (models.empty() ? std::string("none") : models) + "; environment " +
         std::string(toString(environment)) + "; " + std::to_string(material_variants.size()) +
         " material variant" + (material_variants.size() == 1 ? "" : "s") + "; " +
         (uber ? "uber" : "specialized") + (shadows ? "; shadows" : "") + (ao ? "; gtao" : "") +
         (blend ? "; blend" : "");
}

VariantKey deriveVariantKey(const Scene& scene) {
  VariantKey k;
  k.uber = scene.settings.uber;
  for (const Light& l : renderedLights(scene)) {
    // A spot is shaded as its shape (lightShape) times its cone.
    k.point_lights |= lightShape(l) == LightType::Point;
    k.sphere_lights |= lightShape(l) == LightType::Sphere;
    k.tube_lights |= l.type == LightType::Tube;
    k.spot_lights |= l.type == LightType::Spot;
    k.directional_lights |= l.type == LightType::Directional;
    k.shadows |= l.shadows;
  }
  k.environment = scene.environment.kind;
  k.environment_sun = environmentHasSun(scene.environment);
  // Only materials that are drawn count.
  std::vector<bool> drawn(scene.materials.size(), false);
  std::vector<bool> colored(scene.materials.size(), false);  // drawn on a mesh with COLOR_0
  for (const Object& o : scene.objects) {
    for (int mi : o.meshes) {
      const Mesh& mesh = scene.meshes.at(size_t(mi));
      const int mat = mesh.material;
      if (mat >= 0 && size_t(mat) < drawn.size()) {
        drawn[size_t(mat)] = true;
        if (mesh.has_colors) colored[size_t(mat)] = true;
      }
    }
  }
  k.material_variant.assign(scene.materials.size(), -1);
  for (size_t i = 0; i < scene.materials.size(); ++i) {
    if (!drawn[i]) continue;
    const Material& m = scene.materials[i];
    k.unlit |= m.model == ShadingModel::Unlit;
    // A clear coat is default lit plus its coat: both compile the lit code.
    k.default_lit |= isLit(m.model);
    k.clear_coat |= m.model == ShadingModel::ClearCoat;
    k.blend |= m.alpha_mode == AlphaMode::Blend;
    if (k.uber) continue;
    const MaterialFeatures f = materialFeatures(m, colored[i]);
    auto it = std::find(k.material_variants.begin(), k.material_variants.end(), f);
    if (it == k.material_variants.end()) it = k.material_variants.insert(it, f);
    k.material_variant[i] = int(it - k.material_variants.begin());
  }
  if (k.uber) {
    k.point_lights = k.sphere_lights = k.tube_lights = k.spot_lights = k.directional_lights = true;
    k.unlit = k.default_lit = k.clear_coat = true;
    k.material_variants = {allMaterialFeatures()};
    for (size_t i = 0; i < scene.materials.size(); ++i) k.material_variant[i] = drawn[i] ? 0 : -1;
  }
  k.ao = scene.settings.ao == AmbientOcclusion::Gtao && k.ambientIbl();
  k.auto_culling = chooseCulling(scene);
  k.settings = canonicalSettings(scene.settings, k);
  return k;
}

std::vector<std::string> validateKey(const VariantKey& k) {
  std::vector<std::string> bad;
  RenderSettings d;
  d.culling = k.auto_culling.culling;  // the default, auto, as the key holds it
  const RenderSettings& s = k.settings;
  if (s.culling == Culling::Auto)
    bad.push_back("culling auto not resolved to tiled or brute force");
  if (!k.hasEnvironment() && s.irradiance == Irradiance::Cubemap) {
    bad.push_back("irradiance cubemap without an environment");
  }
  for (SettingFeature f :
       {SettingFeature::Lights, SettingFeature::SphereLights, SettingFeature::TubeLights,
        SettingFeature::AmbientIbl, SettingFeature::ShadowedLights, SettingFeature::ScreenSpaceAo,
        SettingFeature::EnvironmentSun, SettingFeature::VaryingAmbient}) {
    if (featurePresent(f, k)) continue;
    bool changed = false;
    forEachSetting([&](const auto& row) {
      changed = changed || (row.info.feature == f && s.*row.member != d.*row.member);
    });
    if (changed) bad.push_back(featureInvalid(f));
  }
  forEachSetting([&](const auto& row) {
    using T = typename std::decay_t<decltype(row)>::Type;
    if constexpr (std::is_same_v<T, bool>) {
      if (superseded(row.info.superseded_by, s) && s.*row.member != row.info.superseded_value) {
        bad.push_back(supersedeInvalid(row.info.superseded_by));
      }
    }
  });
  for (size_t i = 0; i < k.material_variants.size(); ++i) {
    const MaterialFeatures& f = k.material_variants[i];
    const std::string where = "material variant " + std::to_string(i) + ": ";
    if (f.emissive_map && !f.emissive) bad.push_back(where + "emissive map without emissive");
    if (f.uv1 && !(f.base_color_map || f.metal_rough_map || f.normal_map || f.occlusion_map ||
                   f.emissive_map || f.clear_coat_maps)) {
      bad.push_back(where + "second UV set without any map");
    }
    if (std::count(k.material_variants.begin(), k.material_variants.end(), f) > 1) {
      bad.push_back(where + "duplicate feature set");
    }
  }
  if (k.uber && k.material_variants.size() != 1) bad.push_back("uber key with several variants");
  if (k.uber && !(k.point_lights && k.sphere_lights && k.tube_lights && k.spot_lights &&
                  k.directional_lights)) {
    bad.push_back("uber key without every light type");
  }
  for (int v : k.material_variant) {
    if (v < -1 || v >= int(k.material_variants.size())) {
      bad.push_back("material index into variants out of range");
      break;
    }
  }
  return bad;
}

namespace {

std::string flag(bool b) {
  return b ? "1" : "0";
}

// "materials a, b, c" (at most 4 names, then "and N more").
std::string materialList(const Scene& scene, const std::vector<size_t>& ids) {
  std::string t = ids.size() == 1 ? "material " : "materials ";
  for (size_t i = 0; i < ids.size() && i < 4; ++i) {
    const std::string& n = scene.materials[ids[i]].name;
    if (i) t += ", ";
    if (n.empty()) {
      t += '#';
      t += std::to_string(ids[i]);
    } else {
      t += n;
    }
  }
  if (ids.size() > 4) t += " and " + std::to_string(ids.size() - 4) + " more";
  return t;
}

// Lights of shape t (lightShape: a spot counts as its point or sphere), or spots for t = Spot.
size_t countLights(const Scene& scene, LightType t) {
  const size_t sun = t == LightType::Directional && skySunIsLight(scene) ? 1 : 0;  // the sky's
  return sun + size_t(std::count_if(scene.lights.begin(), scene.lights.end(), [&](const Light& l) {
           return t == LightType::Spot ? l.type == t : lightShape(l) == t;
         }));
}

// Reason of a setting-derived define: the setting, or why it was reset.
std::string settingWhy(const std::string& path, std::string_view value, bool reset,
                       const char* reset_reason) {
  if (reset)
    return std::string("default: ") + reset_reason + " (settings." + path + " changes no code)";
  return "settings." + path + " = " + std::string(value);
}

// What an LTC mode shades when the scene's BRDF terms differ from the lobe the table was fitted
// to (GGX x height-correlated Smith x Schlick's F average; docs/lights.md, "Other BRDF choices").
std::string ltcLobeNote(const RenderSettings& s, bool ltc) {
  if (!ltc) return "";
  std::string note;
  if (s.d != DistributionTerm::GGX) {
    note += "; the LTC lobe is GGX whatever brdf.d (" + std::string(toString(s.d)) + ")";
  }
  if (s.v != VisibilityTerm::SmithGGXCorrelated) {
    note +=
        "; the LTC lobe is fitted with smith_ggx_correlated: its magnitude is scaled by brdf.v (" +
        std::string(toString(s.v)) + ") over it at the mirror direction";
  }
  if (s.f != FresnelTerm::SchlickPow5 && s.f != FresnelTerm::SchlickF90Occlusion) {
    note += "; the LTC takes Schlick's Fresnel average whatever brdf.f (" +
            std::string(toString(s.f)) + ")";
  }
  return note;
}

template <class T>
std::string valueText(const T& v) {
  if constexpr (std::is_same_v<T, bool>) {
    return v ? "true" : "false";
  } else if constexpr (std::is_enum_v<T>) {
    return std::string(toString(v));
  } else {
    return std::to_string(v);
  }
}

// The defines `pass` gets from the settings table, each with its setting or why the key reset it.
std::vector<KeyDefine> settingKeyDefines(const VariantKey& k, const Scene& scene,
                                         SettingPass pass) {
  const RenderSettings& s = k.settings;
  const RenderSettings& in = scene.settings;
  const auto values = settingDefines(s, pass);  // in row order, as below
  std::vector<KeyDefine> out;
  forEachSetting([&](const auto& row) {
    using T = typename std::decay_t<decltype(row)>::Type;
    if (row.info.pass != pass || !row.info.define) return;
    const bool present = featurePresent(row.info.feature, k);
    const std::string reason = present ? supersedeReason(row.info.superseded_by)
                                       : featureAbsentReason(row.info.feature, k);
    std::string why = settingWhy(row.key, valueText(s.*row.member), in.*row.member != s.*row.member,
                                 reason.c_str());
    if constexpr (std::is_enum_v<T>) {
      if (present && toString(s.*row.member) == "ltc") why += ltcLobeNote(s, true);
    }
    if constexpr (std::is_same_v<T, Culling>) {
      if (present && in.culling == Culling::Auto) {
        why = "settings.culling = auto: " + std::string(toString(s.culling)) + "; " +
              k.auto_culling.why;
      }
    }
    const auto& [name, value] = values.at(out.size());
    out.push_back({name, value, why});
  });
  return out;
}

// Why the light programs have shadow code or none: the shadowed lights, named.
std::string shadowsWhy(const Scene& scene) {
  const std::vector<Light> lights = renderedLights(scene);  // the sky's sun last
  std::vector<size_t> on;
  for (size_t i = 0; i < lights.size(); ++i) {
    if (lights[i].shadows) on.push_back(i);
  }
  if (on.empty()) return "no light has shadows: true (no shadow maps, no shadow lookup)";
  std::string t = std::to_string(on.size()) + " shadowed light" + (on.size() == 1 ? "" : "s");
  for (size_t i = 0; i < on.size() && i < 4; ++i)
    t += (i ? ", " : " (") + describeLight(lights, on[i]);
  if (on.size() > 4) t += " and " + std::to_string(on.size() - 4) + " more";
  return t + ")";
}

}  // namespace

std::vector<KeyDefine> gbufferDefines(const VariantKey& k, size_t variant, const Scene& scene) {
  const MaterialFeatures& f = k.material_variants.at(variant);
  std::vector<size_t> members;
  for (size_t i = 0; i < k.material_variant.size(); ++i) {
    if (k.material_variant[i] == int(variant)) members.push_back(i);
  }
  std::vector<KeyDefine> out;
  out.push_back({"HV_MAT_RUNTIME_FLAGS", flag(k.uber),
                 k.uber ? "uber build: every feature compiled in, each material's flags read at "
                          "run time"
                        : "specialized: every material drawn with this program has exactly these "
                          "features (" +
                              materialList(scene, members) + ")"});
  for (const auto& field : materialFeatureFields()) {
    const bool on = f.*field.member;
    std::string why;
    if (k.uber) {
      why = "uber build";
    } else if (on) {
      why = materialList(scene, members);
    } else {
      why = "no material of this variant uses it";
    }
    out.push_back({field.define, flag(on), why});
  }
  return out;
}

// The light and ambient passes' clear-coat branch (HV_HAS_CLEAR_COAT).
KeyDefine clearCoatDefine(const VariantKey& k) {
  return {"HV_HAS_CLEAR_COAT", flag(k.clear_coat),
          k.uber         ? "uber build"
          : k.clear_coat ? "clear_coat materials present: the coat target and its lobe"
                         : "no clear_coat material"};
}

std::vector<KeyDefine> lightDefines(const VariantKey& k, const Scene& scene) {
  const RenderSettings& s = k.settings;
  std::vector<KeyDefine> out = settingKeyDefines(k, scene, SettingPass::Light);
  out.push_back({"HV_DIRECT_TERMS", std::to_string(int(s.direct_terms)),
                 s.direct_terms == 3 ? "diffuse and specular (all terms)"
                                     : "term mask " + std::to_string(int(s.direct_terms)) +
                                           " (render --aov, per-term debug view)"});
  const struct {
    const char* define;
    bool on;
    LightType type;
  } types[] = {{"HV_HAS_POINT_LIGHTS", k.point_lights, LightType::Point},
               {"HV_HAS_SPHERE_LIGHTS", k.sphere_lights, LightType::Sphere},
               {"HV_HAS_TUBE_LIGHTS", k.tube_lights, LightType::Tube},
               {"HV_HAS_SPOT_LIGHTS", k.spot_lights, LightType::Spot},
               {"HV_HAS_DIRECTIONAL_LIGHTS", k.directional_lights, LightType::Directional}};
  for (const auto& t : types) {
    const size_t n = countLights(scene, t.type);
    const std::string name(toString(t.type));
    std::string w = std::to_string(n) + " " + name + " light" + (n == 1 ? "" : "s");
    if (n == 0) w = "no " + name + " lights";
    if (k.uber) w = "uber build (" + w + ")";
    out.push_back({t.define, flag(t.on), w});
  }
  out.push_back({"HV_SHADOWS", flag(k.shadows), shadowsWhy(scene)});
  out.push_back(clearCoatDefine(k));
  return out;
}

std::vector<KeyDefine> ambientDefines(const VariantKey& k, const Scene& scene) {
  const RenderSettings& s = k.settings;
  const std::string env_name(toString(k.environment));
  std::vector<KeyDefine> out;
  out.push_back({"HV_ENVIRONMENT", flag(k.hasEnvironment() || k.uber),
                 k.uber ? "uber build (environment " + env_name + ")"
                 : k.hasEnvironment()
                     ? "environment " + env_name
                     : std::string("no environment: background black, no ambient light")});
  out.push_back({"HV_ENV_RUNTIME_CHECK", flag(k.uber),
                 k.uber ? "uber build: environment presence read at run time"
                        : "specialized: presence known at compile time"});
  out.push_back({"HV_HAS_DEFAULT_LIT", flag(k.default_lit),
                 k.uber          ? "uber build"
                 : k.default_lit ? "default_lit materials present"
                                 : "no default_lit material: no image-based lighting code"});
  out.push_back(clearCoatDefine(k));
  for (KeyDefine& d : settingKeyDefines(k, scene, SettingPass::Ambient)) out.push_back(d);
  out.push_back({"HV_AMBIENT_TERMS", std::to_string(int(s.ambient_terms)),
                 s.ambient_terms == 3 ? "diffuse and specular (all terms)"
                                      : "term mask " + std::to_string(int(s.ambient_terms)) +
                                            " (render --aov, per-term debug view)"});
  return out;
}

std::vector<KeyDefine> forwardDefines(const VariantKey& k, size_t variant, const Scene& scene) {
  std::vector<KeyDefine> out = gbufferDefines(k, variant, scene);
  // The forward pass has no texture units for the coat's maps (bindings.glsl,
  // HV_FORWARD_MATERIAL_TEXTURES): a blended coat takes its factors alone.
  for (KeyDefine& d : out) {
    if (d.name == "HV_MAT_CLEAR_COAT_MAPS" && d.value != "0") {
      d.value = "0";
      d.why = "the forward pass binds no coat textures: a blended coat takes its factors";
    }
  }
  for (auto* defs : {lightDefines, ambientDefines}) {
    for (KeyDefine& d : defs(k, scene)) {
      const bool seen =
          std::any_of(out.begin(), out.end(), [&](const KeyDefine& o) { return o.name == d.name; });
      if (!seen) out.push_back(std::move(d));
    }
  }
  return out;
}

std::vector<KeyDefine> aoDefines(const VariantKey& k, const Scene& scene) {
  std::vector<KeyDefine> out = settingKeyDefines(k, scene, SettingPass::Ao);
  // Only the cone specular occlusion reads the bent normal: without it the AO pass skips it.
  const bool bent = k.settings.ao_specular == AoSpecular::Cone;
  out.push_back({"HV_AO_BENT_NORMAL", flag(bent),
                 bent ? "settings.ao_specular = cone reads the bent normal"
                      : "settings.ao_specular = " + std::string(toString(k.settings.ao_specular)) +
                            " reads no bent normal"});
  return out;
}

std::vector<KeyDefine> toneMapDefines(const VariantKey& k, const Scene& scene) {
  return settingKeyDefines(k, scene, SettingPass::ToneMap);
}

}  // namespace hv::render
