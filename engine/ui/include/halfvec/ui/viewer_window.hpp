// Small pieces of the viewer that need its GLFW window or the GL default framebuffer, kept out of
// the app: window and framebuffer coordinates, the content scale, the window's pixels, what a
// dropped file is, the HDR files the Render panel offers, the part of a scene that "Save scene"
// compares.
#pragma once

#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "halfvec/image/image.hpp"
#include "halfvec/scene/scene.hpp"
#include "halfvec/ui/camera_control.hpp"
#include "halfvec/ui/viewer_input.hpp"

struct GLFWwindow;

namespace hv::ui {

// The window's content scale (the larger of x and y; 1 where the platform has none).
float windowContentScale(GLFWwindow* window);
glm::ivec2 windowSize(GLFWwindow* window);
// Window coordinates -> framebuffer pixels (they differ on high-DPI displays).
glm::vec2 windowToFramebuffer(GLFWwindow* window, glm::dvec2 at, glm::ivec2 framebuffer);

// The fly keys held now (W/S, A/D, E/Q, Shift), from the input's events.
FlyKeys flyKeys(const ViewerInput& input);

// The GLFW key of a name a user can type (a letter, "F12", "Esc"), or -1 (`view --press`).
int keyCode(const std::string& name);

// What a file dropped on the window does: open it as the scene (.json, .gltf, .glb), light the
// scene with it (.hdr), or nothing.
enum class DropKind { Scene, Environment, Unsupported };
DropKind dropKind(const std::string& path);

// *.hdr in ${HV_ASSETS_DIR}/env, sorted (empty without the shared assets).
std::vector<std::string> hdrChoices();

// The fields of `scene` the viewer edits (materials, lights, camera, environment, settings), as
// a Scene without geometry or images: what "Save scene" compares the edited scene with.
Scene editableCopy(const Scene& scene);

// The default framebuffer (the back buffer), row 0 = top, alpha 255.
ImageRGBA8 readWindow(glm::ivec2 framebuffer);
// readWindow written to `path` (its folder created; written whole or not at all).
void writeWindowPng(const std::string& path, glm::ivec2 framebuffer);
// Clears the default framebuffer to `color` (the viewer's frame when no program is usable).
void clearWindow(glm::ivec2 framebuffer, glm::vec3 color);

}  // namespace hv::ui
