#include "halfvec/scene/scene_loader.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <list>
#include <numbers>
#include <optional>
#include <sstream>
#include <type_traits>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include "halfvec/core/input_file.hpp"
#include "halfvec/core/suggest.hpp"
#include "halfvec/scene/enums.hpp"
#include "halfvec/scene/gltf_loader.hpp"
#include "halfvec/scene/light_generator.hpp"
#include "halfvec/scene/presets.hpp"
#include "halfvec/scene/primitives.hpp"

namespace hv {

void sceneWarning(const std::string& message, std::vector<std::string>* sink) {
  if (sink) {
    sink->push_back(message);
  } else {
    std::cerr << "halfvec: warning: " << message << "\n";
  }
}

namespace {

using json = nlohmann::json;
namespace fs = std::filesystem;
constexpr double kInf = std::numeric_limits<double>::infinity();

// ", did you mean "x"?" when one candidate is close to `s`, else "" (halfvec/core/suggest.hpp).
std::string didYouMean(std::string_view s, std::span<const std::string_view> candidates) {
  return didYouMeanSuffix(s, candidates);
}

std::string shortDump(const json& j) {
  // error_handler_t::replace: a string from a --set value need not be UTF-8 (a file's is
  // checked by the parser); the default handler would throw from inside an error message.
  std::string s = j.dump(-1, ' ', false, json::error_handler_t::replace);
  if (s.size() > 60) s = s.substr(0, 57) + "...";
  return s;
}

std::string fmt(double x) {
  std::ostringstream o;
  o << x;
  return o.str();
}

// "" when `path` names a regular file (symlinks followed); else what it names, for a message
// ("file not found: x.glb", "not a file: models is a directory").
std::string notAFile(const std::string& path) {
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  if (fs::is_regular_file(st)) return "";
  if (!fs::exists(st)) return "file not found: " + path;
  const char* kind = fs::is_directory(st)        ? "a directory"
                     : fs::is_character_file(st) ? "a character device"
                     : fs::is_block_file(st)     ? "a block device"
                     : fs::is_fifo(st)           ? "a FIFO (named pipe)"
                     : fs::is_socket(st)         ? "a socket"
                                                 : "not a regular file";
  return "not a file: " + path + " is " + kind;
}

struct Range {
  double lo = -kInf, hi = kInf;
  bool lo_open = false;
  std::string describe() const {
    if (lo == -kInf && hi == kInf) return "a number";
    if (hi == kInf) return std::string("a number ") + (lo_open ? "> " : ">= ") + fmt(lo);
    if (lo == -kInf) return "a number <= " + fmt(hi);
    return std::string("a number in ") + (lo_open ? "(" : "[") + fmt(lo) + ", " + fmt(hi) + "]";
  }
  bool contains(double x) const {
    return std::isfinite(x) && (lo_open ? x > lo : x >= lo) && x <= hi;
  }
  // The same for a value stored as a float, against the bounds as floats: 1e-6 written in a file
  // becomes the float nearest 1e-6, which is below the double 1e-6 but is the documented minimum.
  bool containsFloat(float f) const {
    const float flo = float(lo), fhi = float(hi);
    return std::isfinite(f) && (lo_open ? f > flo : f >= flo) && f <= fhi;
  }
};
// Every number is stored as a float, so every range is finite and a positive range starts at a
// float-representable minimum: 1e308 or 1e-300 can never become +inf or 0 after validation.
// Coordinates and sizes are metres: within +-1e6 (1000 km) a float keeps ~6 cm; lengths from
// 1e-6 (a micrometre) up. Colors, intensities and exposure get six decades either way. The
// ranges are documented per field in docs/scene-format.md.
constexpr double kBig = 1e6;
constexpr Range kAny{-kBig, kBig};            // coordinates, angles in degrees
constexpr Range kUnit{0.0, 1.0};              // albedo, metallic, roughness, ...
constexpr Range kNonNeg{0.0, kBig};           // colors, intensities, lengths that may be 0
constexpr Range kPositive{1.0 / kBig, kBig};  // sizes, distances, exposure: > 0 and stays so
constexpr Range kFieldOfView{0.01, 179.9};    // degrees
constexpr Range kFar{1.0 / kBig, 1e9};        // metres

struct Ctx {
  std::string file;  // for messages
  fs::path dir;      // for relative paths
  std::vector<std::string>* warnings = nullptr;
  [[noreturn]] void fail(const std::string& ptr, const std::string& msg) const {
    throw SceneError(file + ": " + (ptr.empty() ? std::string("/") : ptr) + ": " + msg);
  }
  // Expands ${VAR} and resolves relative to the scene file's folder.
  std::string resolve(const std::string& ptr, const std::string& p) const {
    std::string expanded;
    try {
      expanded = expandEnvVars(p);
    } catch (const SceneError& e) {
      fail(ptr, e.what());
    }
    fs::path path(expanded);
    if (path.is_relative()) path = dir / path;
    return path.lexically_normal().string();
  }
};

// A JSON object being read: checks its type and its keys on construction.
class Obj {
 public:
  Obj(const Ctx& ctx, const json& j, std::string ptr, std::vector<std::string_view> allowed)
      : ctx_(ctx), j_(j), ptr_(std::move(ptr)) {
    if (!j.is_object()) ctx.fail(ptr_, "expected an object, got " + shortDump(j));
    for (const auto& [key, value] : j.items()) {
      if (std::find(allowed.begin(), allowed.end(), key) == allowed.end()) {
        ctx.fail(at(key), "unknown key \"" + key + "\"" + didYouMean(key, allowed) +
                              " (allowed here: " + joinNames(allowed) + ")");
      }
    }
  }
  const Ctx& ctx() const { return ctx_; }
  const std::string& ptr() const { return ptr_; }
  std::string at(std::string_view key) const { return ptr_ + "/" + std::string(key); }
  bool has(const char* key) const { return j_.contains(key); }
  const json& operator[](const char* key) const { return j_.at(key); }
  [[noreturn]] void fail(const char* key, const std::string& msg) const { ctx_.fail(at(key), msg); }

  double number(const char* key, double def, Range r = kAny) const {
    if (!has(key)) return def;
    return numberAt(ctx_, (*this)[key], at(key), r);
  }
  float num(const char* key, float def, Range r = kAny) const {
    if (!has(key)) return def;
    return floatAt(ctx_, (*this)[key], at(key), r);
  }
  int integer(const char* key, int def, int lo, int hi) const {
    if (!has(key)) return def;
    const json& v = (*this)[key];
    // An unsigned value beyond int64 would wrap in get<int64_t>(): compare it as unsigned.
    const bool ok =
        v.is_number_unsigned()
            ? v.get<uint64_t>() <= uint64_t(std::max(hi, 0)) && int64_t(v.get<uint64_t>()) >= lo
            : v.is_number_integer() && v.get<int64_t>() >= lo && v.get<int64_t>() <= hi;
    if (!ok) {
      fail(key, "expected an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) +
                    "], got " + shortDump(v));
    }
    return int(v.get<int64_t>());
  }
  bool boolean(const char* key, bool def) const {
    if (!has(key)) return def;
    const json& v = (*this)[key];
    if (!v.is_boolean()) fail(key, "expected true or false, got " + shortDump(v));
    return v.get<bool>();
  }
  std::string string(const char* key, const std::string& def) const {
    if (!has(key)) return def;
    const json& v = (*this)[key];
    if (!v.is_string()) fail(key, "expected a string, got " + shortDump(v));
    return v.get<std::string>();
  }
  glm::vec3 vec3(const char* key, glm::vec3 def, Range r = kAny) const {
    if (!has(key)) return def;
    return vec3At(ctx_, (*this)[key], at(key), r);
  }
  template <class E>
  E enumeration(const char* key, E def) const {
    if (!has(key)) return def;
    return enumAt<E>(ctx_, (*this)[key], at(key));
  }

  static double numberAt(const Ctx& ctx, const json& v, const std::string& ptr, Range r) {
    if (!v.is_number() || !r.contains(v.get<double>())) {
      ctx.fail(ptr, "expected " + r.describe() + ", got " + shortDump(v));
    }
    return v.get<double>();
  }
  // numberAt, as the float it is stored in: still finite and inside the range after conversion.
  static float floatAt(const Ctx& ctx, const json& v, const std::string& ptr, Range r) {
    const double d = numberAt(ctx, v, ptr, r);
    const float f = float(d);  // |d| <= kBig: representable
    if (!r.containsFloat(f)) ctx.fail(ptr, "expected " + r.describe() + ", got " + shortDump(v));
    return f;
  }
  static glm::vec3 vec3At(const Ctx& ctx, const json& v, const std::string& ptr, Range r) {
    const std::string what = r.lo == -kInf && r.hi == kInf
                                 ? "an array of 3 numbers"
                                 : "an array of 3 numbers, each " + r.describe().substr(9);
    if (!v.is_array() || v.size() != 3) ctx.fail(ptr, "expected " + what + ", got " + shortDump(v));
    glm::vec3 out;
    for (int i = 0; i < 3; ++i) {
      if (!v[size_t(i)].is_number() || !r.contains(v[size_t(i)].get<double>()) ||
          !r.containsFloat(float(v[size_t(i)].get<double>()))) {
        ctx.fail(ptr, "expected " + what + ", got " + shortDump(v));
      }
      out[i] = float(v[size_t(i)].get<double>());
    }
    return out;
  }
  template <class E>
  static E enumAt(const Ctx& ctx, const json& v, const std::string& ptr) {
    if (v.is_string()) {
      if (auto e = fromString<E>(v.get<std::string>())) return *e;
    }
    ctx.fail(ptr, "expected one of " + enumNamesJoined<E>() + ", got " + shortDump(v) +
                      (v.is_string() ? didYouMean(v.get<std::string>(), enumNames<E>()) : ""));
  }

 private:
  const Ctx& ctx_;
  const json& j_;
  std::string ptr_;
};

// [lo, hi] with lo <= hi, or a single number meaning [x, x].
glm::vec2 rangeAt(const Obj& o, const char* key, glm::vec2 def, Range r) {
  if (!o.has(key)) return def;
  const json& v = o[key];
  if (v.is_number()) {
    const float x = Obj::floatAt(o.ctx(), v, o.at(key), r);
    return {x, x};
  }
  if (!v.is_array() || v.size() != 2 || !v[0].is_number() || !v[1].is_number() ||
      !r.contains(v[0].get<double>()) || !r.contains(v[1].get<double>()) ||
      v[0].get<double>() > v[1].get<double>()) {
    o.fail(key, "expected [min, max] with min <= max, each " + r.describe().substr(9) +
                    ", or a single number, got " + shortDump(v));
  }
  return {Obj::floatAt(o.ctx(), v[0], o.at(key) + "/0", r),
          Obj::floatAt(o.ctx(), v[1], o.at(key) + "/1", r)};
}

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
  std::vector<std::string_view> keys = {"base_color", "metallic",      "roughness",   "cavity",
                                        "emissive",   "shading_model", "double_sided"};
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
  if (o.has("shading_model")) {
    m.model = o.enumeration<ShadingModel>("shading_model", m.model);
    if (m.model == ShadingModel::Background) {
      o.fail("shading_model", "expected \"default_lit\" or \"unlit\", got \"background\"");
    }
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

Light parseLight(const Ctx& ctx, const json& j, const std::string& ptr) {
  std::optional<LightType> type;
  if (j.is_object() && j.contains("type"))
    type = Obj::enumAt<LightType>(ctx, j["type"], ptr + "/type");
  if (!type) {
    if (!j.is_object()) ctx.fail(ptr, "expected an object, got " + shortDump(j));
    ctx.fail(ptr + "/type", "missing; expected one of " + enumNamesJoined<LightType>());
  }
  std::vector<std::string_view> keys = {"type",      "position", "color",
                                        "intensity", "range",    "shadows"};
  if (*type != LightType::Point) keys.push_back("radius");
  if (*type == LightType::Tube) keys.insert(keys.end(), {"length", "axis"});
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

Environment parseEnvironment(const Ctx& ctx, const json& j,
                             const std::string& ptr = "/environment") {
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

class SceneBuilder {
 public:
  SceneBuilder(const Ctx& ctx, Scene& scene) : ctx_(ctx), scene_(scene) {}

  void parseMaterials(const json& j) {
    const std::string ptr = "/materials";
    if (j.is_object()) {
      for (const auto& [name, m] : j.items()) addNamed(m, ptr + "/" + name, name, false);
    } else if (j.is_array()) {
      for (size_t i = 0; i < j.size(); ++i) {
        const std::string p = ptr + "/" + std::to_string(i);
        if (!j[i].is_object() || !j[i].contains("name") || !j[i]["name"].is_string()) {
          ctx_.fail(p + "/name", "missing; materials given as a list need a \"name\" string");
        }
        addNamed(j[i], p, j[i]["name"].get<std::string>(), true);
      }
    } else {
      ctx_.fail(ptr, "expected an object (name -> material) or a list, got " + shortDump(j));
    }
  }

  void parseObject(const json& j, const std::string& ptr) {
    if (!j.is_object()) ctx_.fail(ptr, "expected an object, got " + shortDump(j));
    const bool has_prim = j.contains("primitive"), has_gltf = j.contains("gltf");
    if (has_prim == has_gltf) {
      ctx_.fail(ptr, "expected exactly one of \"primitive\" or \"gltf\"");
    }
    const std::string default_name = "object" + std::to_string(object_count_++);
    if (has_prim) {
      parsePrimitiveObject(j, ptr, std::nullopt, default_name);
    } else {
      parseGltfObject(j, ptr, default_name);
    }
  }

 private:
  void addNamed(const json& j, const std::string& ptr, const std::string& name, bool allow_name) {
    if (material_names_.size() != scene_.materials.size()) ctx_.fail(ptr, "internal error");
    if (std::find(material_names_.begin(), material_names_.end(), name) != material_names_.end()) {
      ctx_.fail(ptr, "duplicate material name \"" + name + "\"");
    }
    Material m = parseMaterial(ctx_, j, ptr, allow_name);
    m.name = name;
    scene_.materials.push_back(m);
    material_names_.push_back(name);
  }

  int materialRef(const json& j, const std::string& ptr, const std::string& object_name) {
    if (j.is_string()) {
      const std::string name = j.get<std::string>();
      for (size_t i = 0; i < material_names_.size(); ++i) {
        if (material_names_[i] == name) return int(i);
      }
      std::vector<std::string_view> names(material_names_.begin(), material_names_.end());
      ctx_.fail(ptr, "no material named \"" + name + "\"" + didYouMean(name, names));
    }
    if (!j.is_object()) {
      ctx_.fail(ptr, "expected a material name or an inline material object, got " + shortDump(j));
    }
    Material m = parseMaterial(ctx_, j, ptr, false);
    m.name = object_name;
    scene_.materials.push_back(m);
    material_names_.push_back("");  // inline materials cannot be referenced by name
    return int(scene_.materials.size() - 1);
  }

  int defaultMaterial() {
    if (default_material_ < 0) {
      Material m;
      m.name = "default";
      scene_.materials.push_back(m);
      material_names_.push_back("");
      default_material_ = int(scene_.materials.size() - 1);
    }
    return default_material_;
  }

  // `inherited`: the transform of the gltf object whose fallback this is.
  void parsePrimitiveObject(const json& j, const std::string& ptr,
                            std::optional<glm::mat4> inherited, const std::string& default_name) {
    std::optional<PrimKind> kind;
    if (j.contains("primitive") && j["primitive"].is_string()) {
      const std::string s = j["primitive"].get<std::string>();
      for (size_t i = 0; i < std::size(kPrimNames); ++i) {
        if (kPrimNames[i] == s) kind = PrimKind(i);
      }
    }
    if (!kind) {
      ctx_.fail(ptr + "/primitive",
                "expected one of " + joinNames(kPrimNames) + ", got " +
                    (j.contains("primitive") ? shortDump(j["primitive"]) : std::string("nothing")) +
                    (j.contains("primitive") && j["primitive"].is_string()
                         ? didYouMean(j["primitive"].get<std::string>(), kPrimNames)
                         : ""));
    }
    std::vector<std::string_view> keys = {"name", "primitive", "transform", "material"};
    switch (*kind) {
      case PrimKind::Sphere:
        keys.insert(keys.end(), {"radius", "segments", "rings"});
        break;
      case PrimKind::Plane:
        keys.insert(keys.end(), {"size"});
        break;
      case PrimKind::Box:
        keys.insert(keys.end(), {"half_extents"});
        break;
      case PrimKind::Capsule:
        keys.insert(keys.end(), {"radius", "half_length", "segments", "rings"});
        break;
    }
    Obj o(ctx_, j, ptr, keys);
    Object obj;
    obj.name = o.string("name", default_name);
    obj.transform = o.has("transform") ? parseTransform(ctx_, o["transform"], o.at("transform"))
                                       : inherited.value_or(glm::mat4(1.0f));
    Mesh mesh;
    // Tessellation budget, checked before the mesh is built (vertex counts of primitives.cpp).
    auto budget = [&](int segments, int rings, size_t vertices) {
      primitive_vertices_ += vertices;
      if (primitive_vertices_ > kMaxPrimitiveVertices) {
        o.fail("segments", std::to_string(segments) + " segments x " + std::to_string(rings) +
                               " rings (" + std::to_string(vertices) +
                               " vertices) exceed the scene's budget of " +
                               std::to_string(kMaxPrimitiveVertices) +
                               " primitive vertices (kMaxPrimitiveVertices)");
      }
    };
    switch (*kind) {
      case PrimKind::Sphere: {
        const float radius = o.num("radius", 0.5f, kPositive);
        const int segments = o.integer("segments", 64, 3, 4096),
                  rings = o.integer("rings", 32, 2, 4096);
        budget(segments, rings, size_t(segments + 1) * size_t(rings + 1));
        if (!validate_only_) mesh = makeSphere(radius, segments, rings);
        break;
      }
      case PrimKind::Plane: {
        glm::vec2 size(10.0f);
        if (o.has("size")) {
          const json& v = o["size"];
          if (v.is_number()) {
            size = glm::vec2(o.num("size", 10.0f, kPositive));
          } else if (v.is_array() && v.size() == 2 && v[0].is_number() && v[1].is_number() &&
                     kPositive.contains(v[0].get<double>()) &&
                     kPositive.contains(v[1].get<double>())) {
            size = glm::vec2(float(v[0].get<double>()), float(v[1].get<double>()));
          } else {
            o.fail("size", "expected [size_x, size_z], each " + kPositive.describe().substr(9) +
                               ", or such a number, got " + shortDump(v));
          }
        }
        mesh = makePlane(size.x, size.y);
        break;
      }
      case PrimKind::Box:
        mesh = makeBox(o.vec3("half_extents", glm::vec3(0.5f), kPositive));
        break;
      case PrimKind::Capsule: {
        const float radius = o.num("radius", 0.25f, kPositive);
        const float half_length = o.num("half_length", 0.5f, kNonNeg);
        const int segments = o.integer("segments", 48, 3, 4096),
                  rings = o.integer("rings", 24, 2, 4096);
        budget(segments, rings, size_t(segments + 1) * size_t(2 * ((rings + 1) / 2 + 1)));
        if (!validate_only_) mesh = makeCapsule(radius, half_length, segments, rings);
        break;
      }
    }
    mesh.material = o.has("material") ? materialRef(o["material"], o.at("material"), obj.name)
                                      : defaultMaterial();
    mesh.name = obj.name + "/" + mesh.name;
    scene_.meshes.push_back(std::move(mesh));
    obj.meshes.push_back(int(scene_.meshes.size() - 1));
    scene_.objects.push_back(std::move(obj));
  }

  void parseGltfObject(const json& j, const std::string& ptr, const std::string& default_name) {
    Obj o(ctx_, j, ptr, {"name", "gltf", "transform", "material_override", "fallback"});
    const std::string name = o.string("name", default_name);
    const glm::mat4 transform = o.has("transform")
                                    ? parseTransform(ctx_, o["transform"], o.at("transform"))
                                    : glm::mat4(1.0f);
    const std::string file = o.string("gltf", "");
    if (file.empty()) o.fail("gltf", "expected the path of a .gltf or .glb file");
    // A model that cannot be found (a missing file, or a ${VAR} in its path that is not set) is
    // replaced by the fallback object when there is one.
    std::string path, missing;
    try {
      path = ctx_.resolve(o.at("gltf"), file);
      missing = notAFile(path);
    } catch (const SceneError& e) {
      if (!o.has("fallback")) throw;
      missing = e.what();
    }
    if (!missing.empty()) {
      if (!o.has("fallback")) o.fail("gltf", missing);
      sceneWarning(
          (missing.rfind(ctx_.file, 0) == 0 ? missing
                                            : ctx_.file + ": " + o.at("gltf") + ": " + missing) +
              "; using the fallback object",
          ctx_.warnings);
      const json& fb = o["fallback"];
      if (!fb.is_object() || !fb.contains("primitive")) {
        o.fail("fallback", "expected an object with a \"primitive\"");
      }
      parsePrimitiveObject(fb, o.at("fallback"), transform, name);
      return;
    }
    if (o.has("fallback")) {  // validate it even when unused, so errors do not hide
      Scene scratch;
      SceneBuilder check(ctx_, scratch);
      check.material_names_ = material_names_;
      check.validate_only_ = true;  // its mesh is never used: do not build it
      check.scene_.materials = scene_.materials;
      check.parsePrimitiveObject(o["fallback"], o.at("fallback"), transform, name);
    }
    GltfOptions opt;
    opt.name_prefix = name;
    opt.warnings = ctx_.warnings;
    if (o.has("material_override")) {
      opt.material_override = materialRef(o["material_override"], o.at("material_override"), name);
    }
    try {
      loadGltf(path, transform, scene_, opt);
    } catch (const SceneError& e) {
      ctx_.fail(o.at("gltf"), e.what());
    }
  }

  enum class PrimKind { Sphere, Plane, Box, Capsule };
  static constexpr std::string_view kPrimNames[] = {"sphere", "plane", "box", "capsule"};

  const Ctx& ctx_;
  Scene& scene_;
  std::vector<std::string> material_names_;  // parallel to scene_.materials; "" = unnamed
  int default_material_ = -1;
  int object_count_ = 0;
  size_t primitive_vertices_ = 0;
  // Checks objects without building their meshes (an unused fallback).
  bool validate_only_ = false;
};

// nlohmann's message without its "[json.exception.parse_error.101] " prefix.
std::string jsonErrorText(const json::exception& e) {
  std::string m = e.what();
  if (m.rfind("[json.exception.", 0) == 0) {
    const size_t end = m.find("] ");
    if (end != std::string::npos) m = m.substr(end + 2);
  }
  return m;
}

}  // namespace

std::string readSceneFile(const std::string& path) {
  try {
    return readInputFile(path, kMaxSceneFileBytes, "kMaxSceneFileBytes");
  } catch (const InputError& e) {
    throw SceneError(e.what());
  }
}

namespace {

std::string positionPrefix(const std::string& source_name, std::string_view text, size_t offset) {
  const TextPosition p = textPosition(text, offset);
  return source_name + ": line " + std::to_string(p.line) + ", column " + std::to_string(p.column) +
         ": ";
}

}  // namespace

void checkSceneJsonText(std::string_view text, const std::string& source_name) {
  // nlohmann's lexer ends the input at a NUL byte: whatever follows would be ignored silently.
  if (const size_t nul = text.find('\0'); nul != std::string_view::npos) {
    throw SceneError(positionPrefix(source_name, text, nul) + "invalid JSON: NUL byte at offset " +
                     std::to_string(nul) + " (not a text file?)");
  }
  if (const size_t at = jsonNestingBeyond(text, kMaxSceneJsonDepth); at != std::string_view::npos) {
    throw SceneError(positionPrefix(source_name, text, at) + "JSON nesting deeper than " +
                     std::to_string(kMaxSceneJsonDepth) + " levels (kMaxSceneJsonDepth)");
  }
}

void throwSceneJsonError(const json::exception& e, std::string_view text,
                         const std::string& source_name) {
  std::string m = jsonErrorText(e);
  if (const auto* pe = dynamic_cast<const json::parse_error*>(&e)) {
    // "parse error at line L, column C: syntax error ...": the position goes in front, in the
    // loader's style. nlohmann's byte is 1-based, the character it stopped at.
    if (const size_t colon = m.find(": "); m.rfind("parse error", 0) == 0 && colon != m.npos) {
      m = m.substr(colon + 2);
    }
    throw SceneError(positionPrefix(source_name, text, pe->byte > 0 ? pe->byte - 1 : 0) +
                     "invalid JSON: " + m);
  }
  // out_of_range 406, a number beyond double range (1e400): nlohmann gives the token but no
  // position; the token's first occurrence in the text gives it.
  const size_t q0 = m.find('\''), q1 = m.rfind('\'');
  if (q0 != std::string::npos && q1 > q0 + 1) {
    const size_t at = text.find(m.substr(q0 + 1, q1 - q0 - 1));
    if (at != std::string_view::npos) {
      throw SceneError(positionPrefix(source_name, text, at) + "invalid JSON: " + m +
                       " (numbers must fit a double)");
    }
  }
  throw SceneError(source_name + ": invalid JSON: " + m + " (numbers must fit a double)");
}

std::string expandEnvVars(const std::string& text) {
  std::string out;
  size_t i = 0;
  while (i < text.size()) {
    if (text.compare(i, 2, "${") == 0) {
      const size_t end = text.find('}', i + 2);
      if (end == std::string::npos) throw SceneError("unterminated \"${\" in \"" + text + "\"");
      const std::string var = text.substr(i + 2, end - i - 2);
      const char* value = std::getenv(var.c_str());
      if (value && *value) {
        out += value;
      } else {
        throw SceneError("environment variable " + var + " (used in \"" + text + "\") is not set");
      }
      i = end + 1;
    } else {
      out += text[i++];
    }
  }
  return out;
}

void applyOverride(json& j, const std::string& text, const std::string& source_name) {
  auto fail = [&](const std::string& msg) -> void {
    throw SceneError(source_name + ": override \"" + text + "\": " + msg);
  };
  const size_t eq = text.find('=');
  if (eq == std::string::npos || eq == 0) {
    fail("expected json.path=value");
  }
  const std::string path = text.substr(0, eq), value_text = text.substr(eq + 1);
  json value = json::parse(value_text, nullptr, false);
  if (value.is_discarded()) value = value_text;
  std::vector<std::string> parts;
  for (size_t start = 0;;) {
    const size_t dot = path.find('.', start);
    parts.push_back(path.substr(start, dot - start));
    if (dot == std::string::npos) break;
    start = dot + 1;
  }
  json* cur = &j;
  for (size_t k = 0; k < parts.size(); ++k) {
    const std::string& part = parts[k];
    if (part.empty()) fail("empty path component");
    const bool last = k + 1 == parts.size();
    if (cur->is_array()) {
      size_t idx = 0;
      const bool numeric = std::all_of(part.begin(), part.end(), ::isdigit);
      if (!numeric) fail("\"" + part + "\" is not an array index");
      // Parsed strictly: digits only, no overflow (an index past the list is an error below).
      const auto [end, ec] = std::from_chars(part.data(), part.data() + part.size(), idx);
      if (ec != std::errc() || end != part.data() + part.size())
        idx = std::numeric_limits<size_t>::max();
      if (idx > cur->size() || (idx == cur->size() && !last)) {
        fail("index " + part + " out of range (size " + std::to_string(cur->size()) + ")");
      }
      if (idx == cur->size()) {
        cur->push_back(value);
        return;
      }
      cur = &(*cur)[idx];
    } else if (cur->is_object() || cur->is_null()) {
      if (cur->is_null()) *cur = json::object();
      cur = &(*cur)[part];
    } else {
      fail("cannot descend into \"" + part + "\": the value there is " + shortDump(*cur));
    }
    if (last) *cur = value;
  }
}

Scene parseScene(const json& j, const std::string& source_name,
                 std::vector<std::string>* warnings) {
  Ctx ctx;
  ctx.file = source_name;
  ctx.dir = fs::path(source_name).parent_path();
  ctx.warnings = warnings;
  Obj top(ctx, j, "",
          {"description", "camera", "materials", "objects", "lights", "light_generators",
           "environment", "settings"});
  Scene scene;
  scene.source_path = source_name;
  if (top.has("description")) top.string("description", "");
  if (top.has("camera")) scene.camera = parseCamera(ctx, top["camera"]);
  SceneBuilder builder(ctx, scene);
  if (top.has("materials")) builder.parseMaterials(top["materials"]);
  auto list = [&](const char* key) -> const json& {
    const json& v = top[key];
    if (!v.is_array()) top.fail(key, "expected a list, got " + shortDump(v));
    return v;
  };
  if (top.has("objects")) {
    const json& objs = list("objects");
    for (size_t i = 0; i < objs.size(); ++i) {
      builder.parseObject(objs[i], "/objects/" + std::to_string(i));
    }
  }
  if (top.has("lights")) {
    const json& ls = list("lights");
    if (ls.size() > kMaxSceneLights) {
      top.fail("lights", std::to_string(ls.size()) + " lights exceed the budget of " +
                             std::to_string(kMaxSceneLights) + " (kMaxSceneLights)");
    }
    for (size_t i = 0; i < ls.size(); ++i) {
      scene.lights.push_back(parseLight(ctx, ls[i], "/lights/" + std::to_string(i)));
    }
  }
  if (top.has("light_generators")) {
    const json& gs = list("light_generators");
    for (size_t i = 0; i < gs.size(); ++i) {
      expandGenerator(ctx, gs[i], "/light_generators/" + std::to_string(i), scene.lights);
    }
  }
  if (top.has("environment")) scene.environment = parseEnvironment(ctx, top["environment"]);
  if (top.has("settings")) scene.settings = parseSettings(ctx, top["settings"]);
  return scene;
}

Scene loadSceneFromString(std::string_view text, const std::string& source_name,
                          const std::vector<std::string>& overrides,
                          std::vector<std::string>* warnings) {
  checkSceneJsonText(text, source_name);
  json j;
  try {
    j = json::parse(text);
  } catch (const json::exception& e) {
    throwSceneJsonError(e, text, source_name);
  }
  for (const std::string& o : overrides) applyOverride(j, o, source_name);
  return parseScene(j, source_name, warnings);
}

Scene loadScene(const std::string& path, const std::vector<std::string>& overrides,
                std::vector<std::string>* warnings) {
  try {
    return loadSceneFromString(readSceneFile(path), path, overrides, warnings);
  } catch (const SceneError&) {
    throw;
  } catch (const std::bad_alloc&) {
    throw SceneError(path + ": out of memory while building the scene");
  } catch (const std::exception& e) {  // a check missing in the loader (the fuzzer looks for these)
    throw SceneError(path + ": " + e.what() + " (internal error: unchecked input)");
  }
}

}  // namespace hv
