// Programs built from (stage files, define set) and cached by that key. Compile and link errors
// throw ShaderError with the log mapped to file:line; nothing is ever printed and ignored.
// The cache also keeps, on disk, the driver's program binaries (GL_ARB_get_program_binary) when
// the driver offers a binary format: a variant compiled in an earlier run is loaded, not compiled.
// A binary cache file is keyed by the expanded source text, the defines and the driver's
// GL_VENDOR/GL_RENDERER/GL_VERSION; a corrupt, stale or rejected file is ignored with a log line.
#pragma once

#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "halfvec/gl/objects.hpp"
#include "halfvec/gl/shader_source.hpp"

namespace hv::gl {

struct StageFile {
  GLenum stage;      // GL_VERTEX_SHADER, GL_FRAGMENT_SHADER, GL_COMPUTE_SHADER
  std::string path;  // relative to shaderRoot()
};

struct ProgramDesc {
  std::string name;  // debug label and manifest name
  std::vector<StageFile> stages;
  DefineSet defines;
  // Why each define has its value ("NAME" -> reason), for the manifest; optional.
  std::map<std::string, std::string> reasons = {};
  std::string key() const;  // stages + canonical defines
};

struct BuildTimings {
  double compile_ms = 0.0;  // all stages: glCompileShader until the status is known
  double link_ms = 0.0;     // glLinkProgram until the status is known
};

// Compiles and links. With `retrievable`, asks the driver to keep the binary
// (GL_PROGRAM_BINARY_RETRIEVABLE_HINT) so glGetProgramBinary can save it.
Program buildProgram(const ProgramDesc& desc, BuildTimings* timings = nullptr,
                     bool retrievable = false);

struct VariantInfo {
  std::string name;
  std::string key;
  std::string defines;  // canonical "A=1;B=0"
  std::vector<std::string> stages;
  std::vector<std::string> reasons;  // "NAME=VALUE: why", in define order
  double compile_ms = 0.0;           // 0 when loaded from the binary cache
  double link_ms = 0.0;
  double cache_load_ms = 0.0;  // glProgramBinary (binary-cache hit)
  bool from_binary_cache = false;
  bool binary_saved = false;  // written to the binary cache this run
  uint64_t last_frame = 0;    // the frame (ProgramCache::beginFrame count) it was last used in
  uint64_t reasons_generation = 0;  // the setDefineReasons call the reasons were written after
};

// Where the binary cache lives: $HV_CACHE_DIR, else $XDG_CACHE_HOME/halfvec, else
// ~/.cache/halfvec (like the IBL bake cache), plus "/programs".
std::filesystem::path defaultProgramCacheDir();

class ProgramCache {
 public:
  // Compiles on first use (or loads the binary); throws ShaderError (and caches nothing) on
  // failure.
  GLuint get(const ProgramDesc& desc);
  const std::vector<VariantInfo>& variants() const { return variants_; }
  void clear();
  // Rebuilds every cached program from its files as they are now (shader hot reload). All or
  // nothing: if any fails to compile or link, throws its ShaderError and every program stays the
  // last good one, still usable.
  void reloadAll();
  size_t size() const { return programs_.size(); }

  // Default reasons for defines of programs whose desc gives none: NAME -> (VALUE, why); used
  // when the program's value matches. Replaces the previous table; a cached program's reasons
  // are rewritten (from its desc and this table) the next time it is used.
  void setDefineReasons(std::map<std::string, std::pair<std::string, std::string>> reasons) {
    define_reasons_ = std::move(reasons);
    ++reasons_generation_;
  }

  // Starts a frame: variants() entries whose last_frame equals frame() were used in it.
  void beginFrame() { ++frame_; }
  uint64_t frame() const { return frame_; }

  // Turns the on-disk binary cache on (in `dir`) or off (empty path). Needs a current context:
  // queries GL_NUM_PROGRAM_BINARY_FORMATS; with 0 formats the cache stays off and
  // binaryCacheStatus() says "unsupported by driver".
  void setBinaryCacheDir(const std::filesystem::path& dir);
  bool binaryCacheEnabled() const { return binary_supported_ && !binary_dir_.empty(); }
  // "off", "unsupported by driver (GL_NUM_PROGRAM_BINARY_FORMATS = 0)" or "DIR (N formats)".
  std::string binaryCacheStatus() const;
  size_t binaryHits() const { return hits_; }
  size_t binaryMisses() const { return misses_; }
  // The cache file a program with these stages and defines would use (empty when off).
  std::filesystem::path binaryCachePath(const ProgramDesc& desc) const;

 private:
  std::map<std::string, std::pair<Program, size_t>> programs_;  // key -> program, variants_ index
  std::vector<VariantInfo> variants_;
  std::map<std::string, ProgramDesc> descs_;  // key -> what built it (for reloadAll)
  uint64_t frame_ = 0;
  std::filesystem::path binary_dir_;
  bool binary_supported_ = false;
  bool binary_queried_ = false;
  int binary_formats_ = 0;
  std::string driver_;  // GL_VENDOR|GL_RENDERER|GL_VERSION
  size_t hits_ = 0, misses_ = 0;
  std::map<std::string, std::pair<std::string, std::string>> define_reasons_;
  uint64_t reasons_generation_ = 0;
  std::vector<std::string> reasonsFor(const ProgramDesc& desc) const;
};

}  // namespace hv::gl
