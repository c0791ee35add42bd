#include "scene_elements.hpp"

#include <algorithm>
#include <limits>
#include <list>
#include <optional>
#include <type_traits>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include "halfvec/scene/light_generator.hpp"
#include "halfvec/scene/presets.hpp"
#include "halfvec/scene/scene_loader.hpp"

namespace hv::scene_json {

Camera parseCamera(const Ctx& ctx, const json& j) {
  Obj o(ctx, j, "/camera", {"position", "target", "up", "fov_y_deg", "near", "far"});
  Camera c;
  c.position = o.vec3("position", c.position);
  c.target = o.vec3("target", c.target);
  c.up = o.vec3("up", c.up);
  c.fov_y_deg = o.num("fov_y_deg", c.fov_y_deg, kFieldOfView);
  c.near_plane = o.num("near", c.near_plane, kPositive);
  c.far_plane = o.num("far", c.far_plane, kFar);
  if (c.far_plane <= c.near_plane) {
    o.fail("far", "expected far > near (" + fmt(c.near_plane) + "), got " + fmt(c.far_plane));
  }
  const glm::vec3 fwd = c.target - c.position;
  if (glm::length(fwd) < 1e-6f) o.fail("target", "target must differ from position");
  if (glm::length(glm::cross(glm::normalize(fwd), c.up)) < 1e-4f) {
    o.fail("up", "up must not be zero or parallel to the view direction");
  }
  return c;
}

Material parseMaterial(const Ctx& ctx, const json& j, const std::string& ptr, bool allow_name) {
  std::vector<std::string_view> keys = {
      "base_color",    "metallic",     "roughness",          "cavity", "emissive",
      "shading_model", "double_sided", "vertex_color",       "alpha",  "alpha_mode",
      "alpha_cutoff",  "clearcoat",    "clearcoat_roughness"};
  if (allow_name) keys.push_back("name");
  Obj o(ctx, j, ptr, keys);
  Material m;
  m.source = ptr;
  m.name = o.string("name", "");
  m.base_color = o.vec3("base_color", m.base_color, kUnit);
  m.metallic = o.num("metallic", m.metallic, kUnit);
  m.roughness = o.num("roughness", m.roughness, kUnit);
  m.cavity = o.num("cavity", m.cavity, kUnit);
  m.emissive = o.vec3("emissive", m.emissive, kNonNeg);
  m.double_sided = o.boolean("double_sided", m.double_sided);
  m.vertex_color = o.boolean("vertex_color", m.vertex_color);
  m.base_alpha = o.num("alpha", m.base_alpha, kUnit);
  if (o.has("alpha_mode")) m.alpha_mode = o.enumeration<AlphaMode>("alpha_mode", m.alpha_mode);
  m.alpha_cutoff = o.num("alpha_cutoff", m.alpha_cutoff, kUnit);
  if (o.has("shading_model")) {
    m.model = o.enumeration<ShadingModel>("shading_model", m.model);
    if (m.model == ShadingModel::Background) {
      o.fail("shading_model",
             "expected \"default_lit\", \"clear_coat\" or \"unlit\", got \"background\"");
    }
  }
  // KHR_materials_clearcoat's two factors. A coat makes the material clear_coat; clear_coat
  // without a weight is a full coat (clearcoat 1), as the viewer's model menu sets it.
  m.clearcoat_roughness = o.num("clearcoat_roughness", m.clearcoat_roughness, kUnit);
  if (o.has("clearcoat")) {
    m.clearcoat = o.num("clearcoat", m.clearcoat, kUnit);
    if (m.model == ShadingModel::Unlit && m.clearcoat > 0.0f) {
      o.fail("clearcoat", "an unlit material has no clear coat (shading_model is \"unlit\")");
    }
    if (m.clearcoat > 0.0f) m.model = ShadingModel::ClearCoat;
    if (m.clearcoat == 0.0f && m.model == ShadingModel::ClearCoat) {
      o.fail("clearcoat", "shading_model \"clear_coat\" needs clearcoat > 0, got 0");
    }
  } else if (m.model == ShadingModel::ClearCoat) {
    m.clearcoat = 1.0f;
  }
  return m;
}

glm::mat4 parseTransform(const Ctx& ctx, const json& j, const std::string& ptr) {
  Obj o(ctx, j, ptr, {"translation", "rotation_deg", "quaternion", "scale"});
  const glm::vec3 t = o.vec3("translation", glm::vec3(0.0f));
  glm::quat q(1.0f, 0.0f, 0.0f, 0.0f);
  if (o.has("rotation_deg") && o.has("quaternion")) {
    o.fail("quaternion", "give either rotation_deg or quaternion, not both");
  }
  if (o.has("rotation_deg")) {
    const glm::vec3 e = glm::radians(o.vec3("rotation_deg", glm::vec3(0.0f)));
    // Extrinsic X, then Y, then Z: R = Rz * Ry * Rx.
    q = glm::angleAxis(e.z, glm::vec3(0, 0, 1)) * glm::angleAxis(e.y, glm::vec3(0, 1, 0)) *
        glm::angleAxis(e.x, glm::vec3(1, 0, 0));
  }
  if (o.has("quaternion")) {
    const json& v = o["quaternion"];
    if (!v.is_array() || v.size() != 4 || !std::all_of(v.begin(), v.end(), [](const json& x) {
          return x.is_number() && kAny.contains(x.get<double>());
        })) {
      o.fail("quaternion",
             "expected [x, y, z, w], each " + kAny.describe().substr(9) + ", got " + shortDump(v));
    }
    q = glm::quat(float(v[3].get<double>()), float(v[0].get<double>()), float(v[1].get<double>()),
                  float(v[2].get<double>()));
    if (glm::length(q) < 1e-6f) o.fail("quaternion", "expected a non-zero quaternion");
    q = glm::normalize(q);
  }
  glm::vec3 s(1.0f);
  if (o.has("scale")) {
    if (o["scale"].is_number()) {
      s = glm::vec3(o.num("scale", 1.0f, kPositive));
    } else {
      s = o.vec3("scale", s, kPositive);
    }
  }
  return glm::translate(glm::mat4(1.0f), t) * glm::mat4_cast(q) * glm::scale(glm::mat4(1.0f), s);
}

// A spot's radius (0: a point), direction and cone, with KHR_lights_punctual's names and
// defaults (inner 0, outer pi/4). The cone's attenuation (spot.glsl) needs inner < outer, and a
// cone wider than a hemisphere has no finite bounding sphere of its cap for the culling.
void parseSpot(const Obj& o, Light& l) {
  constexpr double kHalfPi = 1.5707963267948966;
  l.radius = o.num("radius", 0.0f, kNonNeg);
  const glm::vec3 d = o.vec3("direction", l.direction);
  if (glm::length(d) < 1e-6f) o.fail("direction", "expected a non-zero direction, got [0, 0, 0]");
  l.direction = glm::normalize(d);
  l.inner_cone_angle = o.num("inner_cone_angle", l.inner_cone_angle, Range{0.0, kHalfPi});
  l.outer_cone_angle =
      o.num("outer_cone_angle", l.outer_cone_angle, Range{0.0, kHalfPi, /*lo_open=*/true});
  if (!(l.inner_cone_angle < l.outer_cone_angle)) {
    o.fail(o.has("outer_cone_angle") ? "outer_cone_angle" : "inner_cone_angle",
           "expected 0 <= inner_cone_angle < outer_cone_angle <= pi/2, got inner " +
               fmt(l.inner_cone_angle) + " and outer " + fmt(l.outer_cone_angle));
  }
}

// A directional light: the direction its light travels, its illuminance and the disk's angular
// diameter. It has no position, range or radius: those keys are errors, as any key that does not
// apply to a type.
Light parseDirectional(const Ctx& ctx, const json& j, const std::string& ptr) {
  Obj o(ctx, j, ptr, {"type", "direction", "color", "intensity", "angular_diameter", "shadows"});
  Light l;
  l.type = LightType::Directional;
  const glm::vec3 d = o.vec3("direction", l.direction);
  if (glm::length(d) < 1e-6f) o.fail("direction", "expected a non-zero direction, got [0, 0, 0]");
  l.direction = glm::normalize(d);
  l.color = o.vec3("color", l.color, kNonNeg);
  l.intensity = o.num("intensity", l.intensity, kNonNeg);
  l.angular_diameter =
      o.num("angular_diameter", l.angular_diameter, Range{0.0, 1.5707963267948966});  // pi / 2
  l.shadows = o.boolean("shadows", l.shadows);
  return l;
}

Light parseLight(const Ctx& ctx, const json& j, const std::string& ptr) {
  std::optional<LightType> type;
  if (j.is_object() && j.contains("type"))
    type = Obj::enumAt<LightType>(ctx, j["type"], ptr + "/type");
  if (!type) {
    if (!j.is_object()) ctx.fail(ptr, "expected an object, got " + shortDump(j));
    ctx.fail(ptr + "/type", "missing; expected one of " + enumNamesJoined<LightType>());
  }
  if (*type == LightType::Directional) return parseDirectional(ctx, j, ptr);
  std::vector<std::string_view> keys = {"type",      "position", "color",
                                        "intensity", "range",    "shadows"};
  if (*type != LightType::Point) keys.push_back("radius");
  if (*type == LightType::Tube) keys.insert(keys.end(), {"length", "axis"});
  if (*type == LightType::Spot) {
    keys.insert(keys.end(), {"direction", "inner_cone_angle", "outer_cone_angle"});
  }
  Obj o(ctx, j, ptr, keys);
  Light l;
  l.type = *type;
  l.position = o.vec3("position", l.position);
  l.color = o.vec3("color", l.color, kNonNeg);
  l.intensity = o.num("intensity", l.intensity, kNonNeg);
  l.range = o.num("range", l.range, kPositive);
  l.shadows = o.boolean("shadows", l.shadows);
  if (l.type == LightType::Sphere) l.radius = o.num("radius", 0.1f, kPositive);
  if (l.type == LightType::Tube) {
    l.radius = o.num("radius", 0.05f, kNonNeg);
    l.length = o.num("length", 1.0f, kPositive);
    const glm::vec3 a = o.vec3("axis", l.axis);
    if (glm::length(a) < 1e-6f) o.fail("axis", "expected a non-zero direction, got [0, 0, 0]");
    l.axis = glm::normalize(a);
  }
  if (l.type == LightType::Spot) parseSpot(o, l);
  return l;
}

void expandGenerator(const Ctx& ctx, const json& j, const std::string& ptr,
                     std::vector<Light>& out) {
  Obj o(ctx, j, ptr,
        {"count", "seed", "types", "volume", "intensity", "radius", "length", "range", "color_mode",
         "color", "saturation"});
  const int count = o.integer("count", 64, 1, int(kMaxSceneLights));
  if (out.size() + size_t(count) > kMaxSceneLights) {
    o.fail("count", std::to_string(count) + " more lights after " + std::to_string(out.size()) +
                        " exceed the scene's budget of " + std::to_string(kMaxSceneLights) +
                        " lights (kMaxSceneLights)");
  }
  const int seed = o.integer("seed", 1, 0, std::numeric_limits<int>::max());
  float weights[3] = {1.0f, 1.0f, 1.0f};
  if (o.has("types")) {
    Obj t(ctx, o["types"], o.at("types"), {"point", "sphere", "tube"});
    weights[0] = t.num("point", 0.0f, kNonNeg);
    weights[1] = t.num("sphere", 0.0f, kNonNeg);
    weights[2] = t.num("tube", 0.0f, kNonNeg);
    if (weights[0] + weights[1] + weights[2] <= 0.0f) {
      t.ctx().fail(t.ptr(), "expected at least one positive weight among point, sphere, tube");
    }
  }
  glm::vec3 vmin(-5.0f, 0.2f, -5.0f), vmax(5.0f, 3.0f, 5.0f);
  if (o.has("volume")) {
    Obj v(ctx, o["volume"], o.at("volume"), {"min", "max"});
    vmin = v.vec3("min", vmin);
    vmax = v.vec3("max", vmax);
    if (glm::any(glm::greaterThan(vmin, vmax))) v.fail("max", "expected max >= min componentwise");
  }
  const glm::vec2 intensity = rangeAt(o, "intensity", {1.0f, 5.0f}, kNonNeg);
  const glm::vec2 radius = rangeAt(o, "radius", {0.02f, 0.1f}, kPositive);
  const glm::vec2 length = rangeAt(o, "length", {0.2f, 1.0f}, kPositive);
  const glm::vec2 range = rangeAt(o, "range", {1.0f, 3.0f}, kPositive);
  const std::string mode = o.string("color_mode", "random_hue");
  static constexpr std::string_view kModes[] = {"white", "random_hue", "fixed"};
  if (std::find(std::begin(kModes), std::end(kModes), mode) == std::end(kModes)) {
    o.fail("color_mode", "expected one of " + joinNames(kModes) + ", got \"" + mode + "\"" +
                             didYouMean(mode, kModes));
  }
  if (o.has("color") && mode != "fixed") o.fail("color", "only used with color_mode \"fixed\"");
  const glm::vec3 fixed = o.vec3("color", glm::vec3(1.0f), kNonNeg);
  const float saturation = o.num("saturation", 0.7f, kUnit);
  LightGeneratorParams p;
  p.count = count;
  p.seed = uint64_t(seed);
  p.weights = {weights[0], weights[1], weights[2]};
  p.volume_min = vmin;
  p.volume_max = vmax;
  p.intensity = intensity;
  p.radius = radius;
  p.length = length;
  p.range = range;
  p.color_mode = mode == "white"   ? LightColorMode::White
                 : mode == "fixed" ? LightColorMode::Fixed
                                   : LightColorMode::RandomHue;
  p.color = fixed;
  p.saturation = saturation;
  generateLights(p, out);
}

Environment parseEnvironment(const Ctx& ctx, const json& j, const std::string& ptr) {
  Obj o(ctx, j, ptr,
        {"type", "path", "color", "intensity", "rotation_deg", "cube_size", "prefilter_samples",
         "fallback"});
  Environment e;
  e.kind = o.enumeration<EnvironmentKind>("type", e.kind);
  if (o.has("path") && e.kind != EnvironmentKind::HdrFile)
    o.fail("path", "only used with type \"hdr\"");
  if (o.has("color") && e.kind != EnvironmentKind::Uniform) {
    o.fail("color", "only used with type \"uniform\"");
  }
  if (e.kind == EnvironmentKind::HdrFile) {
    if (!o.has("path")) o.fail("path", "missing; type \"hdr\" needs the path of an .hdr file");
    e.path = ctx.resolve(o.at("path"), o.string("path", ""));
    const std::string missing = notAFile(e.path);
    if (!missing.empty() && o.has("fallback")) {  // as a glTF object's fallback
      sceneWarning(
          ctx.file + ": " + o.at("path") + ": " + missing + "; using the fallback environment",
          ctx.warnings);
      return parseEnvironment(ctx, o["fallback"], o.at("fallback"));
    }
    if (!missing.empty()) o.fail("path", missing);
    if (o.has("fallback")) parseEnvironment(ctx, o["fallback"], o.at("fallback"));  // validated
  }
  e.color = o.vec3("color", e.color, kNonNeg);
  e.intensity = o.num("intensity", e.intensity, kNonNeg);
  e.rotation_deg = o.num("rotation_deg", e.rotation_deg);
  e.cube_size = o.integer("cube_size", e.cube_size, 8, 4096);
  if ((e.cube_size & (e.cube_size - 1)) != 0) {
    o.fail("cube_size", "expected a power of two, got " + std::to_string(e.cube_size));
  }
  e.prefilter_samples = o.integer("prefilter_samples", e.prefilter_samples, 1, 65536);
  return e;
}

namespace {

// "brdf" of "brdf.d"; empty for a top-level key.
std::string_view settingGroup(std::string_view key) {
  const size_t dot = key.find('.');
  return dot == std::string_view::npos ? std::string_view() : key.substr(0, dot);
}
// "d" of "brdf.d".
std::string_view settingLeaf(std::string_view key) {
  const size_t dot = key.find('.');
  return dot == std::string_view::npos ? key : key.substr(dot + 1);
}

// One setting's value, parsed as its row's type says.
template <class T>
T parseSetting(const Obj& o, const char* key, T def, const SettingInfo& info) {
  if constexpr (std::is_same_v<T, bool>) {
    return o.boolean(key, def);
  } else if constexpr (std::is_same_v<T, int>) {
    return o.integer(key, def, int(info.lo), int(info.hi));
  } else if constexpr (std::is_same_v<T, float>) {
    return o.num(key, def, Range{info.lo, info.hi, info.lo_open});
  } else {
    return o.enumeration(key, def);
  }
}

}  // namespace

// The settings table (render_settings.hpp) read row by row: its keys are the only ones allowed,
// a preset first so that the explicit settings override it.
RenderSettings parseSettings(const Ctx& ctx, const json& j) {
  std::vector<std::string_view> top = {"preset"};
  std::vector<std::pair<std::string_view, std::vector<std::string_view>>> groups;
  forEachSetting([&](const auto& row) {
    const std::string_view group = settingGroup(row.key);
    const std::string_view first = group.empty() ? std::string_view(row.key) : group;
    if (std::find(top.begin(), top.end(), first) == top.end()) top.push_back(first);
    if (group.empty()) return;
    auto g =
        std::find_if(groups.begin(), groups.end(), [&](const auto& e) { return e.first == group; });
    if (g == groups.end()) g = groups.insert(groups.end(), {group, {}});
    g->second.push_back(settingLeaf(row.key));
  });
  Obj o(ctx, j, "/settings", top);
  RenderSettings s;
  if (o.has("preset")) {
    const std::string name = o.string("preset", "");
    if (!applySettingsPreset(name, s)) {
      o.fail("preset", "unknown preset \"" + name + "\"" + didYouMean(name, settingsPresetNames()) +
                           " (expected one of: " + joinNames(settingsPresetNames()) + ")");
    }
  }
  std::list<std::pair<std::string_view, Obj>> nested;  // made when their first row is read
  forEachSetting([&](const auto& row) {
    const std::string_view group = settingGroup(row.key);
    const Obj* where = &o;
    if (!group.empty()) {
      const std::string g(group);
      if (!o.has(g.c_str())) return;
      auto it = std::find_if(nested.begin(), nested.end(),
                             [&](const auto& e) { return e.first == group; });
      if (it == nested.end()) {
        const auto& keys = std::find_if(groups.begin(), groups.end(), [&](const auto& e) {
                             return e.first == group;
                           })->second;
        it = nested.emplace(nested.end(), group, Obj(ctx, o[g.c_str()], o.at(g), keys));
      }
      where = &it->second;
    }
    const std::string leaf(settingLeaf(row.key));
    s.*row.member = parseSetting(*where, leaf.c_str(), s.*row.member, row.info);
  });
  return s;
}

}  // namespace hv::scene_json
