// hv_shaderc: expands pass shaders with the engine's own #include resolver (the code the runtime
// uses) and validates each variant with glslangValidator at build time, so a broken shader fails
// the build. Errors are reported as original file:line.
//
//   hv_shaderc --validate GLSLANG --root SHADER_DIR --variants variants.txt --work DIR
//   hv_shaderc --expand FILE [NAME=VALUE ...]      (prints the expanded source)
//
// variants.txt: one variant per line, `FILE [NAME=VALUE ...]`; '#' starts a comment.
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "halfvec/gl/shader_source.hpp"

namespace fs = std::filesystem;

namespace {

hv::gl::DefineSet parseDefines(std::istringstream& in) {
  hv::gl::DefineSet d;
  std::string tok;
  while (in >> tok) {
    const auto eq = tok.find('=');
    d.push_back({tok.substr(0, eq), eq == std::string::npos ? "1" : tok.substr(eq + 1)});
  }
  return d;
}

int validate(const std::string& glslang, const fs::path& root, const fs::path& variants,
             const fs::path& work) {
  std::ifstream in(variants);
  if (!in) {
    std::fprintf(stderr, "%s: cannot open\n", variants.string().c_str());
    return 1;
  }
  fs::create_directories(work);
  std::string line;
  int n = 0, failed = 0, line_no = 0;
  while (std::getline(in, line)) {
    ++line_no;
    if (auto h = line.find('#'); h != std::string::npos) line.resize(h);
    std::istringstream ls(line);
    std::string file;
    if (!(ls >> file)) continue;
    const auto defines = parseDefines(ls);
    hv::gl::ExpandedSource src;
    try {
      src = hv::gl::expandShader(root / file, defines);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "%s\n", e.what());
      ++failed;
      continue;
    }
    const fs::path out = work / (std::to_string(n++) + "_" + fs::path(file).filename().string());
    std::ofstream(out) << src.text;
    const fs::path log = out.string() + ".log";
    const std::string cmd =
        "\"" + glslang + "\" \"" + out.string() + "\" > \"" + log.string() + "\" 2>&1";
    if (std::system(cmd.c_str()) != 0) {
      std::ifstream l(log);
      std::stringstream ss;
      ss << l.rdbuf();
      std::fprintf(stderr, "%s:%d: variant [%s] of %s does not compile:\n%s\n",
                   variants.string().c_str(), line_no, hv::gl::defineKey(defines).c_str(),
                   file.c_str(), hv::gl::mapDiagnostics(ss.str(), src.files).c_str());
      ++failed;
    }
  }
  std::printf("hv_shaderc: %d shader variants validated, %d failed\n", n, failed);
  return failed == 0 ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> a(argv + 1, argv + argc);
  if (a.size() >= 2 && a[0] == "--expand") {
    std::string defs;
    for (size_t i = 2; i < a.size(); ++i) defs += a[i] + " ";
    std::istringstream ds(defs);
    try {
      std::cout << hv::gl::expandShader(a[1], parseDefines(ds)).text;
    } catch (const std::exception& e) {
      std::fprintf(stderr, "%s\n", e.what());
      return 1;
    }
    return 0;
  }
  std::string glslang, root, variants, work;
  for (size_t i = 0; i + 1 < a.size(); i += 2) {
    if (a[i] == "--validate")
      glslang = a[i + 1];
    else if (a[i] == "--root")
      root = a[i + 1];
    else if (a[i] == "--variants")
      variants = a[i + 1];
    else if (a[i] == "--work")
      work = a[i + 1];
  }
  if (glslang.empty() || root.empty() || variants.empty() || work.empty()) {
    std::fprintf(stderr,
                 "usage: hv_shaderc --validate GLSLANG --root DIR --variants FILE --work DIR\n"
                 "       hv_shaderc --expand FILE [NAME=VALUE ...]\n");
    return 2;
  }
  return validate(glslang, root, variants, work);
}
