// One function per subcommand; each returns the process exit code.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "halfvec/core/output_files.hpp"
#include "halfvec/scene/model_scene.hpp"
#include "halfvec/scene/scene.hpp"

namespace hv::app {

using Args = std::vector<std::string>;

int cmdRender(const Args& args);
int cmdCompare(const Args& args);
int cmdStability(const Args& args);
int cmdBench(const Args& args);
int cmdReference(const Args& args);
int cmdView(const Args&);
// `bench --variants` (bench_variants.cpp): specialized vs uber programs per pass per sample scene.
int benchVariants(int width, int height, int frames);
// Table (e) of `halfvec bench`: per area-light type, `n` lights of the scene `scene(type)`, the
// light pass of each method (eval/light_methods.hpp) from interleaved frames, and the ratios to
// the representative point (bench_methods.cpp).
void methodsTable(const std::function<Scene(LightType)>& scene, int n, int w, int h, int frames);
// `bench --frame` (bench_frame.cpp): every pass as a multiple of the floor pass, per sample scene.
struct FrameBenchOptions {
  int width = 1280, height = 720, frames = 9;
  std::string scene;                     // empty: every sample scene
  std::vector<std::string> shader_dirs;  // A/B shader trees (needs `scene`)
  // Settings overrides compared with the scene as it is (needs `scene`): "K=V,K=V" per set.
  std::vector<std::string> settings_sets;
  std::string report;         // markdown table to write (empty: none)
  bool vs_brute = false;      // instead: whole frame, tiled culling vs brute force (interleaved)
  bool cull_stages = false;   // the culling timed per stage (DebugOptions::cull_stage_timers)
  bool shadow_sweep = false;  // instead: shadow cost per filter and shadowed-light count
};
int benchFrame(const FrameBenchOptions& options);
// The sample scene files (samples/scenes/*.json), sorted.
std::vector<std::string> sampleScenePaths();
int cmdAccuracy(const Args& args);
int cmdTrade(const Args& args);
int cmdLtcFit(const Args& args);
int cmdErrorFit(const Args& args);

// Parses a --size value "WxH" (1..16384 each); throws UsageError naming the bad value.
void parseSize(const std::string& value, int& width, int& height);

// Thrown for bad command-line usage; the message is printed with the command's help hint.
struct UsageError {
  std::string message;
};

// The value of option args[i]: advances i to it; throws UsageError "<option> needs a value" when
// the option is the last argument.
std::string optionValue(const Args& args, size_t& i);

// A generated table's command line as its header records it: `command` and the arguments, less
// the options in `unrecorded` and their values (those that do not change the table).
std::string recordedCommand(const std::string& command, const Args& args,
                            const std::vector<std::string>& unrecorded);

// `v` as an integer in [lo, hi], the whole string decimal digits; else UsageError "<option>
// expects an integer in <lo>..<hi>, got '<v>'".
int intInRange(const std::string& option, const std::string& v, int lo, int hi);
int positiveInt(const std::string& option, const std::string& v);  // 1..1,000,000
// `v` as a number in [lo, hi] (hi may be infinity), the whole string (no leading space, not NaN);
// else UsageError "<option> expects a number in [<lo>, <hi>], got '<v>'".
double numberInRange(const std::string& option, const std::string& v, double lo, double hi);
// The same for an option stored as a float: parsed as a double, converted, and the float compared
// with the bounds as floats (so the bounds themselves are accepted and nothing becomes inf).
float floatInRange(const std::string& option, const std::string& v, float lo, float hi);

// A positional argument of a command that takes one scene file: stores it in `scene`; throws
// UsageError for an unknown option (a leading '-') or a second scene file.
void takeScenePath(const std::string& arg, std::string& scene);

// Options of the commands that open a scene or a model (render, view): --env FILE.hdr,
// --camera N, --set PATH=VALUE, --print-scene, --camera-position X,Y,Z, --camera-target X,Y,Z,
// --fov DEG (the three as --set camera.* overrides, in order with the --set ones),
// --no-key-light, --look gltf|scene. Returns true when args[i] was one of them (i then points at
// its last value); throws UsageError for a bad value.
bool takeSceneOption(const Args& args, size_t& i, SceneOpenOptions& options, bool& print_scene);

// "; did you mean "depth"? (one of: none, basecolor, ...)" for an unknown --view name.
std::string debugViewSuggestion(const std::string& typed);

// --print-scene: writes to stdout the scene JSON `path` opens as (a model's synthesized scene,
// --env, --look and the --set overrides applied), in the sample scenes' style.
int printScene(const std::string& path, const SceneOpenOptions& options);

// Declares every file a scene run reads as an input of `outputs` (OutputFiles::protectInput), so
// that no output of the run can overwrite one: the scene file (or model), --env's HDR, the
// scene's HDR environment and the glTF files its objects name. Call before adding outputs.
void protectSceneInputs(OutputFiles& outputs, const std::string& scene_path,
                        const SceneOpenOptions& options, const Scene& scene);

}  // namespace hv::app
