#include "halfvec/scene/render_settings.hpp"

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
    }
  });
  return out;
}

}  // namespace hv
