// hv_setting_values: writes shaders/common/setting_values.glsl from the settings table's value
// lists (halfvec/scene/render_settings.hpp, settingValuesGlsl()), or checks that it is current.
// The build runs --check, so a list changed without regenerating the file fails the build.
//
//   hv_setting_values --out shaders/common/setting_values.glsl
//   hv_setting_values --check shaders/common/setting_values.glsl
#include <cstdio>
#include <fstream>
#include <iterator>
#include <optional>
#include <string>
#include <string_view>

#include "halfvec/core/output_files.hpp"
#include "halfvec/scene/render_settings.hpp"

namespace {

std::optional<std::string> readText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

int usage() {
  std::fprintf(stderr, "usage: hv_setting_values --out FILE | --check FILE\n");
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) return usage();
  const std::string_view mode = argv[1];
  const std::string path = argv[2];
  const std::string text = hv::settingValuesGlsl();
  const std::optional<std::string> current = readText(path);
  if (mode == "--check") {
    if (current == text) return 0;
    std::fprintf(stderr,
                 "%s: %s the value lists of render_settings.hpp; regenerate it with\n"
                 "  hv_setting_values --out %s\n",
                 path.c_str(), current ? "does not match" : "cannot be read, expected from",
                 path.c_str());
    return 1;
  }
  if (mode != "--out") return usage();
  if (current == text) return 0;  // unchanged: keep its time stamp (the shaders' rebuild)
  try {
    hv::writeFileAtomic(path, text);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  }
  std::printf("wrote %s\n", path.c_str());
  return 0;
}
