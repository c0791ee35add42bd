#include "halfvec/scene/scene_loader.hpp"

#include <algorithm>
#include <charconv>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <limits>
#include <optional>

#include "halfvec/core/input_file.hpp"
#include "halfvec/core/suggest.hpp"
#include "halfvec/scene/enums.hpp"
#include "halfvec/scene/gltf_loader.hpp"
#include "halfvec/scene/primitives.hpp"
#include "scene_elements.hpp"

namespace hv {

void sceneWarning(const std::string& message, std::vector<std::string>* sink) {
  if (sink) {
    sink->push_back(message);
  } else {
    std::cerr << "halfvec: warning: " << message << "\n";
  }
}

namespace {

using namespace scene_json;

class SceneBuilder {
  enum class PrimKind { Sphere, Plane, Box, Capsule };
  static constexpr std::string_view kPrimNames[] = {"sphere", "plane", "box", "capsule"};

 public:
  SceneBuilder(const Ctx& ctx, Scene& scene) : ctx_(ctx), scene_(scene) {}

  // The models' KHR_lights_punctual lights: parseScene appends them after the file's lights and
  // generators, so that /lights/i stays scene.lights[i] (the scene writer maps them so).
  std::vector<Light> model_lights;

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

  // The "primitive" of an object, with an error naming the allowed values.
  PrimKind primitiveKind(const json& j, const std::string& ptr) const {
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
    return *kind;
  }

  // The keys an object of that primitive may have.
  static std::vector<std::string_view> primitiveKeys(PrimKind kind) {
    std::vector<std::string_view> keys = {"name", "primitive", "transform", "material"};
    switch (kind) {
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
    return keys;
  }

  // The primitive's mesh, its tessellation checked against the scene's budget first.
  Mesh primitiveMesh(const Obj& o, PrimKind kind) {
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
    switch (kind) {
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
    return mesh;
  }

  // `inherited`: the transform of the gltf object whose fallback this is.
  void parsePrimitiveObject(const json& j, const std::string& ptr,
                            std::optional<glm::mat4> inherited, const std::string& default_name) {
    const PrimKind kind = primitiveKind(j, ptr);
    Obj o(ctx_, j, ptr, primitiveKeys(kind));
    Object obj;
    obj.name = o.string("name", default_name);
    obj.transform = o.has("transform") ? parseTransform(ctx_, o["transform"], o.at("transform"))
                                       : inherited.value_or(glm::mat4(1.0f));
    Mesh mesh = primitiveMesh(o, kind);
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
    opt.lights = &model_lights;  // after the file's own lights (parseScene)
    if (o.has("material_override")) {
      opt.material_override = materialRef(o["material_override"], o.at("material_override"), name);
    }
    try {
      loadGltf(path, transform, scene_, opt);
    } catch (const SceneError& e) {
      ctx_.fail(o.at("gltf"), e.what());
    }
  }

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
    size_t directional = 0;
    for (size_t i = 0; i < ls.size(); ++i) {
      const std::string ptr = "/lights/" + std::to_string(i);
      scene.lights.push_back(parseLight(ctx, ls[i], ptr));
      if (scene.lights.back().type == LightType::Directional &&
          ++directional > kMaxDirectionalLights) {
        ctx.fail(ptr + "/type", "a directional light beyond the scene's " +
                                    std::to_string(kMaxDirectionalLights) +
                                    " (kMaxDirectionalLights: every pixel shades them all)");
      }
    }
  }
  if (top.has("light_generators")) {
    const json& gs = list("light_generators");
    for (size_t i = 0; i < gs.size(); ++i) {
      expandGenerator(ctx, gs[i], "/light_generators/" + std::to_string(i), scene.lights);
    }
  }
  if (scene.lights.size() + builder.model_lights.size() > kMaxSceneLights) {
    top.fail("objects", std::to_string(builder.model_lights.size()) +
                            " lights of glTF models exceed, with the scene's, the budget of " +
                            std::to_string(kMaxSceneLights) + " (kMaxSceneLights)");
  }
  const auto directional = [](const Light& l) { return l.type == LightType::Directional; };
  const size_t directional_count =
      size_t(std::count_if(scene.lights.begin(), scene.lights.end(), directional)) +
      size_t(std::count_if(builder.model_lights.begin(), builder.model_lights.end(), directional));
  if (directional_count > kMaxDirectionalLights) {
    top.fail("objects", std::to_string(directional_count) +
                            " directional lights (the scene's and its glTF models') exceed the " +
                            std::to_string(kMaxDirectionalLights) + " of kMaxDirectionalLights");
  }
  scene.lights.insert(scene.lights.end(), builder.model_lights.begin(), builder.model_lights.end());
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
