// Reading scene JSON: typed, range-checked fields whose errors name the file, the JSON pointer
// and what was expected. Private to the scene module (scene_loader.cpp, scene_elements.cpp).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "halfvec/core/suggest.hpp"
#include "halfvec/scene/enums.hpp"
#include "halfvec/scene/scene_error.hpp"

namespace hv::scene_json {

using json = nlohmann::json;
namespace fs = std::filesystem;
inline constexpr double kInf = std::numeric_limits<double>::infinity();

// ", did you mean "x"?" when one candidate is close to `s`, else "" (halfvec/core/suggest.hpp).
inline std::string didYouMean(std::string_view s, std::span<const std::string_view> candidates) {
  return didYouMeanSuffix(s, candidates);
}
// `j` as compact JSON for a message, cut to 60 characters.
std::string shortDump(const json& j);
std::string fmt(double x);
// "" when `path` names a regular file (symlinks followed); else what it names, for a message
// ("file not found: x.glb", "not a file: models is a directory").
std::string notAFile(const std::string& path);

struct Range {
  double lo = -kInf, hi = kInf;
  bool lo_open = false;
  std::string describe() const;
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
inline constexpr double kBig = 1e6;
inline constexpr Range kAny{-kBig, kBig};            // coordinates, angles in degrees
inline constexpr Range kUnit{0.0, 1.0};              // albedo, metallic, roughness, ...
inline constexpr Range kNonNeg{0.0, kBig};           // colors, intensities, lengths that may be 0
inline constexpr Range kPositive{1.0 / kBig, kBig};  // sizes, distances, exposure: > 0 and stays so
inline constexpr Range kFieldOfView{0.01, 179.9};    // degrees
inline constexpr Range kFar{1.0 / kBig, 1e9};        // metres

struct Ctx {
  std::string file;  // for messages
  fs::path dir;      // for relative paths
  std::vector<std::string>* warnings = nullptr;
  [[noreturn]] void fail(const std::string& ptr, const std::string& msg) const {
    throw SceneError(file + ": " + (ptr.empty() ? std::string("/") : ptr) + ": " + msg);
  }
  // Expands ${VAR} and resolves relative to the scene file's folder.
  std::string resolve(const std::string& ptr, const std::string& p) const;
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
glm::vec2 rangeAt(const Obj& o, const char* key, glm::vec2 def, Range r);

}  // namespace hv::scene_json
