#include "scene_json.hpp"

#include <sstream>

#include "halfvec/scene/scene_loader.hpp"

namespace hv::scene_json {

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

std::string Range::describe() const {
  if (lo == -kInf && hi == kInf) return "a number";
  if (hi == kInf) return std::string("a number ") + (lo_open ? "> " : ">= ") + fmt(lo);
  if (lo == -kInf) return "a number <= " + fmt(hi);
  return std::string("a number in ") + (lo_open ? "(" : "[") + fmt(lo) + ", " + fmt(hi) + "]";
}

std::string Ctx::resolve(const std::string& ptr, const std::string& p) const {
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

}  // namespace hv::scene_json
