// Scene save keeps the user's file (halfvec/scene/scene_writer.hpp): numbers as typed, only what
// changed written, every other byte kept; round trip on every sample scene.
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "halfvec/scene/scene_error.hpp"
#include "halfvec/scene/scene_loader.hpp"
#include "halfvec/scene/scene_writer.hpp"

namespace fs = std::filesystem;
using namespace hv;

namespace {

std::string readText(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

size_t lines(const std::string& s) {
  return size_t(std::count(s.begin(), s.end(), '\n'));
}

// Lines of `a` and `b` that differ, compared position by position (same line count expected).
size_t changedLines(const std::string& a, const std::string& b) {
  std::istringstream x(a), y(b);
  std::string la, lb;
  size_t n = 0;
  while (std::getline(x, la) && std::getline(y, lb)) n += la != lb;
  return n;
}

fs::path tmpDir() {
  const fs::path d = fs::temp_directory_path() / ("hv_scene_writer_" + std::to_string(getpid()));
  fs::create_directories(d);
  return d;
}

std::vector<fs::path> samples() {
  std::vector<fs::path> out;
  for (const auto& e : fs::directory_iterator(fs::path(HV_SOURCE_DIR) / "samples" / "scenes")) {
    if (e.path().extension() == ".json") out.push_back(e.path());
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace

TEST(SceneWriter, NumbersAsAUserWouldTypeThem) {
  EXPECT_EQ(formatNumber(double(0.7f)), "0.7");
  EXPECT_EQ(formatNumber(double(0.699999988079071f)), "0.7");
  EXPECT_EQ(formatNumber(2.0), "2");
  EXPECT_EQ(formatNumber(-0.0), "0");
  EXPECT_EQ(formatNumber(double(1.0f / 3.0f)), "0.33333334");  // float32 shortest round trip
  EXPECT_EQ(formatNumber(0.1), "0.1");
  EXPECT_EQ(formatNumber(double(1e-5f)), "1e-05");
  for (float f : {0.7f, 1.0f / 3.0f, 123.456f, 1e-7f, 65504.0f}) {
    EXPECT_EQ(std::stof(formatNumber(double(f))), f) << f;  // reads back as the same float
  }
}

TEST(SceneWriter, FormatsVectorsOnOneLine) {
  nlohmann::ordered_json j;
  j["camera"] = {{"position", {0.0f, 2.2f, 6.5f}}, {"fov_y_deg", 45}};
  j["lights"] = nlohmann::ordered_json::array(
      {{{"type", "point"}, {"position", {0, 2.5f, 2}}, {"intensity", 8}}});
  const std::string text = formatSceneJson(j);
  EXPECT_NE(text.find("\"position\": [0, 2.2, 6.5]"), std::string::npos) << text;
  EXPECT_NE(text.find("{\"type\": \"point\", \"position\": [0, 2.5, 2], \"intensity\": 8}"),
            std::string::npos)
      << text;
  const auto back = nlohmann::json::parse(text);
  EXPECT_EQ(back["camera"]["position"][1].get<float>(), 2.2f);
  EXPECT_EQ(back["lights"][0]["type"], "point");
}

TEST(SceneWriter, EditsReplaceInsertAndEraseInPlace) {
  const std::string text = R"({
  "camera": {"position": [0, 1, 5], "fov_y_deg": 45},
  "materials": {
    "red": {"base_color": [0.7, 0.05, 0.05], "roughness": 0.3}
  },
  "settings": {"exposure": 1.0}
}
)";
  const std::string out =
      applyJsonEdits(text,
                     {{"/materials/red/roughness", 0.5f, false},
                      {"/materials/red/metallic", 1, false},    // new key in a one-line object
                      {"/settings/tone_map", "aces", false},    // new key
                      {"/environment/type", "uniform", false},  // missing parent: created
                      {"/camera/fov_y_deg", nullptr, true}},    // erased
                     "test.json");
  EXPECT_NE(
      out.find(R"("red": {"base_color": [0.7, 0.05, 0.05], "roughness": 0.5, "metallic": 1})"),
      std::string::npos)
      << out;
  EXPECT_NE(out.find(R"("settings": {"exposure": 1.0, "tone_map": "aces"})"), std::string::npos)
      << out;
  EXPECT_NE(out.find("\n  \"environment\": {\"type\": \"uniform\"}\n"), std::string::npos) << out;
  EXPECT_NE(out.find(R"("camera": {"position": [0, 1, 5]})"), std::string::npos) << out;
  EXPECT_TRUE(nlohmann::json::accept(out));
  EXPECT_THROW(applyJsonEdits("{\"a\": [1, 2]}", {{"/a/5/x", 1, false}}, "t.json"), SceneError);
  EXPECT_THROW(applyJsonEdits("{\"a\": ", {{"/a", 1, false}}, "t.json"), SceneError);
}

// Erasing cuts the member with one separator: the one before it, or after it for the first
// member; the only member leaves its braces empty. Arrays alike.
TEST(SceneWriter, EraseKeepsTheSeparatorsRight) {
  auto erase = [](const std::string& text, const char* pointer) {
    return applyJsonEdits(text, {{pointer, nullptr, true}}, "t.json");
  };
  EXPECT_EQ(erase(R"({"a": 1, "b": 2, "c": 3})", "/a"), R"({"b": 2, "c": 3})");
  EXPECT_EQ(erase(R"({"a": 1, "b": 2, "c": 3})", "/b"), R"({"a": 1, "c": 3})");
  EXPECT_EQ(erase(R"({"a": 1, "b": 2, "c": 3})", "/c"), R"({"a": 1, "b": 2})");
  EXPECT_EQ(erase(R"({"s": {"x": 1}})", "/s/x"), R"({"s": {}})");
  EXPECT_EQ(erase(R"({"l": [1, 2, 3]})", "/l/1"), R"({"l": [1, 3]})");
  EXPECT_EQ(erase(R"({"l": [1, 2, 3]})", "/l/0"), R"({"l": [2, 3]})");
  EXPECT_EQ(erase(R"({"a": 1})", "/missing"), R"({"a": 1})");  // nothing to remove
}

// A key added to an empty object becomes its only member, with any missing objects below it;
// a replaced value keeps the text around it.
TEST(SceneWriter, InsertIntoAnEmptyObjectAndReplace) {
  auto set = [](const std::string& text, const char* pointer, const nlohmann::ordered_json& v) {
    return applyJsonEdits(text, {{pointer, v, false}}, "t.json");
  };
  EXPECT_EQ(set(R"({"s": {}})", "/s/k", 1), R"({"s": {"k": 1}})");
  EXPECT_EQ(set(R"({"s": {}})", "/s/a/b", 2), R"({"s": {"a": {"b": 2}}})");
  EXPECT_EQ(set(R"({"s": {"k": 1}, "t": 0})", "/s/k", "x"), R"({"s": {"k": "x"}, "t": 0})");
  EXPECT_EQ(set(R"({"s": {"k": 1}})", "/s", nlohmann::ordered_json::array({1, 2})),
            R"({"s": [1, 2]})");
  EXPECT_THROW(set(R"({"s": 1})", "", 2), SceneError);  // the whole document
}

// Every sample: saved without edits the file is byte-identical; with a material, a light, the
// environment and a setting edited, only those values change, and it loads as the edited scene.
TEST(SceneWriter, RoundTripOnEverySample) {
  const fs::path dir = tmpDir();
  int tested = 0;
  for (const fs::path& sample : samples()) {
    SCOPED_TRACE(sample.filename().string());
    const fs::path path = dir / sample.filename();
    fs::copy_file(sample, path, fs::copy_options::overwrite_existing);
    const std::string original = readText(path);
    const Scene loaded = loadScene(path.string(), {}, nullptr);
    std::vector<std::string> warnings;
    EXPECT_EQ(saveSceneEdits(path.string(), loaded, loaded), 0u);
    EXPECT_EQ(readText(path), original);

    Scene edited = loaded;
    int mat = -1;
    for (size_t i = 0; i < edited.materials.size() && mat < 0; ++i) {
      if (!edited.materials[i].source.empty()) mat = int(i);
    }
    if (mat >= 0) edited.materials[size_t(mat)].roughness = 0.35f;
    const bool explicit_light =
        !edited.lights.empty() && readText(path).find("\"lights\"") != std::string::npos;
    if (explicit_light) edited.lights[0].intensity = 12.5f;
    edited.environment.intensity = 0.8f;
    edited.settings.tone_map = ToneMap::PbrNeutral;
    const size_t n = saveSceneEdits(path.string(), loaded, edited);
    EXPECT_GE(n, 2u);
    const std::string saved = readText(path);
    std::printf("%-20s %zu edits: %zu lines -> %zu lines, %zu lines differ\n",
                sample.filename().string().c_str(), n, lines(original), lines(saved),
                lines(saved) == lines(original) ? changedLines(original, saved) : size_t(0));
    // Two keys at most are new (tone_map, intensity may be absent); the rest are changed values.
    EXPECT_LE(lines(saved), lines(original) + 2);
    if (lines(saved) == lines(original)) {
      EXPECT_LE(changedLines(original, saved), n);
    }

    const Scene back = loadScene(path.string(), {}, nullptr);
    if (mat >= 0) {
      EXPECT_EQ(back.materials[size_t(mat)].roughness, 0.35f);
    }
    if (explicit_light) {
      EXPECT_EQ(back.lights[0].intensity, 12.5f);
    }
    EXPECT_EQ(back.lights.size(), loaded.lights.size());
    EXPECT_EQ(back.environment.intensity, 0.8f);
    EXPECT_EQ(back.settings.tone_map, ToneMap::PbrNeutral);
    EXPECT_EQ(back.settings.exposure, loaded.settings.exposure);
    EXPECT_EQ(back.camera.position, loaded.camera.position);
    ++tested;
  }
  EXPECT_GE(tested, 6);
  fs::remove_all(dir);
}

TEST(SceneWriter, AddedLightRewritesTheListOneLightPerLine) {
  const fs::path dir = tmpDir();
  const fs::path path = dir / "default.json";
  fs::copy_file(fs::path(HV_SOURCE_DIR) / "samples/scenes/default.json", path,
                fs::copy_options::overwrite_existing);
  const std::string original = readText(path);
  const Scene loaded = loadScene(path.string());
  Scene edited = loaded;
  Light l;
  l.type = LightType::Sphere;
  l.position = {1.0f, 2.0f, 0.5f};
  l.radius = 0.15f;
  edited.lights.push_back(l);
  saveSceneEdits(path.string(), loaded, edited);
  const std::string saved = readText(path);
  EXPECT_LE(lines(saved), lines(original) + edited.lights.size() + 2);
  EXPECT_NE(
      saved.find(
          R"({"type": "sphere", "position": [1, 2, 0.5], "color": [1, 1, 1], "intensity": 10, "radius": 0.15, "range": 10})"),
      std::string::npos)
      << saved;
  const Scene back = loadScene(path.string());
  ASSERT_EQ(back.lights.size(), loaded.lights.size() + 1);
  EXPECT_EQ(back.lights.back().position, l.position);
  fs::remove_all(dir);
}

TEST(SceneWriter, GeneratedLightsAreFoldedInWhenTheListChanges) {
  const fs::path dir = tmpDir();
  const fs::path path = dir / "gen.json";
  std::ofstream(path) << R"({"light_generators": [{"count": 5, "seed": 3}]})"
                      << "\n";
  const Scene loaded = loadScene(path.string());
  ASSERT_EQ(loaded.lights.size(), 5u);
  Scene edited = loaded;
  edited.lights.erase(edited.lights.begin());
  saveSceneEdits(path.string(), loaded, edited);
  const Scene back = loadScene(path.string());
  ASSERT_EQ(back.lights.size(), 4u);
  EXPECT_EQ(back.lights[0].position, loaded.lights[1].position);
  EXPECT_EQ(readText(path).find("light_generators"), std::string::npos);
  fs::remove_all(dir);
}

// A coat given to a material in the viewer is saved as its two keys and loads back as a
// clear_coat material; taking it off (weight 0) loads back as default_lit.
TEST(SceneWriter, ClearCoatEditsRoundTrip) {
  const fs::path dir = tmpDir();
  const fs::path path = dir / "coat.json";
  {
    std::ofstream f(path);
    f << R"({"materials": {"red": {"base_color": [0.7, 0.05, 0.05], "roughness": 0.5}},
 "objects": [{"primitive": "sphere", "material": "red"}],
 "lights": [{"type": "point", "position": [0, 2, 2]}]})";
  }
  const Scene loaded = loadScene(path.string(), {}, nullptr);
  Scene edited = loaded;
  Material& m = edited.materials.at(size_t(edited.meshes.at(0).material));
  m.clearcoat = 0.75f;
  m.clearcoat_roughness = 0.05f;
  m.model = ShadingModel::ClearCoat;
  EXPECT_GE(saveSceneEdits(path.string(), loaded, edited), 2u);
  const Scene back = loadScene(path.string(), {}, nullptr);
  const Material& b = back.materials.at(size_t(back.meshes.at(0).material));
  EXPECT_EQ(b.model, ShadingModel::ClearCoat);
  EXPECT_EQ(b.clearcoat, 0.75f);
  EXPECT_EQ(b.clearcoat_roughness, 0.05f);
  Scene off = back;
  Material& o = off.materials.at(size_t(off.meshes.at(0).material));
  o.clearcoat = 0.0f;
  o.model = ShadingModel::DefaultLit;
  saveSceneEdits(path.string(), back, off);
  const Scene again = loadScene(path.string(), {}, nullptr);
  EXPECT_EQ(again.materials.at(size_t(again.meshes.at(0).material)).model,
            ShadingModel::DefaultLit);
  fs::remove_all(dir);
}
