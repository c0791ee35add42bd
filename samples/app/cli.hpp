// The halfvec command line: `halfvec render|compare|...`. runCli is the whole program, so tests
// drive it without a subprocess.
#pragma once

#include <string>
#include <vector>

namespace hv::app {

int runCli(const std::vector<std::string>& args);

// Defaults of the `halfvec` program (not of the library), set once at start-up:
//  - the shader folder beside the executable, so edited shaders reload without a rebuild (the
//    viewer's R key): <exe dir>/share/halfvec/shaders (the build tree) or
//    <exe dir>/../share/halfvec/shaders (an installed prefix); without one the library's
//    embedded shaders are used. HV_SHADER_DIR, when set, still wins (gl::shaderRoot).
//  - HV_ASSETS_DIR, when unset, to the assets folder the build was configured with (CMake
//    option HV_ASSETS_DIR; scripts/build.sh sets it to ../shared/assets when present).
void applyProgramDefaults();

}  // namespace hv::app
