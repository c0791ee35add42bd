// Opening what a user points at: a scene file (.json) or a glTF model (.gltf / .glb), for which a
// scene is made on the fly (docs/scene-format.md, "Models opened by path"):
//  - camera: the model's bounds (every node's vertices with their world transforms) framed from a
//    three-quarter view (azimuth kFramingAzimuthDeg, elevation kFramingElevationDeg, vertical
//    field of view 45 degrees, 16:9), at the distance where the bounds' projection fills
//    kFramingFill of the frame, centered; near and far from the bounds; or, with
//    SceneOpenOptions::camera, one of the model's own cameras;
//  - environment: the procedural sky (or SceneOpenOptions::environment_hdr);
//  - the default key light (keyLight): a sphere light above and to the left of the camera, unless
//    SceneOpenOptions::key_light is false or the look is Look::Gltf.
// The synthesized scene is plain scene JSON (modelSceneJson), so `--print-scene` prints exactly
// what is rendered and a user can start a scene file from it.
#pragma once

#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "halfvec/scene/scene.hpp"

namespace hv {

inline constexpr float kFramingAzimuthDeg = 25.0f;    // from +Z towards +X
inline constexpr float kFramingElevationDeg = 15.0f;  // above the horizon
inline constexpr float kFramingFovDeg = 45.0f;        // vertical
inline constexpr float kFramingAspect = 16.0f / 9.0f;
inline constexpr float kFramingFill = 0.95f;  // the bounds' projection spans 85% of the frame

// A set of conventions applied to the scene before the overrides (--look).
enum class Look : uint8_t {
  Scene,  // the scene's own settings (a model: the engine's defaults and the key light)
  // The glTF viewers' conventions (Khronos glTF Sample Viewer, three.js): no added light (models:
  // no key light; image-based lighting only), Khronos PBR Neutral tone mapping, the sRGB transfer
  // function, no dither.
  Gltf,
};

struct SceneOpenOptions {
  std::vector<std::string> overrides;  // "json.path=value" (loadScene), applied last
  std::string environment_hdr;  // non-empty: this .hdr replaces the scene's environment (--env)
  int camera = -1;              // >= 0: the model's camera N (models only; --camera)
  bool key_light = true;        // models: add the default key light (--no-key-light: false)
  Look look = Look::Scene;      // --look
};

// The overrides a look stands for, in the order they are applied ("settings.tone_map=..."); the
// key light of Look::Gltf is left out by sceneJsonFor, not by an override.
std::vector<std::string> lookOverrides(Look look);

// True for .gltf and .glb (any case).
bool isModelPath(const std::string& path);

// World-space bounds of every vertex of every object (an empty scene gives min > max).
struct Bounds {
  glm::vec3 min{1e30f}, max{-1e30f};
  bool empty() const { return min.x > max.x; }
  glm::vec3 center() const { return 0.5f * (min + max); }
  float radius() const { return 0.5f * glm::length(max - min); }
};
Bounds sceneBounds(const Scene& scene);

// The camera that frames `bounds` (see the top of this file) from the view direction given by
// azimuth/elevation, with near/far from the bounds. Points in `points` (world space; the model's
// vertices, or the bounds' corners) set the distance and centering: they all project inside
// kFramingFill of the frame at aspect kFramingAspect.
// `fov_y_deg` and `aspect` default to the model scenes' 45 degrees and 16:9 (the viewer's F passes
// the window's).
Camera frameBounds(const std::vector<glm::vec3>& points, const Bounds& bounds,
                   float azimuth_deg = kFramingAzimuthDeg,
                   float elevation_deg = kFramingElevationDeg, float fov_y_deg = kFramingFovDeg,
                   float aspect = kFramingAspect);

// The default key light of a model scene: a sphere light of radius 0.05 * the bounds' radius at
// 2.5 radii from the center (azimuth kFramingAzimuthDeg - 60, elevation 50 degrees: above and
// to the left of the default camera), warm white, with the intensity that gives an irradiance of
// kKeyLightIrradiance at the center (W/m^2 per unit color, the +1 of Karis's falloff included)
// and a range of 4 times its distance (the window leaves 99.6% at the model).
inline constexpr float kKeyLightIrradiance = 3.0f;
Light keyLight(const Bounds& bounds);

// The scene JSON for a model (the format of docs/scene-format.md): the camera, the model as one
// glTF object with its absolute path, the key light, the sky. Loads the model's geometry to
// measure it; throws SceneError for a file that does not load or an out-of-range camera index.
nlohmann::ordered_json modelSceneJson(const std::string& model_path, int camera = -1,
                                      std::vector<std::string>* warnings = nullptr,
                                      bool key_light = true);

// The JSON `openScene` loads for `path`: the scene file's own (or modelSceneJson for a model),
// with options.environment_hdr, the look and then options.overrides applied, in the key order of
// the file (`--print-scene` prints it). Throws SceneError (unreadable file, invalid JSON,
// --camera or --no-key-light with a scene file, an override that cannot be applied).
nlohmann::ordered_json sceneJsonFor(const std::string& path, const SceneOpenOptions& options = {},
                                    std::vector<std::string>* warnings = nullptr);

// Loads a scene file or a model (above) with the options; throws SceneError like loadScene.
Scene openScene(const std::string& path, const SceneOpenOptions& options = {},
                std::vector<std::string>* warnings = nullptr);

}  // namespace hv
