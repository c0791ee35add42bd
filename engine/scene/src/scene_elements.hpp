// The scene file's elements (camera, material, transform, light, light generator, environment,
// settings), each read from its JSON object with errors naming the field. Private to the scene
// module.
#pragma once

#include <string>
#include <vector>

#include "halfvec/scene/scene.hpp"
#include "scene_json.hpp"

namespace hv::scene_json {

Camera parseCamera(const Ctx& ctx, const json& j);
Material parseMaterial(const Ctx& ctx, const json& j, const std::string& ptr, bool allow_name);
glm::mat4 parseTransform(const Ctx& ctx, const json& j, const std::string& ptr);
Light parseLight(const Ctx& ctx, const json& j, const std::string& ptr);
// Appends the lights of a "generate" object (halfvec/scene/light_generator.hpp).
void expandGenerator(const Ctx& ctx, const json& j, const std::string& ptr,
                     std::vector<Light>& out);
Environment parseEnvironment(const Ctx& ctx, const json& j,
                             const std::string& ptr = "/environment");
RenderSettings parseSettings(const Ctx& ctx, const json& j);

}  // namespace hv::scene_json
