#include "halfvec/gl/timer.hpp"

#include <cstring>
#include <functional>
#include <utility>

#include "halfvec/gl/log.hpp"

namespace hv::gl {

Query PassTimer::take() {
  if (!pool_.empty()) {
    Query q = std::move(pool_.back());
    pool_.pop_back();
    return q;
  }
  return createQuery("pass timestamp", GL_TIMESTAMP);
}

void PassTimer::begin(const std::string& pass) {
  Entry e{pass, take(), Query{}};
  glQueryCounter(e.start.id(), GL_TIMESTAMP);
  entries_.push_back(std::move(e));
}

void PassTimer::end() {
  if (finish_each_pass_) glFinish();
  for (auto it = entries_.rbegin(); it != entries_.rend(); ++it) {
    if (!it->stop) {
      it->stop = take();
      glQueryCounter(it->stop.id(), GL_TIMESTAMP);
      return;
    }
  }
}

std::vector<std::pair<std::string, double>> PassTimer::resolve() {
  std::vector<std::pair<std::string, double>> out;
  for (auto& e : entries_) {
    GLuint64 t0 = 0, t1 = 0;
    glGetQueryObjectui64v(e.start.id(), GL_QUERY_RESULT, &t0);
    if (e.stop) glGetQueryObjectui64v(e.stop.id(), GL_QUERY_RESULT, &t1);
    out.emplace_back(e.name, e.stop ? double(t1 - t0) * 1e-6 : 0.0);
    pool_.push_back(std::move(e.start));
    if (e.stop) pool_.push_back(std::move(e.stop));
  }
  entries_.clear();
  return out;
}

ScopedPass::ScopedPass(PassTimer& timer, const std::string& name) : timer_(timer) {
  glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0, -1, name.c_str());
  timer_.begin(name);
}

ScopedPass::~ScopedPass() {
  timer_.end();
  glPopDebugGroup();
}

namespace {
std::function<void(const std::string&)>& errorHandler() {
  static std::function<void(const std::string&)> handler;
  return handler;
}

void APIENTRY debugCallback(GLenum source, GLenum type, GLuint id, GLenum severity, GLsizei length,
                            const GLchar* message, const void*) {
  if (type == GL_DEBUG_TYPE_PUSH_GROUP || type == GL_DEBUG_TYPE_POP_GROUP) return;
  std::string text = "GL: " + std::string(message, length < 0 ? strlen(message) : size_t(length)) +
                     " (id " + std::to_string(id) + ")";
  // Compiler/linker messages repeat what ShaderError already carries: keep them at debug level.
  if (source == GL_DEBUG_SOURCE_SHADER_COMPILER) severity = GL_DEBUG_SEVERITY_NOTIFICATION;
  if (type == GL_DEBUG_TYPE_ERROR && source != GL_DEBUG_SOURCE_SHADER_COMPILER && errorHandler()) {
    errorHandler()(text);
  }
  switch (severity) {
    case GL_DEBUG_SEVERITY_HIGH:
      log::error(text);
      break;
    case GL_DEBUG_SEVERITY_MEDIUM:
      log::warn(text);
      break;
    case GL_DEBUG_SEVERITY_LOW:
      log::info(text);
      break;
    default:
      log::debug(text);
      break;
  }
}
}  // namespace

void setDebugErrorHandler(std::function<void(const std::string&)> handler) {
  errorHandler() = std::move(handler);
}

void installDebugOutput() {
  glEnable(GL_DEBUG_OUTPUT);
  glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
  glDebugMessageCallback(debugCallback, nullptr);
  glDebugMessageControl(GL_DONT_CARE, GL_DONT_CARE, GL_DONT_CARE, 0, nullptr, GL_TRUE);
}

}  // namespace hv::gl
