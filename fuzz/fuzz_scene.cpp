// libFuzzer harness: scene files and --set overrides. Input: the scene JSON, then any number of
// overrides, each after a NUL byte. Paths resolve in a folder that does not exist, and
// HV_ASSETS_DIR points there too, so the fuzzer exercises the loader, not the shared assets.
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

#include "halfvec/scene/scene_loader.hpp"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  setenv("HV_ASSETS_DIR", "/nonexistent-hv-fuzz", 1);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view all(reinterpret_cast<const char*>(data), size);
  const size_t nul = all.find('\0');
  const std::string_view text = all.substr(0, nul);
  std::vector<std::string> overrides;
  for (size_t at = nul; at != std::string_view::npos && at < all.size();) {
    const size_t next = all.find('\0', at + 1);
    overrides.emplace_back(
        all.substr(at + 1, next == std::string_view::npos ? next : next - at - 1));
    at = next;
  }
  std::vector<std::string> warnings;
  try {
    hv::loadSceneFromString(text, "/nonexistent-hv-fuzz/scene.json", overrides, &warnings);
  } catch (const hv::SceneError&) {
  }  // any other exception is a check the loader misses: uncaught, libFuzzer reports it
  return 0;
}
