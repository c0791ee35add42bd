#include "halfvec/scene/scene_writer.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

#include "halfvec/core/output_files.hpp"
#include "halfvec/scene/enums.hpp"
#include "halfvec/scene/scene_error.hpp"

namespace hv {

namespace {

using ojson = nlohmann::ordered_json;

// ---- formatting -------------------------------------------------------------------------------

bool isScalar(const ojson& j) {
  return !j.is_object() && !j.is_array();
}

std::string oneLine(const ojson& j) {
  if (j.is_number_float()) return formatNumber(j.get<double>());
  if (isScalar(j)) return j.dump();
  std::string s(j.is_object() ? "{" : "[");
  bool first = true;
  if (j.is_object()) {
    for (const auto& [k, v] : j.items()) {
      if (!first) s += ", ";
      s += ojson(k).dump();
      s += ": ";
      s += oneLine(v);
      first = false;
    }
  } else {
    for (const auto& v : j) {
      if (!first) s += ", ";
      s += oneLine(v);
      first = false;
    }
  }
  s += j.is_object() ? "}" : "]";
  return s;
}

// An object of scalars and lists of scalars (a light, a material, a transform).
bool isFlat(const ojson& j) {
  return j.is_object() && std::all_of(j.begin(), j.end(), [](const ojson& v) {
           return isScalar(v) || (v.is_array() && std::all_of(v.begin(), v.end(), isScalar));
         });
}

// `j` written at indentation `indent`, the first line starting after `used` columns of that line.
// `element`: j is an element of a list (a flat element then stays on one line whatever its
// length: one light, one object per line).
std::string formatValue(const ojson& j, int indent, int used, int width, bool top,
                        bool element = false) {
  const std::string line = oneLine(j);
  const bool numbers = j.is_array() && std::all_of(j.begin(), j.end(), isScalar);
  if (isScalar(j) || numbers || (element && isFlat(j)) ||
      (!top && used + int(line.size()) <= width)) {
    return line;
  }
  if (j.empty()) return line;
  const std::string pad(size_t(indent + 2), ' ');
  std::string s(j.is_object() ? "{\n" : "[\n");
  size_t k = 0;
  for (auto it = j.begin(); it != j.end(); ++it, ++k) {
    std::string head = pad;
    if (j.is_object()) {
      head += ojson(it.key()).dump();
      head += ": ";
    }
    s += head;
    s += formatValue(*it, indent + 2, int(head.size()), width - 1, false, j.is_array());
    s += k + 1 < j.size() ? ",\n" : "\n";
  }
  s.append(size_t(indent), ' ');
  s += j.is_object() ? "}" : "]";
  return s;
}

// ---- spans of a JSON text --------------------------------------------------------------------

// One value of the text: [begin, end) and, for objects and arrays, its members; a member also
// records its key (objects) and where its key (or, in an array, its value) begins.
struct Span {
  size_t begin = 0, end = 0;
  char kind = 's';  // '{', '[' or 's' (scalar)
  std::string key;
  size_t key_begin = 0;
  std::vector<Span> members;
};

class SpanParser {
 public:
  SpanParser(const std::string& text, const std::string& source) : t_(text), source_(source) {}
  Span parse() {
    Span s = value();
    skip();
    if (p_ != t_.size()) fail("unexpected text after the JSON value");
    return s;
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw SceneError(source_ + ": cannot edit: invalid JSON at byte " + std::to_string(p_) + ": " +
                     what);
  }
  void skip() {
    while (p_ < t_.size() && std::isspace(static_cast<unsigned char>(t_[p_]))) ++p_;
  }
  std::string string() {
    const size_t start = p_++;
    while (p_ < t_.size() && t_[p_] != '"') p_ += t_[p_] == '\\' ? 2 : 1;
    if (p_ >= t_.size()) fail("unterminated string");
    ++p_;
    return ojson::parse(t_.substr(start, p_ - start)).get<std::string>();
  }
  Span value() {
    skip();
    if (p_ >= t_.size()) fail("unexpected end");
    Span s;
    s.begin = p_;
    const char c = t_[p_];
    if (c == '{' || c == '[') {
      s.kind = c;
      const char close = c == '{' ? '}' : ']';
      ++p_;
      skip();
      if (p_ < t_.size() && t_[p_] == close) {
        s.end = ++p_;
        return s;
      }
      while (true) {
        skip();
        const size_t key_begin = p_;
        std::string key;
        if (c == '{') {
          if (p_ >= t_.size() || t_[p_] != '"') fail("expected a key");
          key = string();
          skip();
          if (p_ >= t_.size() || t_[p_] != ':') fail("expected ':'");
          ++p_;
        }
        Span m = value();
        m.key = std::move(key);
        m.key_begin = key_begin;
        s.members.push_back(std::move(m));
        skip();
        if (p_ < t_.size() && t_[p_] == ',') {
          ++p_;
          continue;
        }
        if (p_ < t_.size() && t_[p_] == close) break;
        fail(std::string("expected ',' or '") + close + "'");
      }
      s.end = ++p_;
      return s;
    }
    if (c == '"') {
      string();
    } else {
      while (p_ < t_.size() && !std::isspace(static_cast<unsigned char>(t_[p_])) && t_[p_] != ',' &&
             t_[p_] != '}' && t_[p_] != ']') {
        ++p_;
      }
    }
    s.end = p_;
    return s;
  }

  const std::string& t_;
  const std::string& source_;
  size_t p_ = 0;
};

std::vector<std::string> pointerTokens(const std::string& pointer) {
  std::vector<std::string> out;
  for (size_t i = 0; i < pointer.size(); ++i) {
    if (pointer[i] == '/') {
      out.emplace_back();
    } else if (!out.empty() && pointer[i] == '~' && i + 1 < pointer.size()) {
      out.back().push_back(pointer[i + 1] == '1' ? '/' : '~');  // RFC 6901 escapes
      ++i;
    } else if (!out.empty()) {
      out.back().push_back(pointer[i]);
    }
  }
  return out;
}

const Span* child(const Span& s, const std::string& token) {
  if (s.kind == '{') {
    for (const auto& m : s.members) {
      if (m.key == token) return &m;
    }
  } else if (s.kind == '[') {
    size_t idx = 0;
    auto [ptr, ec] = std::from_chars(token.data(), token.data() + token.size(), idx);
    if (ec == std::errc() && ptr == token.data() + token.size() && idx < s.members.size()) {
      return &s.members[idx];
    }
  }
  return nullptr;
}

// Column of `pos` on its line and whether [a, b) spans several lines.
int columnOf(const std::string& t, size_t pos) {
  const size_t nl = t.rfind('\n', pos == 0 ? 0 : pos - 1);
  return int(pos - (nl == std::string::npos ? 0 : nl + 1));
}
bool multiLine(const std::string& t, size_t a, size_t b) {
  return t.find('\n', a) < b;
}

// How far a pointer reaches into the text: the deepest value it names that exists (`at`, the
// root when none does), that value as a member of its parent, and how many tokens matched.
struct Reach {
  const Span* at = nullptr;
  const Span* member = nullptr;  // null at the root
  const Span* parent = nullptr;
  size_t depth = 0;
};

Reach reach(const Span& root, const std::vector<std::string>& tokens) {
  Reach r;
  r.at = &root;
  for (; r.depth < tokens.size(); ++r.depth) {
    const Span* m = child(*r.at, tokens[r.depth]);
    if (!m) break;
    r.parent = r.at;
    r.member = m;
    r.at = m;
  }
  return r;
}

// The value of `member` replaced by `value`, its lines indented as the member's key.
std::string replaceValue(const std::string& text, const Span& member, const ojson& value) {
  const int indent = columnOf(text, member.key_begin);
  const int used = columnOf(text, member.begin);
  std::string out = text.substr(0, member.begin);
  out += formatValue(value, indent, used, 100, false);
  out += text.substr(member.end);
  return out;
}

// `member` removed from `parent` with the separator before it (after the member before it), or
// after it when it is the first.
std::string eraseMember(const std::string& text, const Span& parent, const Span& member) {
  const auto& ms = parent.members;
  const size_t k = size_t(&member - ms.data());
  size_t cut_begin = ms[k - (k > 0)].end, cut_end = ms[k].end;  // ", key: value" after k-1
  if (ms.size() == 1) {
    cut_begin = parent.begin + 1;
    cut_end = parent.end - 1;
  } else if (k == 0) {
    cut_begin = ms[0].key_begin;
    cut_end = ms[1].key_begin;
  }
  std::string out = text.substr(0, cut_begin);
  out += text.substr(cut_end);
  return out;
}

// `key: value` as the only member of the empty object `at`, on a line of its own if the braces
// are on different lines.
std::string insertIntoEmpty(const std::string& text, const Span& at, const std::string& key,
                            const ojson& value) {
  const bool ml = multiLine(text, at.begin, at.end);
  const int indent = columnOf(text, at.begin);
  std::string out = text.substr(0, at.begin + 1);
  if (ml) {
    out += '\n';
    out.append(size_t(indent + 2), ' ');
  }
  out += key;
  out += formatValue(value, indent + 2, indent + 2 + int(key.size()), 100, false);
  if (ml) {
    out += '\n';
    out.append(size_t(indent), ' ');
  }
  out += text.substr(at.end - 1);
  return out;
}

// `key: value` after the last member of `at`, on a line of its own where the members are one per
// line, else on the same line.
std::string appendMember(const std::string& text, const Span& at, const std::string& key,
                         const ojson& value) {
  const Span& last = at.members.back();
  const bool own_line = multiLine(text, at.begin, last.key_begin);  // one member per line
  const int indent = columnOf(text, last.key_begin);
  std::string out = text.substr(0, last.end);
  out += ',';
  if (own_line) {
    out += '\n';
    out.append(size_t(indent), ' ');
  } else {
    out += ' ';
  }
  const int used =
      own_line ? indent + int(key.size()) : columnOf(text, last.end) + 2 + int(key.size());
  out += key;
  out += formatValue(value, indent, used, 100, false);
  out += text.substr(last.end);
  return out;
}

std::string applyOne(const std::string& text, const JsonEdit& e, const std::string& source) {
  const Span root = SpanParser(text, source).parse();
  const std::vector<std::string> tokens = pointerTokens(e.pointer);
  const Reach r = reach(root, tokens);
  if (r.depth == tokens.size()) {
    if (tokens.empty()) throw SceneError(source + ": cannot edit the whole document");
    return e.erase ? eraseMember(text, *r.parent, *r.member)
                   : replaceValue(text, *r.member, e.value);
  }
  if (e.erase) return text;  // nothing to remove
  if (r.at->kind != '{') {
    throw SceneError(source + ": cannot edit " + e.pointer + ": no such element");
  }
  // Insert the missing key (with any missing objects below it) as the last member of `at`.
  ojson value = e.value;
  for (size_t k = tokens.size() - 1; k > r.depth; --k) value = ojson{{tokens[k], value}};
  std::string key = ojson(tokens[r.depth]).dump();
  key += ": ";
  return r.at->members.empty() ? insertIntoEmpty(text, *r.at, key, value)
                               : appendMember(text, *r.at, key, value);
}

// ---- scene -> edits --------------------------------------------------------------------------

ojson vec3(glm::vec3 v) {
  return ojson::array({v.x, v.y, v.z});
}

template <class E>
ojson name(E e) {
  return std::string(toString(e));
}

std::string escapeToken(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '~') {
      out += "~0";
    } else if (c == '/') {
      out += "~1";
    } else {
      out += c;
    }
  }
  return out;
}

ojson lightJson(const Light& l) {
  if (l.type == LightType::Directional) {
    ojson j{{"type", name(l.type)},
            {"direction", vec3(l.direction)},
            {"color", vec3(l.color)},
            {"intensity", l.intensity},
            {"angular_diameter", l.angular_diameter}};
    if (l.shadows) j["shadows"] = true;
    return j;
  }
  ojson j{{"type", name(l.type)},
          {"position", vec3(l.position)},
          {"color", vec3(l.color)},
          {"intensity", l.intensity}};
  if (l.type != LightType::Point) j["radius"] = l.radius;
  if (l.type == LightType::Tube) {
    j["length"] = l.length;
    j["axis"] = vec3(l.axis);
  }
  if (l.type == LightType::Spot) {
    j["direction"] = vec3(l.direction);
    j["inner_cone_angle"] = l.inner_cone_angle;
    j["outer_cone_angle"] = l.outer_cone_angle;
  }
  j["range"] = l.range;
  if (l.shadows) j["shadows"] = true;
  return j;
}

bool sameLight(const Light& a, const Light& b) {
  return lightJson(a) == lightJson(b);
}

struct Collector {
  std::vector<JsonEdit>& out;
  template <class T>
  void field(const std::string& ptr, const T& before, const T& after, const ojson& value) {
    if (!(before == after)) out.push_back({ptr, value, false});
  }
};

void materialEdits(const Scene& loaded, const Scene& edited, Collector& c) {
  for (size_t i = 0; i < edited.materials.size() && i < loaded.materials.size(); ++i) {
    const Material &a = loaded.materials[i], &b = edited.materials[i];
    if (b.source.empty()) continue;  // glTF and default materials: not in the scene file
    std::string p = b.source;
    // The loader's pointers carry material names unescaped; escape them for the editor.
    if (p.rfind("/materials/", 0) == 0) p = "/materials/" + escapeToken(p.substr(11));
    c.field(p + "/base_color", a.base_color, b.base_color, vec3(b.base_color));
    c.field(p + "/metallic", a.metallic, b.metallic, b.metallic);
    c.field(p + "/roughness", a.roughness, b.roughness, b.roughness);
    c.field(p + "/cavity", a.cavity, b.cavity, b.cavity);
    c.field(p + "/emissive", a.emissive, b.emissive, vec3(b.emissive));
    c.field(p + "/shading_model", a.model, b.model, name(b.model));
    c.field(p + "/clearcoat", a.clearcoat, b.clearcoat, b.clearcoat);
    c.field(p + "/clearcoat_roughness", a.clearcoat_roughness, b.clearcoat_roughness,
            b.clearcoat_roughness);
    c.field(p + "/double_sided", a.double_sided, b.double_sided, b.double_sided);
    c.field(p + "/vertex_color", a.vertex_color, b.vertex_color, b.vertex_color);
    c.field(p + "/alpha", a.base_alpha, b.base_alpha, b.base_alpha);
    c.field(p + "/alpha_mode", a.alpha_mode, b.alpha_mode, name(b.alpha_mode));
    c.field(p + "/alpha_cutoff", a.alpha_cutoff, b.alpha_cutoff, b.alpha_cutoff);
  }
}

void lightEdits(const nlohmann::json& file, const Scene& loaded, const Scene& edited,
                Collector& c) {
  const size_t explicit_count =
      file.contains("lights") && file["lights"].is_array() ? file["lights"].size() : 0;
  if (loaded.lights.size() < explicit_count) return;  // not loaded from this file: nothing to map
  bool per_field = edited.lights.size() == loaded.lights.size();
  for (size_t i = explicit_count; per_field && i < loaded.lights.size(); ++i) {
    per_field = sameLight(loaded.lights[i], edited.lights[i]);  // generated lights untouched
  }
  for (size_t i = 0; per_field && i < explicit_count; ++i) {
    per_field = loaded.lights[i].type == edited.lights[i].type;
  }
  if (!per_field) {  // lights added, removed or retyped: the whole list, generators folded in
    ojson list = ojson::array();
    for (const Light& l : edited.lights) list.push_back(lightJson(l));
    c.out.push_back({"/lights", list, false});
    if (file.contains("light_generators")) c.out.push_back({"/light_generators", {}, true});
    return;
  }
  for (size_t i = 0; i < explicit_count; ++i) {
    const Light &a = loaded.lights[i], &b = edited.lights[i];
    const std::string p = "/lights/" + std::to_string(i);
    if (b.type == LightType::Directional) {
      c.field(p + "/direction", a.direction, b.direction, vec3(b.direction));
      c.field(p + "/color", a.color, b.color, vec3(b.color));
      c.field(p + "/intensity", a.intensity, b.intensity, b.intensity);
      c.field(p + "/angular_diameter", a.angular_diameter, b.angular_diameter, b.angular_diameter);
      c.field(p + "/shadows", a.shadows, b.shadows, b.shadows);
      continue;
    }
    c.field(p + "/position", a.position, b.position, vec3(b.position));
    c.field(p + "/color", a.color, b.color, vec3(b.color));
    c.field(p + "/intensity", a.intensity, b.intensity, b.intensity);
    if (b.type != LightType::Point) c.field(p + "/radius", a.radius, b.radius, b.radius);
    if (b.type == LightType::Tube) {
      c.field(p + "/length", a.length, b.length, b.length);
      c.field(p + "/axis", a.axis, b.axis, vec3(b.axis));
    }
    if (b.type == LightType::Spot) {
      c.field(p + "/direction", a.direction, b.direction, vec3(b.direction));
      c.field(p + "/inner_cone_angle", a.inner_cone_angle, b.inner_cone_angle, b.inner_cone_angle);
      c.field(p + "/outer_cone_angle", a.outer_cone_angle, b.outer_cone_angle, b.outer_cone_angle);
    }
    c.field(p + "/range", a.range, b.range, b.range);
    c.field(p + "/shadows", a.shadows, b.shadows, b.shadows);
  }
}

void environmentEdits(const nlohmann::json& file, const Environment& a, const Environment& b,
                      Collector& c) {
  const nlohmann::json* env = file.contains("environment") ? &file["environment"] : nullptr;
  auto has = [&](const char* k) { return env && env->is_object() && env->contains(k); };
  if (a.kind != b.kind) {
    c.out.push_back({"/environment/type", name(b.kind), false});
    if (b.kind != EnvironmentKind::HdrFile && has("path"))
      c.out.push_back({"/environment/path", {}, true});
    if (b.kind != EnvironmentKind::Uniform && has("color"))
      c.out.push_back({"/environment/color", {}, true});
    if (b.kind == EnvironmentKind::HdrFile) c.out.push_back({"/environment/path", b.path, false});
    if (b.kind == EnvironmentKind::Uniform)
      c.out.push_back({"/environment/color", vec3(b.color), false});
  } else {
    if (b.kind == EnvironmentKind::HdrFile) c.field("/environment/path", a.path, b.path, b.path);
    if (b.kind == EnvironmentKind::Uniform)
      c.field("/environment/color", a.color, b.color, vec3(b.color));
  }
  c.field("/environment/intensity", a.intensity, b.intensity, b.intensity);
  c.field("/environment/rotation_deg", a.rotation_deg, b.rotation_deg, b.rotation_deg);
  c.field("/environment/cube_size", a.cube_size, b.cube_size, b.cube_size);
  c.field("/environment/prefilter_samples", a.prefilter_samples, b.prefilter_samples,
          b.prefilter_samples);
}

// Every row of the settings table (render_settings.hpp) that the edit changed, at its JSON path.
void settingsEdits(const RenderSettings& a, const RenderSettings& b, Collector& c) {
  forEachSetting([&](const auto& row) {
    using T = typename std::decay_t<decltype(row)>::Type;
    std::string path = std::string("/settings/") + row.key;
    std::replace(path.begin(), path.end(), '.', '/');
    if constexpr (std::is_enum_v<T>) {
      c.field(path, a.*row.member, b.*row.member, name(b.*row.member));
    } else {
      c.field(path, a.*row.member, b.*row.member, ojson(b.*row.member));
    }
  });
}

void cameraEdits(const Camera& a, const Camera& b, Collector& c) {
  c.field("/camera/position", a.position, b.position, vec3(b.position));
  c.field("/camera/target", a.target, b.target, vec3(b.target));
  c.field("/camera/up", a.up, b.up, vec3(b.up));
  c.field("/camera/fov_y_deg", a.fov_y_deg, b.fov_y_deg, b.fov_y_deg);
  c.field("/camera/near", a.near_plane, b.near_plane, b.near_plane);
  c.field("/camera/far", a.far_plane, b.far_plane, b.far_plane);
}

}  // namespace

std::string formatNumber(double x) {
  if (!std::isfinite(x)) return "null";  // JSON has no Inf/NaN; the loader rejects null
  char buf[64];
  if (x == std::trunc(x) && std::abs(x) < 1e15) {
    auto r = std::to_chars(buf, buf + sizeof buf, static_cast<long long>(x));
    return std::string(buf, r.ptr);
  }
  const float f = static_cast<float>(x);
  std::to_chars_result r = double(f) == x ? std::to_chars(buf, buf + sizeof buf, f)
                                          : std::to_chars(buf, buf + sizeof buf, x);
  return std::string(buf, r.ptr);
}

std::string formatSceneJson(const ojson& json, int width) {
  return formatValue(json, 0, 0, width, true) + "\n";
}

std::string applyJsonEdits(const std::string& text, const std::vector<JsonEdit>& edits,
                           const std::string& source_name) {
  std::string out = text;
  for (const JsonEdit& e : edits) out = applyOne(out, e, source_name);
  return out;
}

std::vector<JsonEdit> sceneEdits(const std::string& text, const Scene& loaded, const Scene& edited,
                                 bool include_camera, const std::string& source_name) {
  nlohmann::json file;
  try {
    file = nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    throw SceneError(source_name + ": invalid JSON: " + e.what());
  }
  std::vector<JsonEdit> edits;
  Collector c{edits};
  materialEdits(loaded, edited, c);
  lightEdits(file, loaded, edited, c);
  environmentEdits(file, loaded.environment, edited.environment, c);
  settingsEdits(loaded.settings, edited.settings, c);
  if (include_camera) cameraEdits(loaded.camera, edited.camera, c);
  return edits;
}

size_t saveSceneEdits(const std::string& path, const Scene& loaded, const Scene& edited,
                      bool include_camera) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw SceneError(path + ": cannot open file");
  std::ostringstream s;
  s << in.rdbuf();
  const std::string text = s.str();
  const auto edits = sceneEdits(text, loaded, edited, include_camera, path);
  if (edits.empty()) return 0;
  writeFileAtomic(path, applyJsonEdits(text, edits, path));
  return edits.size();
}

}  // namespace hv
