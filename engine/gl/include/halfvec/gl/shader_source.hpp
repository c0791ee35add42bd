// GLSL source assembly without any GL call (the build-time validator uses it too):
// resolves #include "file" relative to the including file, inserts the variant's defines right
// after #version, and emits #line directives so a compiler's file:line maps back to the file.
#pragma once

#include <filesystem>
#include <optional>
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

// Where the engine's shaders are read from (program paths are relative to it), first match:
//  1. the folder in the environment variable HV_SHADER_DIR (the user's override);
//  2. the folder given to setShaderDir (applications: e.g. an installed share/halfvec/shaders,
//     for editing shaders and reloading them at run time);
//  3. the copy of shaders/ compiled into the library at build time: embeddedShaderRoot(), a
//     virtual folder no file system holds (so a program linking the library needs no files).
std::filesystem::path shaderRoot();
// Sets (or, with an empty path, clears) the shader folder of rule 2. Throws ShaderError naming
// the folder when it does not hold passes/ and common/.
void setShaderDir(const std::filesystem::path& dir);
// The virtual folder of the embedded shaders; diagnostics name files under it
// ("[embedded]/shaders/passes/light_shade.comp:12").
const std::filesystem::path& embeddedShaderRoot();
// The text of a shader file: from the embedded copy for paths under embeddedShaderRoot(), else
// from disk. nullopt when there is no such file.
std::optional<std::string> readShaderFile(const std::filesystem::path& path);

}  // namespace hv::gl
