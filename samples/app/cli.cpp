#include "app/cli.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <string_view>
#include <exception>
#include <filesystem>
#include <system_error>

#include "app/commands.hpp"
#include "halfvec/gl/shader_source.hpp"

namespace hv::app {

namespace {
constexpr const char* kHelp = R"(halfvec - a deferred PBR renderer (UE4 shading model), measured.

Usage: halfvec <command> [options]

Commands:
  render SCENE.json     render headless to PNG (and HDR PFM), print per-pass GPU times
  compare A.pfm B.pfm   error metrics between two HDR images (+ heat map)
  stability             NaN/Inf/negative sweep over extreme light and material cases
  reference SCENE.json  CPU Monte Carlo ground truth over the GPU's G-buffer
  bench                 light-pass scaling tables (ms, light-pixel evaluations per second)
  view SCENE.json       interactive viewer: orbit camera, material/lights/rendering panels
  accuracy              sweep of every approximation vs the reference -> docs/accuracy.md
  trade SCENE.json      speed/accuracy trade report: ms per pass and error per option, presets

Run `halfvec <command> --help` for the options of each command.
)";
}  // namespace

void parseSize(const std::string& v, int& w, int& h) {
  // Exactly "WxH": decimal digits only (no sign, space or trailing text), each in 1..16384.
  auto number = [](std::string_view s, int& out) {
    if (s.empty() || s.size() > 5 || !std::all_of(s.begin(), s.end(), ::isdigit)) return false;
    std::from_chars(s.data(), s.data() + s.size(), out);
    return out >= 1 && out <= 16384;
  };
  const size_t x = v.find('x');
  int pw = 0, ph = 0;
  if (x == std::string::npos || !number(std::string_view(v).substr(0, x), pw) ||
      !number(std::string_view(v).substr(x + 1), ph)) {
    throw UsageError{"--size expects WxH with 1 <= W,H <= 16384, got '" + v + "'"};
  }
  w = pw, h = ph;
}

std::string optionValue(const Args& args, size_t& i) {
  if (i + 1 >= args.size()) throw UsageError{args[i] + " needs a value"};
  return args[++i];
}

void takeScenePath(const std::string& arg, std::string& scene) {
  if (!arg.empty() && arg[0] == '-') throw UsageError{"unknown option '" + arg + "'"};
  if (!scene.empty()) throw UsageError{"more than one scene file given"};
  scene = arg;
}

void applyProgramDefaults() {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path exe_dir = fs::read_symlink("/proc/self/exe", ec).parent_path();
  if (!ec) {
    for (const fs::path& dir :
         {exe_dir / "share/halfvec/shaders", exe_dir / "../share/halfvec/shaders"}) {
      if (fs::is_directory(dir / "passes", ec)) {
        gl::setShaderDir(dir.lexically_normal());
        break;
      }
    }
  }
#ifdef HV_DEFAULT_ASSETS_DIR
  const char* assets = std::getenv("HV_ASSETS_DIR");
  if ((!assets || !*assets) && *HV_DEFAULT_ASSETS_DIR &&
      fs::is_directory(HV_DEFAULT_ASSETS_DIR, ec)) {
    ::setenv("HV_ASSETS_DIR", HV_DEFAULT_ASSETS_DIR, 0);
  }
#endif
}

int runCli(const std::vector<std::string>& args) {
  if (args.empty() || args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
    std::fputs(kHelp, stdout);
    return args.empty() ? 2 : 0;
  }
  const std::string cmd = args[0];
  const Args rest(args.begin() + 1, args.end());
  try {
    if (cmd == "render") return cmdRender(rest);
    if (cmd == "compare") return cmdCompare(rest);
    if (cmd == "stability") return cmdStability(rest);
    if (cmd == "bench") return cmdBench(rest);
    if (cmd == "reference") return cmdReference(rest);
    if (cmd == "view") return cmdView(rest);
    if (cmd == "accuracy") return cmdAccuracy(rest);
    if (cmd == "trade") return cmdTrade(rest);
    std::fprintf(stderr, "halfvec: unknown command '%s' (see halfvec --help)\n", cmd.c_str());
    return 2;
  } catch (const UsageError& e) {
    std::fprintf(stderr, "halfvec %s: %s (see halfvec %s --help)\n", cmd.c_str(), e.message.c_str(),
                 cmd.c_str());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "halfvec %s: error: %s\n", cmd.c_str(), e.what());
    return 1;
  }
}

}  // namespace hv::app
