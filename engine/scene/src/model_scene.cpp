#include "halfvec/scene/model_scene.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "halfvec/scene/gltf_loader.hpp"
#include "halfvec/scene/scene_error.hpp"
#include "halfvec/scene/scene_loader.hpp"

namespace hv {

namespace {

namespace fs = std::filesystem;
using ojson = nlohmann::ordered_json;

glm::vec3 directionFrom(float azimuth_deg, float elevation_deg) {
  const float az = glm::radians(azimuth_deg), el = glm::radians(elevation_deg);
  return {std::sin(az) * std::cos(el), std::sin(el), std::cos(az) * std::cos(el)};
}

ojson vec3Json(glm::vec3 v) {
  return ojson::array({v.x, v.y, v.z});
}

// The view basis of a camera looking along `forward` with world +Y up.
struct Basis {
  glm::vec3 f, r, u;
  explicit Basis(glm::vec3 forward) : f(glm::normalize(forward)) {
    r = glm::normalize(glm::cross(f, glm::vec3(0, 1, 0)));
    u = glm::cross(r, f);
  }
};

// Smallest distance from `target` along -f at which every point projects inside `fill` of the
// frame (tangents of the half fields of view tan_h, tan_v).
float fitDistance(const std::vector<glm::vec3>& pts, glm::vec3 target, const Basis& b, float tan_h,
                  float tan_v, float fill) {
  float d = 0.0f;
  for (const glm::vec3& x : pts) {
    const glm::vec3 o = x - target;
    const float along = glm::dot(o, b.f);
    d = std::max(d, std::abs(glm::dot(o, b.r)) / (tan_h * fill) - along);
    d = std::max(d, std::abs(glm::dot(o, b.u)) / (tan_v * fill) - along);
  }
  return d;
}

// The model's geometry only (materials and images are not imported) and its cameras.
Scene loadGeometry(const std::string& path, std::vector<GltfCamera>& cameras,
                   std::vector<std::string>* warnings) {
  Scene s;
  s.materials.emplace_back();
  GltfOptions opt;
  opt.material_override = 0;
  opt.warnings = warnings;
  opt.cameras = &cameras;
  loadGltf(path, glm::mat4(1.0f), s, opt);
  return s;
}

Camera modelCamera(const GltfCamera& c, const Bounds& bounds) {
  Camera cam;
  cam.position = glm::vec3(c.world[3]);
  const glm::vec3 forward = -glm::normalize(glm::vec3(c.world[2]));
  glm::vec3 up = glm::normalize(glm::vec3(c.world[1]));
  if (!std::isfinite(up.x) || glm::length(glm::cross(forward, up)) < 1e-4f) up = {0, 1, 0};
  const float r = std::max(bounds.empty() ? 1.0f : bounds.radius(), 1e-6f);
  const float to_center = bounds.empty() ? r : glm::dot(bounds.center() - cam.position, forward);
  cam.target = cam.position + forward * std::max(to_center, r * 1e-2f);
  cam.up = up;
  cam.fov_y_deg = c.perspective ? std::clamp(glm::degrees(c.yfov_rad), 1.0f, 170.0f) : 45.0f;
  cam.near_plane = c.znear;
  cam.far_plane = c.zfar > c.znear ? c.zfar : std::max(c.znear * 1e4f, 4.0f * (to_center + r));
  return cam;
}

// Makes `o` equal to `j`, keeping `o`'s key order (keys only in `j` are appended).
void mergeInOrder(ojson& o, const nlohmann::json& j) {
  if (o.is_object() && j.is_object()) {
    for (auto it = o.begin(); it != o.end();) {
      if (!j.contains(it.key())) {
        it = o.erase(it);
      } else {
        ++it;
      }
    }
    for (auto it = j.begin(); it != j.end(); ++it) {
      if (o.contains(it.key())) {
        mergeInOrder(o[it.key()], it.value());
      } else {
        o[it.key()] = ojson::parse(it.value().dump());
      }
    }
  } else if (o.is_array() && j.is_array() && o.size() == j.size()) {
    for (size_t i = 0; i < j.size(); ++i) mergeInOrder(o[i], j[i]);
  } else {
    o = ojson::parse(j.dump());
  }
}

}  // namespace

bool isModelPath(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  return ext == ".gltf" || ext == ".glb";
}

Bounds sceneBounds(const Scene& scene) {
  Bounds b;
  for (const Object& o : scene.objects) {
    for (int m : o.meshes) {
      for (const Vertex& v : scene.meshes[size_t(m)].vertices) {
        const glm::vec3 p = glm::vec3(o.transform * glm::vec4(v.position, 1.0f));
        b.min = glm::min(b.min, p);
        b.max = glm::max(b.max, p);
      }
    }
  }
  return b;
}

Camera frameBounds(const std::vector<glm::vec3>& points, const Bounds& bounds, float azimuth_deg,
                   float elevation_deg, float fov_y_deg, float aspect) {
  Camera cam;
  cam.fov_y_deg = fov_y_deg;
  const float tan_v = std::tan(glm::radians(fov_y_deg) * 0.5f);
  const float tan_h = tan_v * aspect;
  const Basis b(-directionFrom(azimuth_deg, elevation_deg));
  glm::vec3 target = bounds.center();
  const float r = std::max(bounds.radius(), 1e-6f);
  float d = r;
  // Fit the distance, then center the projection; the projection of an off-center point moves
  // with the distance, so a few rounds converge (each moves the target by a shrinking amount).
  for (int round = 0; round < 6; ++round) {
    d = std::max(fitDistance(points, target, b, tan_h, tan_v, kFramingFill), r * 1e-3f);
    glm::vec2 lo(1e30f), hi(-1e30f);
    for (const glm::vec3& x : points) {
      const glm::vec3 o = x - target;
      const float z = glm::dot(o, b.f) + d;
      const glm::vec2 ndc(glm::dot(o, b.r) / (z * tan_h), glm::dot(o, b.u) / (z * tan_v));
      lo = glm::min(lo, ndc);
      hi = glm::max(hi, ndc);
    }
    const glm::vec2 mid = 0.5f * (lo + hi);
    target += b.r * (mid.x * d * tan_h) + b.u * (mid.y * d * tan_v);
  }
  d = std::max(fitDistance(points, target, b, tan_h, tan_v, kFramingFill), r * 1e-3f);
  cam.target = target;
  cam.position = target - b.f * d;
  cam.up = {0, 1, 0};
  float z_min = 1e30f, z_max = 0.0f;
  for (const glm::vec3& x : points) {
    const float z = glm::dot(x - cam.position, b.f);
    z_min = std::min(z_min, z);
    z_max = std::max(z_max, z);
  }
  // Near: half the distance to the closest point (a little room to move in); far: well past the
  // farthest (the projection is infinite, far only bounds picking and the depth view's scale).
  cam.near_plane = std::max(0.5f * z_min, 1e-4f * d);
  cam.far_plane = std::max(4.0f * z_max, 2.0f * cam.near_plane);
  return cam;
}

Light keyLight(const Bounds& bounds) {
  const float r = std::max(bounds.empty() ? 1.0f : bounds.radius(), 1e-6f);
  const float dist = 2.5f * r;
  Light l;
  l.type = LightType::Sphere;
  l.position = (bounds.empty() ? glm::vec3(0.0f) : bounds.center()) +
               dist * directionFrom(kFramingAzimuthDeg - 60.0f, 50.0f);
  l.color = {1.0f, 0.95f, 0.88f};
  l.radius = 0.05f * r;
  // Irradiance at the center under Karis's falloff 1/(d^2 + 1): I / (d^2 + 1).
  l.intensity = kKeyLightIrradiance * (dist * dist + 1.0f);
  l.range = 4.0f * dist;
  l.shadows = true;  // the model shadows itself (docs/scene-format.md)
  return l;
}

ojson modelSceneJson(const std::string& model_path, int camera, std::vector<std::string>* warnings,
                     bool key_light) {
  const std::string abs = fs::absolute(model_path).lexically_normal().string();
  std::vector<GltfCamera> cameras;
  const Scene geometry = loadGeometry(abs, cameras, warnings);
  Bounds bounds = sceneBounds(geometry);
  std::vector<glm::vec3> points;
  for (const Object& o : geometry.objects) {
    for (int m : o.meshes) {
      for (const Vertex& v : geometry.meshes[size_t(m)].vertices) {
        points.push_back(glm::vec3(o.transform * glm::vec4(v.position, 1.0f)));
      }
    }
  }
  if (bounds.empty()) {
    sceneWarning(model_path + ": no triangles to frame; framing the unit cube", warnings);
    bounds.min = glm::vec3(-0.5f);
    bounds.max = glm::vec3(0.5f);
  }
  if (points.empty()) points = {bounds.min, bounds.max};
  Camera cam;
  if (camera >= 0) {
    if (size_t(camera) >= cameras.size()) {
      throw SceneError(
          model_path + ": --camera " + std::to_string(camera) + ": the model has " +
          std::to_string(cameras.size()) + " camera" + (cameras.size() == 1 ? "" : "s") +
          (cameras.empty() ? "" : " (0 to " + std::to_string(cameras.size() - 1) + ")"));
    }
    cam = modelCamera(cameras[size_t(camera)], bounds);
  } else {
    cam = frameBounds(points, bounds);
  }
  const Light key = keyLight(bounds);
  const std::string stem = fs::path(model_path).stem().string();

  ojson j;
  j["description"] =
      "Made by halfvec for " + fs::path(model_path).filename().string() +
      (camera >= 0 ? ": the model's camera " + std::to_string(camera)
                   : ": the bounds framed from a three-quarter view") +
      (key_light ? ", the default key light (a sphere light above left of the camera)"
                 : ", no light of its own") +
      ", the procedural sky (docs/scene-format.md, \"Models opened by path\").";
  ojson c;
  c["position"] = vec3Json(cam.position);
  c["target"] = vec3Json(cam.target);
  c["up"] = vec3Json(cam.up);
  c["fov_y_deg"] = cam.fov_y_deg;
  c["near"] = cam.near_plane;
  c["far"] = cam.far_plane;
  j["camera"] = c;
  j["objects"] = ojson::array({ojson{{"name", stem}, {"gltf", abs}}});
  j["lights"] = ojson::array();
  if (key_light) {
    j["lights"].push_back(ojson{{"type", "sphere"},
                                {"position", vec3Json(key.position)},
                                {"color", vec3Json(key.color)},
                                {"intensity", key.intensity},
                                {"radius", key.radius},
                                {"range", key.range},
                                {"shadows", key.shadows}});
  }
  j["environment"] = ojson{{"type", "sky"}};
  return j;
}

std::vector<std::string> lookOverrides(Look look) {
  switch (look) {
    case Look::Gltf:
      return {"settings.tone_map=\"pbr_neutral\"", "settings.gamma=\"srgb\"",
              "settings.dither=false"};
    default:
      return {};
  }
}

ojson sceneJsonFor(const std::string& path, const SceneOpenOptions& options,
                   std::vector<std::string>* warnings) {
  ojson j;
  if (isModelPath(path)) {
    j = modelSceneJson(path, options.camera, warnings,
                       options.key_light && options.look != Look::Gltf);
  } else {
    if (options.camera >= 0) {
      throw SceneError(path +
                       ": --camera selects a glTF model's camera; a scene file has one "
                       "camera (edit its \"camera\")");
    }
    if (!options.key_light) {
      throw SceneError(path +
                       ": --no-key-light drops the light added to a glTF model; a scene file's "
                       "lights are its own (edit its \"lights\")");
    }
    // The same checks as loadScene: a regular file within kMaxSceneFileBytes, nesting bounded,
    // parse errors with file, line and column.
    const std::string text = readSceneFile(path);
    const bool gltf_like = !text.empty() && (text.rfind("glTF", 0) == 0 ||
                                             text.find("\"asset\"") != std::string::npos);
    const std::string hint = gltf_like ? " (a glTF model? name it .gltf or .glb)" : "";
    try {
      checkSceneJsonText(text, path);
      j = ojson::parse(text);
    } catch (const SceneError& e) {
      throw SceneError(e.what() + hint);
    } catch (const ojson::exception& e) {
      try {
        throwSceneJsonError(e, text, path);
      } catch (const SceneError& named) {
        throw SceneError(named.what() + hint);
      }
    }
  }
  if (!options.environment_hdr.empty()) {
    const std::string hdr = fs::absolute(options.environment_hdr).lexically_normal().string();
    if (!fs::is_regular_file(hdr))
      throw SceneError(options.environment_hdr + ": file not found (--env)");
    if (!j.is_object()) throw SceneError(path + ": expected a JSON object");
    ojson env = j.contains("environment") && j["environment"].is_object() ? j["environment"]
                                                                          : ojson::object();
    env.erase("color");
    env["type"] = "hdr";
    env["path"] = hdr;
    j["environment"] = env;
  }
  std::vector<std::string> overrides = lookOverrides(options.look);
  overrides.insert(overrides.end(), options.overrides.begin(), options.overrides.end());
  if (!overrides.empty()) {
    // applyOverride edits plain (key-sorted) JSON; the result is merged back into the file's
    // order, new keys after the existing ones.
    nlohmann::json plain = nlohmann::json::parse(j.dump());
    for (const std::string& o : overrides) applyOverride(plain, o, path);
    mergeInOrder(j, plain);
  }
  return j;
}

Scene openScene(const std::string& path, const SceneOpenOptions& options,
                std::vector<std::string>* warnings) {
  const ojson ordered = sceneJsonFor(path, options, warnings);
  return parseScene(nlohmann::json::parse(ordered.dump()), path, warnings);
}

}  // namespace hv
