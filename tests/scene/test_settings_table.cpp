// The settings table (halfvec/scene/render_settings.hpp) is the one description of every render
// setting: each row must load from its key, be written back at its path, and give its define the
// value the shaders compare with (setting_values.glsl, generated from the table), for every value
// of its type.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <fstream>
#include <iterator>
#include <string>
#include <type_traits>

#include <nlohmann/json.hpp>

#include "halfvec/scene/enums.hpp"
#include "halfvec/scene/scene_error.hpp"
#include "halfvec/scene/scene_loader.hpp"
#include "halfvec/scene/scene_writer.hpp"

using namespace hv;

namespace {

// The JSON of `value` under the row's key path inside "settings".
nlohmann::json sceneWith(const std::string& key, const nlohmann::json& value) {
  nlohmann::json settings = nlohmann::json::object();
  const size_t dot = key.find('.');
  if (dot == std::string::npos) {
    settings[key] = value;
  } else {
    settings[key.substr(0, dot)][key.substr(dot + 1)] = value;
  }
  return {{"settings", settings}};
}

// A value of the row's type other than its default, as the scene file writes it.
template <class T>
std::pair<T, nlohmann::json> otherValue(const SettingRow<T>& row) {
  if constexpr (std::is_same_v<T, bool>) {
    return {!row.default_value, !row.default_value};
  } else if constexpr (std::is_same_v<T, int>) {
    const int v = row.default_value == int(row.info.hi) ? int(row.info.lo) : int(row.info.hi);
    return {v, v};
  } else if constexpr (std::is_same_v<T, float>) {
    // Twice the default, or half the range's top for a default of 0 (max_error: no budget).
    const float v = row.default_value != 0.0f ? row.default_value * 2.0f : float(row.info.hi) / 2;
    return {v, v};
  } else {
    const T v = T((static_cast<int>(row.default_value) + 1) % int(enumNames<T>().size()));
    return {v, std::string(toString(v))};
  }
}

TEST(SettingsTable, EveryRowLoadsFromItsKey) {
  int rows = 0;
  forEachSetting([&](const auto& row) {
    ++rows;
    const auto [value, json] = otherValue(row);
    const Scene s = parseScene(sceneWith(row.key, json), "settings.json");
    EXPECT_EQ(s.settings.*row.member, value) << row.key;
    EXPECT_EQ(RenderSettings{}.*row.member, row.default_value) << row.key;
    // Everything else keeps its default.
    RenderSettings expected;
    expected.*row.member = value;
    EXPECT_TRUE(s.settings == expected) << row.key;
  });
  EXPECT_GE(rows, 20);
}

TEST(SettingsTable, EveryRowIsWrittenBackAtItsPath) {
  const std::string text = "{\n  \"settings\": {\"brdf\": {}}\n}\n";
  const Scene loaded = loadSceneFromString(text, "settings.json");
  forEachSetting([&](const auto& row) {
    Scene edited = loaded;
    const auto [value, json] = otherValue(row);
    edited.settings.*row.member = value;
    const auto edits = sceneEdits(text, loaded, edited, false, "settings.json");
    ASSERT_EQ(edits.size(), 1u) << row.key;
    std::string path = std::string("/settings/") + row.key;
    std::replace(path.begin(), path.end(), '.', '/');
    EXPECT_EQ(edits[0].pointer, path);
    EXPECT_EQ(edits[0].value.dump(), json.dump()) << row.key;
    // And the edited file loads to the edited settings.
    const Scene again = loadSceneFromString(applyJsonEdits(text, edits, "settings.json"), "s.json");
    EXPECT_EQ(again.settings.*row.member, value) << row.key;
  });
}

TEST(SettingsTable, EveryValueReachesItsDefine) {
  int defines = 0;
  forEachSetting([&](const auto& row) {
    using T = typename std::decay_t<decltype(row)>::Type;
    if (!row.info.define) return;
    ++defines;
    auto defineOf = [&](const RenderSettings& s) {
      for (const auto& [name, value] : settingDefines(s, row.info.pass)) {
        if (name == row.info.define) return value;
      }
      return std::string("missing");
    };
    RenderSettings s;
    if constexpr (std::is_same_v<T, bool>) {
      for (bool b : {false, true}) {
        s.*row.member = b;
        EXPECT_EQ(defineOf(s), b ? "1" : "0") << row.key;
      }
    } else if constexpr (std::is_enum_v<T>) {
      // Names are indexed by value (enums.hpp), so every named value is the define's number.
      for (size_t i = 0; i < enumNames<T>().size(); ++i) {
        s.*row.member = *fromString<T>(enumNames<T>()[i]);
        EXPECT_EQ(defineOf(s), std::to_string(i)) << row.key << " = " << enumNames<T>()[i];
      }
    } else if constexpr (std::is_same_v<T, int>) {
      for (int v : {int(row.info.lo), int(row.info.hi)}) {
        s.*row.member = v;
        EXPECT_EQ(defineOf(s), std::to_string(v)) << row.key;
      }
    } else if constexpr (std::is_same_v<T, float>) {
      // A float switches its code on where it is not 0; its value is a uniform.
      for (float v : {0.0f, float(row.info.hi), 1e-6f}) {
        s.*row.member = v;
        EXPECT_EQ(defineOf(s), v != 0.0f ? "1" : "0") << row.key << " = " << v;
      }
    } else {
      ADD_FAILURE() << row.key << ": a define needs a bool, an integer, a float or an enum";
    }
  });
  EXPECT_GE(defines, 18);
}

// The shaders (and the GLSL headers compiled as C++) read the committed file; it must be what the
// value lists give, so that a value's define is its enum's number. The build checks it too
// (hv_setting_values --check); this names the first line that differs.
TEST(SettingsTable, ShaderValuesAreGeneratedFromTheLists) {
  const std::string path = std::string(HV_SOURCE_DIR) + "/shaders/common/setting_values.glsl";
  std::ifstream in(path, std::ios::binary);
  ASSERT_TRUE(in) << path;
  const std::string committed{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  const std::string generated = settingValuesGlsl();
  if (committed == generated) return;
  size_t at = 0;
  while (at < committed.size() && at < generated.size() && committed[at] == generated[at]) ++at;
  const size_t line =
      committed.rfind('\n', at) == std::string::npos ? 0 : committed.rfind('\n', at) + 1;
  ADD_FAILURE() << path << " is stale at \""
                << committed.substr(line, committed.find('\n', line) - line) << "\": expected \""
                << generated.substr(line, generated.find('\n', line) - line)
                << "\"; regenerate with build/shaders/hv_setting_values --out " << path;
}

// Every enumerated row's values name a define each, or are a flag's numbers (0, 1, ...).
TEST(SettingsTable, EnumListsNameDefinesOrNumbers) {
  const std::string generated = settingValuesGlsl();
  int lists = 0;
  forEachSetting([&](const auto& row) {
    using T = typename std::decay_t<decltype(row)>::Type;
    if constexpr (std::is_enum_v<T> && requires { EnumNames<T>::defines; }) {
      ++lists;
      const auto& defines = EnumNames<T>::defines;
      ASSERT_EQ(defines.size(), EnumNames<T>::names.size()) << row.key;
      const bool numbers = std::isdigit(static_cast<unsigned char>(defines[0][0]));
      for (size_t i = 0; i < defines.size(); ++i) {
        if (numbers) {
          EXPECT_EQ(defines[i], std::to_string(i)) << row.key;
        } else {
          EXPECT_TRUE(defines[i].starts_with("HV_")) << row.key << ": " << defines[i];
          EXPECT_NE(
              generated.find("#define " + std::string(defines[i]) + " " + std::to_string(i) + "\n"),
              std::string::npos)
              << defines[i];
        }
      }
    }
  });
  EXPECT_GE(lists, 15);
}

TEST(SettingsTable, UnknownKeyNamesTheTablesKeys) {
  try {
    parseScene(nlohmann::json::parse(R"({"settings": {"sphere_specularr": "ltc"}})"), "s.json");
    FAIL() << "accepted an unknown key";
  } catch (const SceneError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("/settings/sphere_specularr"), std::string::npos) << m;
    EXPECT_NE(m.find("sphere_specular"), std::string::npos) << m;
    forEachSetting([&](const auto& row) {
      const std::string key = row.key;
      EXPECT_NE(m.find('"' + key.substr(0, key.find('.')) + '"'), std::string::npos) << key;
    });
  }
  EXPECT_THROW(parseScene(nlohmann::json::parse(R"({"settings": {"brdf": {"x": 1}}})"), "s.json"),
               SceneError);
}

}  // namespace
