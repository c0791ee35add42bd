// Errors and warnings of scene loading (scene files and glTF).
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

namespace hv {

// Thrown by every scene/glTF loader. The message names the file, the element (a JSON pointer
// such as /objects/2/material/roughness, or a glTF element such as meshes[0].primitives[1]) and
// what was expected, e.g.
//   scene.json: /objects/2/material/roughness: expected a number in [0, 1], got 1.5
class SceneError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Reports a non-fatal problem: appended to `sink` when given, else printed to stderr as
// "halfvec: warning: MESSAGE".
void sceneWarning(const std::string& message, std::vector<std::string>* sink = nullptr);

}  // namespace hv
