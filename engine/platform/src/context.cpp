#include "halfvec/platform/context.hpp"

#include "halfvec/gl/gl.hpp"

namespace hv {

std::string Context::renderer() const {
  const auto* s = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  return s ? s : "unknown";
}

std::string Context::version() const {
  const auto* s = reinterpret_cast<const char*>(glGetString(GL_VERSION));
  return s ? s : "unknown";
}

}  // namespace hv
