// Writing scene files the way a person writes them: numbers as they could have been typed
// (the shortest text that reads back to the same float), vectors and small objects on one line,
// and, when a scene the user edited is saved, only what changed, with the rest of the file kept
// byte for byte (docs/scene-format.md, "Saving").
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "halfvec/scene/scene.hpp"

namespace hv {

// The shortest decimal text that reads back as the same float when the value is a float
// (0.7f -> "0.7", not 0.699999988079071), else the shortest text of the double; integral
// values without a fraction ("2", not "2.0").
std::string formatNumber(double value);

// JSON text in the style of the sample scenes: the top-level object one key per line; any value
// whose one-line form fits in `width` columns at its indentation on one line ({"a": 1, "b": [0,
// 1, 2]}); larger objects and lists one member per line, indented by two spaces; lists of
// numbers always on one line. Ends with a newline.
std::string formatSceneJson(const nlohmann::ordered_json& json, int width = 100);

// One change to a JSON document: set the value at `pointer` (an RFC 6901 JSON pointer such as
// /materials/gold/roughness; the parent must exist, a missing last key is added) or, when
// `erase` is set, remove it.
struct JsonEdit {
  std::string pointer;
  nlohmann::ordered_json value;
  bool erase = false;
};

// Applies `edits` to the JSON text `text` in place: each edited value's text is replaced by the
// formatted new value (a new key is inserted after the object's last member, on its own line
// when the object spans several lines), and every other byte of the file stays as it was
// (comments are not JSON and are not expected). Throws SceneError naming `source_name` when the
// text is not valid JSON or a pointer's parent does not exist.
std::string applyJsonEdits(const std::string& text, const std::vector<JsonEdit>& edits,
                           const std::string& source_name);

// The edits that turn the scene file `text` (as loaded into `loaded`) into one that loads as
// `edited`: changed material fields (named and inline materials; glTF materials are not in the
// scene file and are skipped), changed, added or removed lights (the explicit "lights" list; a
// changed count rewrites the list, one light per line), environment, settings and, when
// `include_camera`, the camera. Fields equal to what was loaded are not touched, so a file saved
// without edits is unchanged.
std::vector<JsonEdit> sceneEdits(const std::string& text, const Scene& loaded, const Scene& edited,
                                 bool include_camera, const std::string& source_name);

// sceneEdits + applyJsonEdits, written with writeFileAtomic. Returns the number of edits.
// Throws SceneError (bad JSON) or OutputError (cannot write).
size_t saveSceneEdits(const std::string& path, const Scene& loaded, const Scene& edited,
                      bool include_camera = false);

}  // namespace hv
