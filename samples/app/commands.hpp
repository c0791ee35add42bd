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

// Thrown for bad command-line usage; the message is printed with the command's help hint.
struct UsageError {
  std::string message;
};

}  // namespace hv::app
