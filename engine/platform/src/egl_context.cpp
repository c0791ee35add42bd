// Headless OpenGL 4.5 core through EGL, no display server. Device platform first so real GPUs are
// used where present; Mesa's surfaceless platform (llvmpipe) as the fallback.
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "halfvec/gl/gl.hpp"
#include "halfvec/gl/timer.hpp"
#include "halfvec/platform/context.hpp"

#ifndef EGL_PLATFORM_SURFACELESS_MESA
#define EGL_PLATFORM_SURFACELESS_MESA 0x31DD
#endif

namespace hv {
namespace {

bool hasExtension(const char* list, const char* ext) {
  if (!list) return false;
  const size_t n = std::strlen(ext);
  for (const char* p = list; (p = std::strstr(p, ext)); p += n) {
    if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
  }
  return false;
}

class EglContext final : public Context {
 public:
  EglContext(EGLDisplay d, EGLContext c, std::string platform)
      : display_(d), context_(c), platform_(std::move(platform)) {}
  ~EglContext() override {
    eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(display_, context_);
    eglTerminate(display_);
  }
  std::string platform() const override { return platform_; }

 private:
  EGLDisplay display_;
  EGLContext context_;
  std::string platform_;
};

// Initializes `display` and makes a core context current; returns nullptr context on failure
// with the reason in `why`.
EGLContext tryCreate(EGLDisplay display, const ContextOptions& o, std::string& why) {
  EGLint major = 0, minor = 0;
  if (display == EGL_NO_DISPLAY || !eglInitialize(display, &major, &minor)) {
    why = "eglInitialize failed";
    return EGL_NO_CONTEXT;
  }
  if (!hasExtension(eglQueryString(display, EGL_EXTENSIONS), "EGL_KHR_surfaceless_context")) {
    why = "no EGL_KHR_surfaceless_context";
    eglTerminate(display);
    return EGL_NO_CONTEXT;
  }
  if (!eglBindAPI(EGL_OPENGL_API)) {
    why = "eglBindAPI(OpenGL) failed";
    eglTerminate(display);
    return EGL_NO_CONTEXT;
  }
  const EGLint config_attribs[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
  EGLConfig config = nullptr;
  EGLint n = 0;
  if (!eglChooseConfig(display, config_attribs, &config, 1, &n) || n < 1) {
    config = nullptr;  // EGL_KHR_no_config_context
  }
  const EGLint ctx_attribs[] = {EGL_CONTEXT_MAJOR_VERSION,
                                o.gl_major,
                                EGL_CONTEXT_MINOR_VERSION,
                                o.gl_minor,
                                EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                EGL_CONTEXT_OPENGL_DEBUG,
                                o.debug ? EGL_TRUE : EGL_FALSE,
                                EGL_NONE};
  EGLContext ctx = eglCreateContext(display, config, EGL_NO_CONTEXT, ctx_attribs);
  if (ctx == EGL_NO_CONTEXT) {
    why = "no OpenGL " + std::to_string(o.gl_major) + "." + std::to_string(o.gl_minor) +
          " core context (eglCreateContext error 0x" +
          [] {
            char b[8];
            std::snprintf(b, sizeof b, "%04X", eglGetError());
            return std::string(b);
          }() +
          ")";
    eglTerminate(display);
    return EGL_NO_CONTEXT;
  }
  if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx)) {
    why = "eglMakeCurrent failed";
    eglDestroyContext(display, ctx);
    eglTerminate(display);
    return EGL_NO_CONTEXT;
  }
  return ctx;
}

}  // namespace

std::unique_ptr<Context> createHeadlessContext(const ContextOptions& options) {
  const char* client_ext = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (!client_ext) {
    throw ContextError(
        "no EGL implementation available (eglQueryString failed; is libEGL and a "
        "vendor library such as Mesa installed?)");
  }
  auto getPlatformDisplay = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
      eglGetProcAddress("eglGetPlatformDisplayEXT"));
  auto queryDevices =
      reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
  const char* forced = std::getenv("HV_EGL_PLATFORM");
  const std::string force = forced ? forced : "";
  std::string reasons;
  std::unique_ptr<Context> result;

  if ((force.empty() || force == "device") && getPlatformDisplay && queryDevices &&
      hasExtension(client_ext, "EGL_EXT_platform_device")) {
    EGLDeviceEXT devices[16];
    EGLint count = 0;
    queryDevices(16, devices, &count);
    for (EGLint i = 0; i < count && !result; ++i) {
      EGLDisplay d = getPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
      std::string why;
      if (EGLContext c = tryCreate(d, options, why); c != EGL_NO_CONTEXT) {
        result = std::make_unique<EglContext>(d, c, "EGL device " + std::to_string(i));
      } else {
        reasons += " device " + std::to_string(i) + ": " + why + ";";
      }
    }
    if (count == 0) reasons += " no EGL devices;";
  }
  if (!result && (force.empty() || force == "surfaceless") && getPlatformDisplay &&
      hasExtension(client_ext, "EGL_MESA_platform_surfaceless")) {
    EGLDisplay d = getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    std::string why;
    if (EGLContext c = tryCreate(d, options, why); c != EGL_NO_CONTEXT) {
      result = std::make_unique<EglContext>(d, c, "EGL surfaceless (Mesa)");
    } else {
      reasons += " surfaceless: " + why + ";";
    }
  }
  if (!result) {
    throw ContextError("cannot create a headless OpenGL " + std::to_string(options.gl_major) + "." +
                       std::to_string(options.gl_minor) + " core context:" +
                       (reasons.empty() ? std::string(" no usable EGL platform") : reasons));
  }
  if (options.debug) gl::installDebugOutput();
  return result;
}

}  // namespace hv
