// Dear ImGui on a GLFW window: context + GLFW and OpenGL3 backends. Kept in its own translation
// unit because the OpenGL3 backend brings its own GL loader (never mixed with gl/gl.hpp).
#pragma once

struct GLFWwindow;

namespace hv::ui {

class ImGuiLayer {
 public:
  // Installs the GLFW callbacks (chaining to ones already set) and creates the GL3 renderer.
  explicit ImGuiLayer(GLFWwindow* window);
  ~ImGuiLayer();
  ImGuiLayer(const ImGuiLayer&) = delete;
  ImGuiLayer& operator=(const ImGuiLayer&) = delete;

  void beginFrame();
  // Draws the frame's UI into the currently bound framebuffer (0 for the window).
  void endFrame();
  // ImGui owns the mouse / keyboard (a widget is hovered or focused).
  bool wantsMouse() const;
  bool wantsKeyboard() const;
};

}  // namespace hv::ui
