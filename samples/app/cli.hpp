// The halfvec command line: `halfvec render|compare|...`. runCli is the whole program, so tests
// drive it without a subprocess.
#pragma once

#include <string>
#include <vector>

namespace hv::app {

int runCli(const std::vector<std::string>& args);

}  // namespace hv::app
