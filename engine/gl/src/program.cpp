#include "halfvec/gl/program.hpp"

#include <sched.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <optional>
#include <sstream>

#include "halfvec/core/output_files.hpp"
#include "halfvec/gl/log.hpp"

namespace hv::gl {

namespace fs = std::filesystem;

std::string ProgramDesc::key() const {
  std::string k;
  for (const auto& s : stages) k += s.path + "|";
  return k + defineKey(defines);
}

namespace {
using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

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

std::vector<ExpandedSource> expandAll(const ProgramDesc& desc) {
  std::vector<ExpandedSource> out;
  for (const auto& st : desc.stages)
    out.push_back(expandShader(shaderRoot() / st.path, desc.defines));
  return out;
}

Program buildFromSources(const ProgramDesc& desc, const std::vector<ExpandedSource>& sources,
                         BuildTimings* timings, bool retrievable) {
  const auto t_compile = Clock::now();
  std::vector<Shader> shaders;
  for (size_t i = 0; i < desc.stages.size(); ++i) {
    const StageFile& st = desc.stages[i];
    const ExpandedSource& src = sources[i];
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
  if (timings) timings->compile_ms = msSince(t_compile);
  const auto t_link = Clock::now();
  Program prog(glCreateProgram(), desc.name);
  if (retrievable) glProgramParameteri(prog.id(), GL_PROGRAM_BINARY_RETRIEVABLE_HINT, GL_TRUE);
  for (const auto& sh : shaders) glAttachShader(prog.id(), sh.id());
  glLinkProgram(prog.id());
  GLint ok = GL_FALSE;
  glGetProgramiv(prog.id(), GL_LINK_STATUS, &ok);
  for (const auto& sh : shaders) glDetachShader(prog.id(), sh.id());
  if (!ok) {
    throw ShaderError("program '" + desc.name + "' failed to link:\n" + infoLog(prog.id(), true));
  }
  if (timings) timings->link_ms = msSince(t_link);
  return prog;
}

// ---- binary cache file ----
// magic, version, key hash (2 x 64 bit), binary format, length, binary, FNV-1a of the binary.
constexpr char kMagic[8] = {'H', 'V', 'P', 'R', 'O', 'G', 'B', '\n'};
constexpr uint32_t kVersion = 1;

// FNV-1a 64 (Fowler/Noll/Vo); the second hash uses another offset basis so a file name
// collision is not mistaken for a match.
uint64_t fnv1a(const void* data, size_t n, uint64_t h = 1469598103934665603ull) {
  const auto* p = static_cast<const unsigned char*>(data);
  for (size_t i = 0; i < n; ++i) {
    h ^= p[i];
    h *= 1099511628211ull;
  }
  return h;
}
uint64_t fnv1a(const std::string& s, uint64_t basis = 1469598103934665603ull) {
  return fnv1a(s.data(), s.size(), basis);
}
constexpr uint64_t kSecondBasis = 0x84222325cbf29ce4ull;

struct BinaryKey {
  uint64_t a = 0, b = 0;
};

BinaryKey binaryKey(const std::string& driver, const ProgramDesc& desc,
                    const std::vector<ExpandedSource>& sources) {
  std::string text = "halfvec program binary v" + std::to_string(kVersion) + "\n" + driver + "\n" +
                     defineKey(desc.defines) + "\n";
  for (size_t i = 0; i < desc.stages.size(); ++i) {
    text += std::to_string(desc.stages[i].stage) + " " + desc.stages[i].path + "\n";
    text += sources[i].text;
    text += "\n";
  }
  return {fnv1a(text), fnv1a(text, kSecondBasis)};
}

fs::path cacheFile(const fs::path& dir, const BinaryKey& k) {
  char name[40];
  std::snprintf(name, sizeof name, "prog-%016llx.bin", static_cast<unsigned long long>(k.a));
  return dir / name;
}

struct BinaryBlob {
  GLenum format = 0;
  std::vector<char> data;
};

// Reads a cache file; returns false (and says why in `why`) when it is missing, corrupt or for
// another key.
bool readBinary(const fs::path& path, const BinaryKey& key, BinaryBlob& blob, std::string& why) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    why = "missing";
    return false;
  }
  char magic[8];
  uint32_t version = 0, format = 0, len = 0;
  uint64_t ka = 0, kb = 0, sum = 0;
  if (!in.read(magic, 8) || std::memcmp(magic, kMagic, 8) != 0) {
    why = "bad magic";
    return false;
  }
  if (!in.read(reinterpret_cast<char*>(&version), 4) || version != kVersion) {
    why = "other file version";
    return false;
  }
  in.read(reinterpret_cast<char*>(&ka), 8);
  in.read(reinterpret_cast<char*>(&kb), 8);
  in.read(reinterpret_cast<char*>(&format), 4);
  in.read(reinterpret_cast<char*>(&len), 4);
  if (!in || ka != key.a || kb != key.b) {
    why = "key mismatch";
    return false;
  }
  if (len == 0 || len > (256u << 20)) {
    why = "bad length";
    return false;
  }
  blob.data.resize(len);
  if (!in.read(blob.data.data(), len) || !in.read(reinterpret_cast<char*>(&sum), 8)) {
    why = "truncated";
    return false;
  }
  if (sum != fnv1a(blob.data.data(), blob.data.size())) {
    why = "checksum mismatch";
    return false;
  }
  blob.format = format;
  return true;
}

void writeBinary(const fs::path& path, const BinaryKey& key, const BinaryBlob& blob) {
  fs::create_directories(path.parent_path());
  // A temporary file of its own beside the cache file (parallel runs, ctest -j, never share one),
  // renamed over it when whole; removed if the write fails or a signal ends the run.
  OutputFiles out;
  const fs::path tmp = out.add(path);
  {
    std::ofstream o(tmp, std::ios::binary | std::ios::trunc);
    if (!o) throw ShaderError("program binary cache '" + tmp.string() + "': cannot open");
    const uint32_t version = kVersion, format = blob.format,
                   len = static_cast<uint32_t>(blob.data.size());
    const uint64_t sum = fnv1a(blob.data.data(), blob.data.size());
    o.write(kMagic, 8);
    o.write(reinterpret_cast<const char*>(&version), 4);
    o.write(reinterpret_cast<const char*>(&key.a), 8);
    o.write(reinterpret_cast<const char*>(&key.b), 8);
    o.write(reinterpret_cast<const char*>(&format), 4);
    o.write(reinterpret_cast<const char*>(&len), 4);
    o.write(blob.data.data(), std::streamsize(blob.data.size()));
    o.write(reinterpret_cast<const char*>(&sum), 8);
    if (!o) throw ShaderError("program binary cache '" + tmp.string() + "': write failed");
  }
  out.commit();
}

// What the driver's binaries depend on beyond its strings. llvmpipe (Mesa 22.3) keys its binary
// format on the CPU capabilities it detected, which include the number of CPUs the process may
// run on (its affinity mask): a binary saved by `halfvec render` was rejected by the same build
// run under `taskset -c 0`, or wherever a scheduler gives a process another CPU set
// (docs/hostile-input.md). The key holds both counts.
std::string cpuKey() {
  std::string k = "cpus " + std::to_string(::sysconf(_SC_NPROCESSORS_ONLN));
  cpu_set_t set;
  CPU_ZERO(&set);
  if (::sched_getaffinity(0, sizeof set, &set) == 0)
    k += " affinity " + std::to_string(CPU_COUNT(&set));
  return k;
}

std::string glString(GLenum e) {
  const auto* s = reinterpret_cast<const char*>(glGetString(e));
  return s ? s : "";
}

// The program stored under `file`, or nothing when it is missing, unreadable or rejected by the
// driver (then compiled again and the entry rewritten).
std::optional<Program> loadBinary(const fs::path& file, const BinaryKey& bkey,
                                  const std::string& name, VariantInfo& info) {
  BinaryBlob blob;
  std::string why;
  const auto t0 = Clock::now();
  if (!readBinary(file, bkey, blob, why)) {
    if (why != "missing")
      log::debug("program binary cache: ignoring " + file.string() + " (" + why + ")");
    return std::nullopt;
  }
  Program p(glCreateProgram(), name);
  glProgramBinary(p.id(), blob.format, blob.data.data(), GLsizei(blob.data.size()));
  GLint ok = GL_FALSE;
  glGetProgramiv(p.id(), GL_LINK_STATUS, &ok);
  if (!ok) {
    // Expected now and then (another driver build, or a key that misses what the driver
    // checks): compiled again and the entry rewritten, silently (--verbose shows it).
    log::debug("program binary cache: " + file.string() + " rejected by the driver; " +
               "compiling '" + name + "' and replacing it");
    return std::nullopt;
  }
  info.cache_load_ms = msSince(t0);
  info.from_binary_cache = true;
  return p;
}

// Stores a freshly linked program's binary; a read-only cache must not stop rendering.
void saveBinary(const Program& prog, const fs::path& file, const BinaryKey& bkey,
                VariantInfo& info) {
  GLint len = 0;
  glGetProgramiv(prog.id(), GL_PROGRAM_BINARY_LENGTH, &len);
  if (len <= 0) return;
  BinaryBlob blob;
  blob.data.resize(size_t(len));
  GLsizei got = 0;
  glGetProgramBinary(prog.id(), len, &got, &blob.format, blob.data.data());
  blob.data.resize(size_t(std::max(got, 0)));
  if (blob.data.empty()) return;
  try {
    writeBinary(file, bkey, blob);
    info.binary_saved = true;
  } catch (const std::exception& e) {
    log::warn(std::string("program binary cache: not written: ") + e.what());
  }
}

}  // namespace

Program buildProgram(const ProgramDesc& desc, BuildTimings* timings, bool retrievable) {
  return buildFromSources(desc, expandAll(desc), timings, retrievable);
}

fs::path defaultProgramCacheDir() {
  fs::path base;
  if (const char* d = std::getenv("HV_CACHE_DIR"); d && *d) {
    base = d;
  } else if (const char* x = std::getenv("XDG_CACHE_HOME"); x && *x) {
    base = fs::path(x) / "halfvec";
  } else if (const char* h = std::getenv("HOME"); h && *h) {
    base = fs::path(h) / ".cache" / "halfvec";
  } else {
    base = fs::temp_directory_path() / "halfvec-cache";
  }
  return base / "programs";
}

void ProgramCache::setBinaryCacheDir(const fs::path& dir) {
  binary_dir_ = dir;
  if (!binary_queried_) {
    GLint n = 0;
    glGetIntegerv(GL_NUM_PROGRAM_BINARY_FORMATS, &n);
    binary_formats_ = n;
    binary_supported_ = n > 0;
    driver_ = glString(GL_VENDOR) + "|" + glString(GL_RENDERER) + "|" + glString(GL_VERSION) + "|" +
              cpuKey();
    binary_queried_ = true;
  }
}

std::string ProgramCache::binaryCacheStatus() const {
  if (binary_dir_.empty()) return "off";
  if (!binary_supported_) return "unsupported by driver (GL_NUM_PROGRAM_BINARY_FORMATS = 0)";
  return binary_dir_.string() + " (" + std::to_string(binary_formats_) + " binary format" +
         (binary_formats_ == 1 ? "" : "s") + ")";
}

fs::path ProgramCache::binaryCachePath(const ProgramDesc& desc) const {
  if (!binaryCacheEnabled()) return {};
  return cacheFile(binary_dir_, binaryKey(driver_, desc, expandAll(desc)));
}

std::vector<std::string> ProgramCache::reasonsFor(const ProgramDesc& desc) const {
  std::vector<std::string> out;
  for (const auto& d : desc.defines) {
    std::string line = d.name + "=" + d.value;
    if (auto r = desc.reasons.find(d.name); r != desc.reasons.end()) {
      line += ": " + r->second;
    } else if (auto dr = define_reasons_.find(d.name);
               dr != define_reasons_.end() && dr->second.first == d.value) {
      line += ": " + dr->second.second;
    }
    out.push_back(std::move(line));
  }
  return out;
}

GLuint ProgramCache::get(const ProgramDesc& desc) {
  const std::string key = desc.key();
  if (auto it = programs_.find(key); it != programs_.end()) {
    VariantInfo& info = variants_[it->second.second];
    info.last_frame = frame_;
    // The scene changed since (e.g. more lights of a type present): same code, new reasons.
    if (info.reasons_generation != reasons_generation_) {
      info.reasons = reasonsFor(desc);
      info.reasons_generation = reasons_generation_;
    }
    return it->second.first.id();
  }
  VariantInfo info;
  info.name = desc.name;
  info.key = key;
  info.defines = defineKey(desc.defines);
  for (const auto& s : desc.stages) info.stages.push_back(s.path);
  info.reasons = reasonsFor(desc);
  info.reasons_generation = reasons_generation_;
  info.last_frame = frame_;

  const auto sources = expandAll(desc);
  std::optional<Program> prog;
  BinaryKey bkey;
  fs::path file;
  if (binaryCacheEnabled()) {
    bkey = binaryKey(driver_, desc, sources);
    file = cacheFile(binary_dir_, bkey);
    prog = loadBinary(file, bkey, desc.name, info);
    if (prog) ++hits_;
  }
  if (!prog) {
    BuildTimings t;
    prog = buildFromSources(desc, sources, &t, binaryCacheEnabled());
    info.compile_ms = t.compile_ms;
    info.link_ms = t.link_ms;
    if (binaryCacheEnabled()) {
      ++misses_;
      saveBinary(*prog, file, bkey, info);
    }
  }
  const GLuint id = prog->id();
  descs_.emplace(key, desc);
  programs_.emplace(key, std::make_pair(std::move(*prog), variants_.size()));
  variants_.push_back(std::move(info));
  return id;
}

void ProgramCache::clear() {
  programs_.clear();
  variants_.clear();
  descs_.clear();
}

void ProgramCache::reloadAll() {
  struct Rebuilt {
    std::string key;
    Program program;
    BuildTimings timings;
  };
  std::vector<Rebuilt> fresh;
  for (const auto& [key, desc] : descs_) {
    BuildTimings t;
    Program p = buildProgram(desc, &t);  // may throw: nothing replaced yet
    fresh.push_back({key, std::move(p), t});
  }
  for (Rebuilt& r : fresh) {
    auto& entry = programs_.at(r.key);
    entry.first = std::move(r.program);
    VariantInfo& info = variants_[entry.second];
    info.compile_ms = r.timings.compile_ms;
    info.link_ms = r.timings.link_ms;
    info.cache_load_ms = 0.0;
    info.from_binary_cache = false;
  }
}

}  // namespace hv::gl
