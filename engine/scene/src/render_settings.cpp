#include "halfvec/scene/render_settings.hpp"

#include <cctype>
#include <set>
#include <type_traits>

namespace hv {

std::vector<std::pair<std::string, std::string>> settingDefines(const RenderSettings& s,
                                                                SettingPass pass) {
  std::vector<std::pair<std::string, std::string>> out;
  forEachSetting([&](const auto& row) {
    using T = typename std::decay_t<decltype(row)>::Type;
    if (row.info.pass != pass || !row.info.define) return;
    if constexpr (std::is_same_v<T, bool>) {
      out.emplace_back(row.info.define, s.*row.member ? "1" : "0");
    } else if constexpr (std::is_enum_v<T>) {
      out.emplace_back(row.info.define, std::to_string(static_cast<int>(s.*row.member)));
    } else if constexpr (std::is_same_v<T, int>) {
      out.emplace_back(row.info.define, std::to_string(s.*row.member));
    } else if constexpr (std::is_same_v<T, float>) {
      out.emplace_back(row.info.define, s.*row.member != 0.0f ? "1" : "0");
    }
  });
  return out;
}

namespace {

// A flag's list gives numbers instead of define names (HV_SETTING_ENUM).
bool namesDefines(std::string_view define) {
  return !define.empty() && !std::isdigit(static_cast<unsigned char>(define[0]));
}

}  // namespace

std::string settingValuesGlsl() {
  std::string out =
      "// GENERATED from the value lists of "
      "engine/scene/include/halfvec/scene/render_settings.hpp\n"
      "// (HV_SETTING_ENUM) by settingValuesGlsl(): do not edit; regenerate with\n"
      "//   build/shaders/hv_setting_values --out shaders/common/setting_values.glsl\n"
      "// The number of every value of an enumerated render setting that reaches a shader as a\n"
      "// define, for GLSL and C++ alike: the shaders compare HV_BRDF_D and the other defines "
      "against\n"
      "// these names, and the C++ enum's value is the same position in the same list. What each\n"
      "// value means is said at its list.\n"
      "#ifndef HV_SETTING_VALUES_GLSL\n"
      "#define HV_SETTING_VALUES_GLSL\n";
  std::set<std::string_view> done;
  forEachSetting([&](const auto& row) {
    using T = typename std::decay_t<decltype(row)>::Type;
    if constexpr (std::is_enum_v<T> && requires { EnumNames<T>::defines; }) {
      const auto& defines = EnumNames<T>::defines;
      if (!namesDefines(defines[0]) || !done.insert(defines[0]).second) return;
      out += "\n// " + std::string(row.key);
      if (row.info.define) out += " (" + std::string(row.info.define) + ")";
      out += ":";
      size_t line = out.size() - out.rfind('\n');
      for (size_t i = 0; i < defines.size(); ++i) {
        const std::string name(EnumNames<T>::names[i]);
        if (line + name.size() + 2 > 100) {
          out += "\n//";
          line = 2;
        }
        out += " " + name + (i + 1 < defines.size() ? "," : "");
        line += name.size() + 2;
      }
      out += "\n";
      for (size_t i = 0; i < defines.size(); ++i) {
        out += "#define " + std::string(defines[i]) + " " + std::to_string(i) + "\n";
      }
    }
  });
  out += "\n#endif  // HV_SETTING_VALUES_GLSL\n";
  return out;
}

}  // namespace hv
