#include "gl/program.hpp"

#include <chrono>

namespace hv::gl {

std::string ProgramDesc::key() const {
  std::string k;
  for (const auto& s : stages) k += s.path + "|";
  return k + defineKey(defines);
}

namespace {
const char* stageName(GLenum s) {
  switch (s) {
    case GL_VERTEX_SHADER:
      return "vertex";
    case GL_FRAGMENT_SHADER:
      return "fragment";
    case GL_COMPUTE_SHADER:
      return "compute";
    default:
      return "shader";
  }
}

std::string infoLog(GLuint obj, bool program) {
  GLint len = 0;
  program ? glGetProgramiv(obj, GL_INFO_LOG_LENGTH, &len)
          : glGetShaderiv(obj, GL_INFO_LOG_LENGTH, &len);
  std::string log(static_cast<size_t>(std::max(len, 1)), '\0');
  program ? glGetProgramInfoLog(obj, len, nullptr, log.data())
          : glGetShaderInfoLog(obj, len, nullptr, log.data());
  while (!log.empty() && (log.back() == '\0' || log.back() == '\n')) log.pop_back();
  return log;
}
}  // namespace

Program buildProgram(const ProgramDesc& desc) {
  std::vector<Shader> shaders;
  for (const auto& st : desc.stages) {
    const auto src = expandShader(shaderRoot() / st.path, desc.defines);
    Shader sh(glCreateShader(st.stage), desc.name + " " + stageName(st.stage));
    const char* text = src.text.c_str();
    glShaderSource(sh.id(), 1, &text, nullptr);
    glCompileShader(sh.id());
    GLint ok = GL_FALSE;
    glGetShaderiv(sh.id(), GL_COMPILE_STATUS, &ok);
    if (!ok) {
      throw ShaderError(std::string(stageName(st.stage)) + " shader of program '" + desc.name +
                        "' failed to compile [" + defineKey(desc.defines) + "]:\n" +
                        mapDiagnostics(infoLog(sh.id(), false), src.files));
    }
    shaders.push_back(std::move(sh));
  }
  Program prog(glCreateProgram(), desc.name);
  for (const auto& sh : shaders) glAttachShader(prog.id(), sh.id());
  glLinkProgram(prog.id());
  GLint ok = GL_FALSE;
  glGetProgramiv(prog.id(), GL_LINK_STATUS, &ok);
  for (const auto& sh : shaders) glDetachShader(prog.id(), sh.id());
  if (!ok) {
    throw ShaderError("program '" + desc.name + "' failed to link:\n" + infoLog(prog.id(), true));
  }
  return prog;
}

GLuint ProgramCache::get(const ProgramDesc& desc) {
  const std::string key = desc.key();
  if (auto it = programs_.find(key); it != programs_.end()) return it->second.id();
  const auto t0 = std::chrono::steady_clock::now();
  Program p = buildProgram(desc);
  const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  const GLuint id = p.id();
  programs_.emplace(key, std::move(p));
  variants_.push_back({desc.name, key, defineKey(desc.defines), ms});
  return id;
}

void ProgramCache::clear() {
  programs_.clear();
  variants_.clear();
}

}  // namespace hv::gl
