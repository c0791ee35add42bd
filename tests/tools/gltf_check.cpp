// hv_gltf_check FILE...: loads each glTF/GLB file with the engine's loader (hv::loadGltf, default
// budgets, materials and images included) and prints one line per file:
//   OK<TAB>FILE<TAB>WARNINGS        or        ERROR<TAB>FILE<TAB>MESSAGE
// For scripts/gltf_validate.sh, which compares the verdicts with the Khronos glTF Validator's.
// Exit status 0 unless a file could not be checked at all (an unexpected exception: 1).
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "halfvec/scene/gltf_loader.hpp"

int main(int argc, char** argv) {
  int status = 0;
  for (int i = 1; i < argc; ++i) {
    hv::Scene scene;
    std::vector<std::string> warnings;
    hv::GltfOptions opt;
    opt.warnings = &warnings;
    std::string line;
    try {
      hv::loadGltf(argv[i], glm::mat4(1.0f), scene, opt);
      line = "OK\t" + std::string(argv[i]) + "\t" + std::to_string(warnings.size());
    } catch (const hv::SceneError& e) {
      line = "ERROR\t" + std::string(argv[i]) + "\t" + e.what();
    } catch (const std::exception& e) {
      line = "ERROR\t" + std::string(argv[i]) + "\tunexpected exception: " + e.what();
      status = 1;
    }
    for (char& c : line) {
      if (c == '\n') c = ' ';
    }
    std::printf("%s\n", line.c_str());
    std::fflush(stdout);
  }
  return status;
}
