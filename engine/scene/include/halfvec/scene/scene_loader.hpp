// Scene files: JSON -> hv::Scene. The format is documented field by field in
// docs/scene-format.md; samples/scenes/ holds examples.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "halfvec/scene/scene.hpp"
#include "halfvec/scene/scene_error.hpp"

namespace hv {

// Budgets of one scene file (docs/scene-format.md): a few KB of JSON must not ask for gigabytes.
// Lights, explicit and generated (a Light is 64 bytes; the GPU holds each once or twice).
constexpr size_t kMaxSceneLights = size_t(1) << 20;
// Vertices of all analytic primitives together: 4,194,304 (a 2048 x 2046 sphere) take 224 MiB
// plus 96 MiB of indices. 16 Mi (1.3 GiB in all) let a 70-byte file take 19 s of CPU to load
// under the sanitizers.
constexpr size_t kMaxPrimitiveVertices = size_t(1) << 22;
// Size of a scene file.
constexpr size_t kMaxSceneFileBytes = size_t(64) << 20;
// JSON nesting of a scene file, as GltfLimits::max_json_depth for glTF: the deepest valid scene
// nests 5 levels ({"objects": [{"transform": {"matrix": [...]}}]}); nlohmann's printer and the
// checks recurse per level, and 50,000 levels overflowed the stack.
constexpr int kMaxSceneJsonDepth = 64;

// Reads a scene file: a regular file (symlinks followed; a directory, FIFO or device is an error
// saying what it is) of at most kMaxSceneFileBytes, reading no further. Throws SceneError.
std::string readSceneFile(const std::string& path);

// Checks scene JSON text before it is parsed (a NUL byte, nesting beyond kMaxSceneJsonDepth) and
// turns a parser exception into a SceneError "FILE: line L, column C: invalid JSON: ...", the
// position of a number beyond double range (1e400) included. For every reader of scene text.
void checkSceneJsonText(std::string_view text, const std::string& source_name);
[[noreturn]] void throwSceneJsonError(const nlohmann::json::exception& e, std::string_view text,
                                      const std::string& source_name);

// Loads the scene file at `path`. `overrides` are "json.path=value" strings applied to the JSON
// before validation, e.g. "settings.width=640", "lights.0.intensity=5",
// "camera.position=[0,1,4]", "environment.type=uniform": the path is split at '.', numeric
// components index arrays, missing object keys are created; the value is parsed as JSON and
// taken as a plain string when that fails. Relative glTF/HDR paths resolve against the scene
// file's folder; "${VAR}" in paths expands environment variables (an unset one is an error,
// except in a glTF object's path when the object has a "fallback"). Returns a complete Scene or
// throws SceneError; warnings (a missing glTF replaced by its fallback, BLEND materials) go to
// stderr, or to `warnings` when given.
Scene loadScene(const std::string& path, const std::vector<std::string>& overrides = {},
                std::vector<std::string>* warnings = nullptr);

// The same from the file's text; `source_name` names it in messages and is the base of relative
// paths. For fuzzers and tests: it lets an exception other than SceneError through (a check the
// loader misses), where loadScene turns it into a SceneError naming the file.
Scene loadSceneFromString(std::string_view text, const std::string& source_name,
                          const std::vector<std::string>& overrides = {},
                          std::vector<std::string>* warnings = nullptr);

// Validates and converts already-parsed JSON. `source_name` is used in error messages and as the
// base for relative paths (its parent folder).
Scene parseScene(const nlohmann::json& json, const std::string& source_name,
                 std::vector<std::string>* warnings = nullptr);

// Applies one "json.path=value" override (see loadScene) to `json`; throws SceneError naming
// `source_name` and the override on a path that cannot be followed.
void applyOverride(nlohmann::json& json, const std::string& override_text,
                   const std::string& source_name);

// Expands "${VAR}" using the environment; throws SceneError for an unset variable.
std::string expandEnvVars(const std::string& text);

}  // namespace hv
