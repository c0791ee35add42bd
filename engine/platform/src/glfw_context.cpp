// A GLFW 3.3 window with an OpenGL 4.5 core context; the renderer draws into framebuffer 0.
#include <GLFW/glfw3.h>

#include <string>

#include "halfvec/gl/timer.hpp"
#include "halfvec/platform/context.hpp"

namespace hv {
namespace {

std::string g_glfw_error;
void onGlfwError(int code, const char* text) {
  g_glfw_error = std::string(text) + " (GLFW error 0x" + std::to_string(code) + ")";
}

class GlfwContext final : public Context {
 public:
  explicit GlfwContext(GLFWwindow* w) : window_(w) {}
  ~GlfwContext() override {
    glfwDestroyWindow(window_);
    glfwTerminate();
  }
  std::string platform() const override { return "GLFW window"; }
  void swapBuffers() override { glfwSwapBuffers(window_); }
  void pollEvents() override { glfwPollEvents(); }
  bool shouldClose() const override { return glfwWindowShouldClose(window_); }
  glm::ivec2 framebufferSize() const override {
    int w = 0, h = 0;
    glfwGetFramebufferSize(window_, &w, &h);
    return {w, h};
  }
  GLFWwindow* window() const override { return window_; }

 private:
  GLFWwindow* window_;
};

}  // namespace

std::unique_ptr<Context> createWindowContext(int width, int height, const std::string& title,
                                             const ContextOptions& options) {
  glfwSetErrorCallback(onGlfwError);
  if (!glfwInit()) {
    throw ContextError("cannot open a window: " +
                       (g_glfw_error.empty() ? std::string("glfwInit failed") : g_glfw_error));
  }
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, options.gl_major);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, options.gl_minor);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, options.debug ? GLFW_TRUE : GLFW_FALSE);
  GLFWwindow* w = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
  if (!w) {
    std::string why = g_glfw_error;
    glfwTerminate();
    throw ContextError("cannot open a window with an OpenGL " + std::to_string(options.gl_major) +
                       "." + std::to_string(options.gl_minor) + " core context: " + why);
  }
  glfwMakeContextCurrent(w);
  glfwSwapInterval(1);
  auto ctx = std::make_unique<GlfwContext>(w);
  if (options.debug) gl::installDebugOutput();
  return ctx;
}

}  // namespace hv
