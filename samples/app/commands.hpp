// One function per subcommand; each returns the process exit code.
#pragma once

#include <string>
#include <vector>

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
// `bench --frame` (bench_frame.cpp): every pass as a multiple of the floor pass, per sample scene.
struct FrameBenchOptions {
  int width = 1280, height = 720, frames = 9;
  std::string scene;                     // empty: every sample scene
  std::vector<std::string> shader_dirs;  // A/B shader trees (needs `scene`)
  std::string report;                    // markdown table to write (empty: none)
};
int benchFrame(const FrameBenchOptions& options);
// The sample scene files (samples/scenes/*.json), sorted.
std::vector<std::string> sampleScenePaths();
int cmdAccuracy(const Args& args);
int cmdTrade(const Args& args);

// Parses a --size value "WxH" (1..16384 each); throws UsageError naming the bad value.
void parseSize(const std::string& value, int& width, int& height);

// Thrown for bad command-line usage; the message is printed with the command's help hint.
struct UsageError {
  std::string message;
};

// The value of option args[i]: advances i to it; throws UsageError "<option> needs a value" when
// the option is the last argument.
std::string optionValue(const Args& args, size_t& i);

// A positional argument of a command that takes one scene file: stores it in `scene`; throws
// UsageError for an unknown option (a leading '-') or a second scene file.
void takeScenePath(const std::string& arg, std::string& scene);

}  // namespace hv::app
