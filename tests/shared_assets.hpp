// Where the tests find ../shared/assets: the HV_ASSETS_DIR environment variable, else the CMake
// option of the same name (empty: tests that need the assets report "skipped" with the reason).
#pragma once

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <vector>

namespace hv::test {

inline std::filesystem::path assetsDir() {
  if (const char* e = std::getenv("HV_ASSETS_DIR"); e && *e) return e;
  return HV_ASSETS_DIR;
}

// Every .gltf and .glb below `dir`, sorted.
inline std::vector<std::filesystem::path> gltfFiles(const std::filesystem::path& dir) {
  std::vector<std::filesystem::path> out;
  for (const auto& e : std::filesystem::recursive_directory_iterator(dir)) {
    const auto ext = e.path().extension();
    if (ext == ".gltf" || ext == ".glb") out.push_back(e.path());
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace hv::test
