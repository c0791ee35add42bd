#include "halfvec/gl/shader_source.hpp"

#include "embedded_shaders.hpp"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <mutex>
#include <regex>
#include <set>
#include <sstream>

namespace hv::gl {
namespace fs = std::filesystem;

std::string defineKey(DefineSet defines) {
  std::sort(defines.begin(), defines.end());
  std::string key;
  for (const auto& d : defines) {
    if (!key.empty()) key += ';';
    key += d.name + '=' + d.value;
  }
  return key;
}

namespace {

std::mutex g_dir_mutex;
fs::path g_shader_dir;  // setShaderDir

// True when `p` lies under the embedded root; `rel` gets the '/'-separated path below it.
bool embeddedPath(const fs::path& p, std::string& rel) {
  const fs::path norm = p.lexically_normal();
  const fs::path r = norm.lexically_relative(embeddedShaderRoot());
  if (r.empty() || *r.begin() == "..") return false;
  rel = r.generic_string();
  return true;
}

}  // namespace

const fs::path& embeddedShaderRoot() {
  static const fs::path root = fs::path("[embedded]") / "shaders";
  return root;
}

void setShaderDir(const fs::path& dir) {
  if (!dir.empty() && !(fs::is_directory(dir / "passes") && fs::is_directory(dir / "common"))) {
    throw ShaderError(dir.string() +
                      ": not a halfvec shader folder (expected passes/ and common/)");
  }
  std::lock_guard<std::mutex> lock(g_dir_mutex);
  g_shader_dir = dir;
}

fs::path shaderRoot() {
  if (const char* env = std::getenv("HV_SHADER_DIR"); env && *env) return env;
  std::lock_guard<std::mutex> lock(g_dir_mutex);
  return g_shader_dir.empty() ? embeddedShaderRoot() : g_shader_dir;
}

std::optional<std::string> readShaderFile(const fs::path& path) {
  std::string rel;
  if (embeddedPath(path, rel)) {
    for (size_t i = 0; i < detail::kEmbeddedShaderCount; ++i) {
      if (rel == detail::kEmbeddedShaders[i].path)
        return std::string(detail::kEmbeddedShaders[i].text);
    }
    return std::nullopt;
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

namespace {

struct Expander {
  std::vector<std::string> files;
  std::set<std::string> included;
  std::vector<std::string> stack;
  std::string out;

  int fileId(const fs::path& p) {
    const std::string s = p.lexically_normal().string();
    auto it = std::find(files.begin(), files.end(), s);
    if (it != files.end()) return static_cast<int>(it - files.begin());
    files.push_back(s);
    return static_cast<int>(files.size() - 1);
  }

  static std::string readFile(const fs::path& p, const std::string& from) {
    std::optional<std::string> text = readShaderFile(p);
    if (!text) {
      throw ShaderError(from.empty() ? p.string() + ": cannot open shader file"
                                     : from + ": cannot open included file '" + p.string() + "'");
    }
    return std::move(*text);
  }

  // Expands one file. `top` is true for the stage's main file (holds #version).
  void expand(const fs::path& path, const std::string& from, const DefineSet* defines) {
    std::string rel;
    const std::string norm = embeddedPath(path, rel) ? path.lexically_normal().string()
                                                     : fs::weakly_canonical(path).string();
    if (std::find(stack.begin(), stack.end(), norm) != stack.end()) {
      throw ShaderError(from + ": include cycle through '" + path.string() + "'");
    }
    if (!defines && included.count(norm)) return;  // each header once per program stage
    included.insert(norm);
    stack.push_back(norm);
    const std::string text = readFile(path, from);
    const int id = fileId(path);
    std::istringstream in(text);
    std::string line;
    int line_no = 0;
    bool version_seen = false;
    static const std::regex include_re(R"(^\s*#\s*include\s+\"([^\"]+)\"\s*$)");
    static const std::regex version_re(R"(^\s*#\s*version\b.*)");
    if (!defines) out += "#line 1 " + std::to_string(id) + "\n";
    while (std::getline(in, line)) {
      ++line_no;
      if (!line.empty() && line.back() == '\r') line.pop_back();
      std::smatch m;
      if (defines && !version_seen && std::regex_match(line, version_re)) {
        version_seen = true;
        out += line + "\n";
        for (const auto& d : *defines) out += "#define " + d.name + " " + d.value + "\n";
        out += "#line " + std::to_string(line_no + 1) + " " + std::to_string(id) + "\n";
        continue;
      }
      if (std::regex_match(line, m, include_re)) {
        const std::string where = path.string() + ":" + std::to_string(line_no);
        expand(path.parent_path() / m[1].str(), where, nullptr);
        out += "#line " + std::to_string(line_no + 1) + " " + std::to_string(id) + "\n";
        continue;
      }
      out += line + "\n";
    }
    if (defines && !version_seen) {
      throw ShaderError(path.string() + ":1: a stage's main file must start with #version");
    }
    stack.pop_back();
  }
};

}  // namespace

ExpandedSource expandShader(const fs::path& file, const DefineSet& defines) {
  Expander e;
  DefineSet sorted = defines;
  std::sort(sorted.begin(), sorted.end());
  e.expand(file, "", &sorted);
  return {std::move(e.out), std::move(e.files)};
}

std::string mapDiagnostics(const std::string& log, const std::vector<std::string>& files) {
  // Mesa: "0:12(3): error"; NVIDIA: "0(12) : error"; glslang: "ERROR: 0:12: ".
  static const std::regex mesa(R"((\d+):(\d+)\((\d+)\))");
  static const std::regex nvidia(R"((^|\n)(\d+)\((\d+)\))");
  static const std::regex glslang(R"((ERROR|WARNING): (\d+):(\d+):)");
  auto name = [&](const std::string& id) {
    const size_t i = std::stoul(id);
    return i < files.size() ? files[i] : "<source " + id + ">";
  };
  std::string out;
  std::istringstream in(log);
  std::string line;
  while (std::getline(in, line)) {
    std::smatch m;
    if (std::regex_search(line, m, glslang)) {
      line = m.prefix().str() + m[1].str() + ": " + name(m[2]) + ":" + m[3].str() + ":" +
             m.suffix().str();
    } else if (std::regex_search(line, m, mesa)) {
      line = m.prefix().str() + name(m[1]) + ":" + m[2].str() + ":" + m[3].str() + m.suffix().str();
    } else if (std::regex_search(line, m, nvidia)) {
      line = m.prefix().str() + m[1].str() + name(m[2]) + ":" + m[3].str() + m.suffix().str();
    }
    out += line + "\n";
  }
  return out;
}

}  // namespace hv::gl
