// Programs built from (stage files, define set) and cached by that key. Compile and link errors
// throw ShaderError with the log mapped to file:line; nothing is ever printed and ignored.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "gl/objects.hpp"
#include "gl/shader_source.hpp"

namespace hv::gl {

struct StageFile {
  GLenum stage;      // GL_VERTEX_SHADER, GL_FRAGMENT_SHADER, GL_COMPUTE_SHADER
  std::string path;  // relative to shaderRoot()
};

struct ProgramDesc {
  std::string name;  // debug label and manifest name
  std::vector<StageFile> stages;
  DefineSet defines;
  std::string key() const;  // stages + canonical defines
};

Program buildProgram(const ProgramDesc& desc);

struct VariantInfo {
  std::string name;
  std::string key;
  std::string defines;
  double compile_ms = 0.0;
};

class ProgramCache {
 public:
  // Compiles on first use; throws ShaderError (and caches nothing) on failure.
  GLuint get(const ProgramDesc& desc);
  const std::vector<VariantInfo>& variants() const { return variants_; }
  void clear();
  size_t size() const { return programs_.size(); }

 private:
  std::map<std::string, Program> programs_;
  std::vector<VariantInfo> variants_;
};

}  // namespace hv::gl
