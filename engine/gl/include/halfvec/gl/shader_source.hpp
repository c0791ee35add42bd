// GLSL source assembly without any GL call (the build-time validator uses it too):
// resolves #include "file" relative to the including file, inserts the variant's defines right
// after #version, and emits #line directives so a compiler's file:line maps back to the file.
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace hv::gl {

struct Define {
  std::string name;
  std::string value = "1";
  bool operator==(const Define&) const = default;
  bool operator<(const Define& o) const { return name < o.name; }
};
using DefineSet = std::vector<Define>;

// Canonical text of a define set ("A=1;B=0"), sorted by name: the cache key of a variant.
std::string defineKey(DefineSet defines);

// A compile, link or include failure. what() names the original file:line.
class ShaderError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct ExpandedSource {
  std::string text;
  std::vector<std::string> files;  // index = source-string number used in #line
};

// Throws ShaderError for a missing file, a missing #version, or an include cycle/bad directive.
ExpandedSource expandShader(const std::filesystem::path& file, const DefineSet& defines);

// Rewrites compiler diagnostics ("0:12(3): error", "0(12) : error", "ERROR: 0:12:") so each
// location reads "path:line".
std::string mapDiagnostics(const std::string& log, const std::vector<std::string>& files);

// The shader folder: $HV_SHADER_DIR if set, else the source tree's shaders/.
std::filesystem::path shaderRoot();

}  // namespace hv::gl
