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
int cmdAccuracy(const Args& args);
int cmdTrade(const Args& args);
int cmdLtcFit(const Args& args);

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
