#include "app/cli.hpp"

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cfloat>
#include <cmath>
#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <string_view>
#include <system_error>

#include "app/commands.hpp"
#include "halfvec/core/suggest.hpp"
#include "halfvec/gl/log.hpp"
#include "halfvec/gl/shader_source.hpp"
#include "halfvec/render/renderer.hpp"
#include "halfvec/scene/model_scene.hpp"
#include "halfvec/scene/scene_loader.hpp"
#include "halfvec/scene/scene_writer.hpp"

namespace hv::app {

namespace {
constexpr const char* kHelp = R"(halfvec - a deferred PBR renderer (UE4 shading model), measured.

Usage: halfvec <command> [options]

Commands:
  render SCENE          render headless to PNG (and HDR PFM), print per-pass GPU times;
                        SCENE is a scene file (.json) or a glTF model (.gltf, .glb)
  compare TEST REF      error metrics between two images (PFM or PNG), exit 1 outside
                        the given tolerances (for regression tests, docs/testing.md)
  stability             NaN/Inf/negative sweep over extreme light and material cases
  reference SCENE.json  CPU Monte Carlo ground truth over the GPU's G-buffer
  bench                 light-pass scaling tables (ms, light-pixel evaluations per second)
  view SCENE            interactive viewer (a scene file or a glTF model): orbit camera,
                        material/lights/rendering panels
  accuracy              sweep of every approximation vs the reference -> docs/accuracy.md
  trade SCENE.json      speed/accuracy trade report: ms per pass and error per option, presets
  ltc-fit               fit the LTC table of the ltc light modes -> engine/shading/src/ltc_table.cpp
  error-fit             measure the error budget's table (max_error)
                        -> engine/shading/src/error_table.cpp

Run `halfvec <command> --help` for the options of each command.
Any command also takes --verbose: debug messages (e.g. program binary cache entries the driver
rejected and that were compiled again) go to stderr too.
)";
struct Command {
  std::string_view name;
  int (*run)(const Args&);
};
constexpr Command kCommands[] = {
    {"render", cmdRender},      {"compare", cmdCompare},     {"stability", cmdStability},
    {"bench", cmdBench},        {"reference", cmdReference}, {"view", cmdView},
    {"accuracy", cmdAccuracy},  {"trade", cmdTrade},         {"ltc-fit", cmdLtcFit},
    {"error-fit", cmdErrorFit},
};

// The options a command's --help lists (lines starting with "  -" or "  --"), read from its
// help text so that the suggestions never drift from the documentation.
std::vector<std::string> helpOptions(const Command& c) {
  std::fflush(stdout);
  FILE* tmp = std::tmpfile();
  if (!tmp) return {};
  const int saved = dup(STDOUT_FILENO);
  dup2(fileno(tmp), STDOUT_FILENO);
  try {
    c.run({"--help"});
  } catch (...) {
  }
  std::fflush(stdout);
  dup2(saved, STDOUT_FILENO);
  close(saved);
  std::rewind(tmp);
  std::string text;
  for (int ch; (ch = std::fgetc(tmp)) != EOF;) text += char(ch);
  std::fclose(tmp);
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    const size_t p = line.find_first_not_of(' ');
    if (p == std::string::npos || line.compare(p, 2, "--") != 0) continue;
    const size_t end = line.find_first_of(" ,=", p);
    out.push_back(line.substr(p, end == std::string::npos ? std::string::npos : end - p));
  }
  return out;
}

// "unknown option '--sise'" -> "unknown option '--sise'; did you mean "--size"?"
std::string withSuggestion(const Command& c, const std::string& message) {
  const std::string prefix = "unknown option '";
  if (message.rfind(prefix, 0) != 0 || message.back() != '\'') return message;
  const std::string typed = message.substr(prefix.size(), message.size() - prefix.size() - 1);
  const std::vector<std::string> options = helpOptions(c);
  const std::vector<std::string_view> names(options.begin(), options.end());
  return message + didYouMeanSuffix(typed, names);
}

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

int intInRange(const std::string& option, const std::string& v, int lo, int hi) {
  // Decimal digits only, the whole value: '12abc', ' 5', '+5' and '' are refused (atoi took
  // them). lo >= 0 for every option, so no sign is needed.
  const bool digits = !v.empty() && v.size() <= 10 &&
                      std::all_of(v.begin(), v.end(), [](char c) { return c >= '0' && c <= '9'; });
  const long n = digits ? std::strtol(v.c_str(), nullptr, 10) : -1;
  if (!digits || n < lo || n > hi) {
    throw UsageError{option + " expects an integer in " + std::to_string(lo) + ".." +
                     std::to_string(hi) + ", got '" + v + "'"};
  }
  return int(n);
}

int positiveInt(const std::string& option, const std::string& v) {
  return intInRange(option, v, 1, 1000000);
}

double numberInRange(const std::string& option, const std::string& v, double lo, double hi) {
  char* end = nullptr;
  const double x = std::strtod(v.c_str(), &end);
  // strtod skips leading white space; the value must not start with any.
  const bool space = !v.empty() && std::isspace(static_cast<unsigned char>(v[0]));
  if (v.empty() || space || end != v.c_str() + v.size() || !(x >= lo && x <= hi)) {
    char buf[96];
    std::snprintf(buf, sizeof buf, " expects a number in [%g, %g], got '", lo, hi);
    throw UsageError{option + buf + v + "'"};
  }
  return x;
}

float floatInRange(const std::string& option, const std::string& v, float lo, float hi) {
  char* end = nullptr;
  const double x = std::strtod(v.c_str(), &end);
  const bool space = !v.empty() && std::isspace(static_cast<unsigned char>(v[0]));
  const float f = std::isfinite(x) && std::abs(x) <= double(FLT_MAX) ? float(x) : NAN;
  if (v.empty() || space || end != v.c_str() + v.size() || !(f >= lo && f <= hi)) {
    char buf[96];
    std::snprintf(buf, sizeof buf, " expects a number in [%g, %g], got '", double(lo), double(hi));
    throw UsageError{option + buf + v + "'"};
  }
  return f;
}

std::string optionValue(const Args& args, size_t& i) {
  if (i + 1 >= args.size()) throw UsageError{args[i] + " needs a value"};
  return args[++i];
}

std::string recordedCommand(const std::string& command, const Args& args,
                            const std::vector<std::string>& unrecorded) {
  std::string out = command;
  for (size_t i = 0; i < args.size(); ++i) {
    if (std::find(unrecorded.begin(), unrecorded.end(), args[i]) != unrecorded.end()) {
      ++i;
      continue;
    }
    out += " " + args[i];
  }
  return out;
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

namespace {

// "X,Y,Z" as the JSON array of a --set override; each coordinate within the scene's +-1e6 m.
std::string vec3Option(const std::string& option, const std::string& v) {
  std::string out = "[";
  size_t start = 0;
  for (int k = 0; k < 3; ++k) {
    const size_t comma = v.find(',', start);
    if ((k < 2) != (comma != std::string::npos)) {
      throw UsageError{option + " expects X,Y,Z (three numbers), got '" + v + "'"};
    }
    const std::string part = v.substr(start, k < 2 ? comma - start : std::string::npos);
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.9g", double(floatInRange(option, part, -1e6f, 1e6f)));
    if (k) out += ',';
    out += buf;
    start = comma + 1;
  }
  return out + "]";
}

}  // namespace

bool takeSceneOption(const Args& args, size_t& i, SceneOpenOptions& options, bool& print_scene) {
  const std::string& a = args[i];
  if (a == "--camera-position" || a == "--camera-target") {
    const std::string key = a == "--camera-position" ? "position" : "target";
    options.overrides.push_back("camera." + key + "=" + vec3Option(a, optionValue(args, i)));
  } else if (a == "--fov") {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.9g",
                  double(floatInRange(a, optionValue(args, i), 0.01f, 179.9f)));
    options.overrides.push_back(std::string("camera.fov_y_deg=") + buf);
  } else if (a == "--no-key-light") {
    options.key_light = false;
  } else if (a == "--look") {
    const std::string v = optionValue(args, i);
    if (v == "gltf") {
      options.look = Look::Gltf;
    } else if (v == "scene") {
      options.look = Look::Scene;
    } else {
      throw UsageError{"--look expects gltf or scene, got '" + v + "'"};
    }
  } else if (a == "--env") {
    options.environment_hdr = optionValue(args, i);
  } else if (a == "--camera") {
    const std::string v = optionValue(args, i);
    char* end = nullptr;
    const long n = std::strtol(v.c_str(), &end, 10);
    if (v.empty() || *end != '\0' || n < 0 || n > 1000000) {
      throw UsageError{"--camera expects a camera index >= 0, got '" + v + "'"};
    }
    options.camera = int(n);
  } else if (a == "--print-scene") {
    print_scene = true;
  } else if (a == "--set") {
    options.overrides.push_back(optionValue(args, i));
  } else {
    return false;
  }
  return true;
}

std::string debugViewSuggestion(const std::string& typed) {
  std::vector<std::string_view> names;
  for (size_t v = 0; v < render::kDebugViewCount; ++v) {
    names.push_back(render::toString(render::DebugView(v)));
  }
  std::string all;
  for (std::string_view n : names) all += (all.empty() ? "" : ", ") + std::string(n);
  return didYouMeanSuffix(typed, names) + " (one of: " + all + ")";
}

int printScene(const std::string& path, const SceneOpenOptions& options) {
  std::fputs(formatSceneJson(sceneJsonFor(path, options)).c_str(), stdout);
  return 0;
}

void protectSceneInputs(OutputFiles& outputs, const std::string& scene_path,
                        const SceneOpenOptions& options, const Scene& scene) {
  namespace fs = std::filesystem;
  outputs.protectInput(scene_path);
  if (!options.environment_hdr.empty()) outputs.protectInput(options.environment_hdr);
  if (!scene.environment.path.empty()) outputs.protectInput(scene.environment.path);
  if (isModelPath(scene_path)) return;
  // The glTF files of a scene file's objects, resolved as the loader does (it has loaded them:
  // the file is valid and its ${VAR}s are set).
  try {
    const nlohmann::json j = nlohmann::json::parse(readSceneFile(scene_path));
    if (!j.contains("objects") || !j["objects"].is_array()) return;
    const fs::path dir = fs::path(scene_path).parent_path();
    for (const auto& o : j["objects"]) {
      if (!o.is_object() || !o.contains("gltf") || !o["gltf"].is_string()) continue;
      fs::path p(expandEnvVars(o["gltf"].get<std::string>()));
      outputs.protectInput(p.is_relative() ? dir / p : p);
    }
  } catch (const std::exception&) {  // the loader accepted the file: nothing more to protect
  }
}

int runCli(const std::vector<std::string>& args) {
  if (args.empty() || args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
    std::fputs(kHelp, stdout);
    return args.empty() ? 2 : 0;
  }
  const std::string cmd = args[0];
  Args rest;
  bool verbose = false;
  for (size_t i = 1; i < args.size(); ++i) {
    if (args[i] == "--verbose") {
      verbose = true;
    } else {
      rest.push_back(args[i]);
    }
  }
  log::setMinLevel(verbose ? log::Level::Debug : log::Level::Info);
  const Command* command = nullptr;
  for (const Command& c : kCommands) {
    if (c.name == cmd) command = &c;
  }
  if (!command) {
    std::vector<std::string_view> names;
    for (const Command& c : kCommands) names.push_back(c.name);
    std::fprintf(stderr, "halfvec: unknown command '%s'%s (see halfvec --help)\n", cmd.c_str(),
                 didYouMeanSuffix(cmd, names).c_str());
    return 2;
  }
  try {
    return command->run(rest);
  } catch (const UsageError& e) {
    std::fprintf(stderr, "halfvec %s: %s (see halfvec %s --help)\n", cmd.c_str(),
                 withSuggestion(*command, e.message).c_str(), cmd.c_str());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "halfvec %s: error: %s\n", cmd.c_str(), e.what());
    return 1;
  }
}

}  // namespace hv::app
