// GL contexts behind one interface: the renderer never knows whether it runs headless (EGL) or in
// a window (GLFW). Creation failures throw ContextError with one clear line.
#pragma once

#include <memory>
#include <stdexcept>
#include <string>

#include <glm/glm.hpp>

struct GLFWwindow;

namespace hv {

class ContextError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct ContextOptions {
  int gl_major = 4;
  int gl_minor = 5;
  bool debug = true;  // KHR_debug output routed to the log
};

class Context {
 public:
  virtual ~Context() = default;
  // "EGL device", "EGL surfaceless (Mesa)", "GLFW window".
  virtual std::string platform() const = 0;
  // GL_RENDERER / GL_VERSION of the current context.
  std::string renderer() const;
  std::string version() const;
  // Window contexts only; headless ones report closed=false and do nothing.
  virtual void swapBuffers() {}
  virtual void pollEvents() {}
  virtual bool shouldClose() const { return false; }
  virtual glm::ivec2 framebufferSize() const { return {0, 0}; }
  virtual GLFWwindow* window() const { return nullptr; }
};

// Tries EGL_EXT_platform_device (real GPUs) first, then EGL_MESA_platform_surfaceless.
// HV_EGL_PLATFORM=device|surfaceless forces one.
std::unique_ptr<Context> createHeadlessContext(const ContextOptions& options = {});

// GLFW 3.3 window with the same GL version.
std::unique_ptr<Context> createWindowContext(int width, int height, const std::string& title,
                                             const ContextOptions& options = {});

}  // namespace hv
