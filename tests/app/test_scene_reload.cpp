// The viewer's hot reload (app/scene_reload.hpp) without a window: a scene edited into invalid
// JSON, or pointing at a missing HDR, reports the error and keeps the last good scene rendering.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "app/scene_reload.hpp"
#include "halfvec/platform/context.hpp"

namespace fs = std::filesystem;
using namespace hv;

namespace {

const char* kGood = R"({"camera": {"position": [0, 1, 4], "target": [0, 0, 0]},
 "objects": [{"primitive": "sphere", "radius": 0.8, "material": {"base_color": [0.9, 0.2, 0.1]}}],
 "lights": [{"type": "point", "position": [1, 2, 2], "intensity": 20}],
 "environment": {"type": "uniform", "color": [0.2, 0.2, 0.2], "cube_size": 16,
                 "prefilter_samples": 16}})";

void write(const fs::path& p, const std::string& text) {
  std::ofstream(p) << text;
  // Make sure the modification time moves even on coarse-grained file systems.
  fs::last_write_time(p, fs::last_write_time(p) + std::chrono::seconds(1));
}

ImageRGBf renderOnce(render::Renderer& r) {
  r.render(48, 32);
  return r.readHdr();
}

}  // namespace

TEST(SceneReload, BadEditsKeepTheLastGoodScene) {
  auto ctx = createHeadlessContext();
  const fs::path dir = fs::temp_directory_path() / "hv_reload_test";
  fs::create_directories(dir);
  const fs::path file = dir / "scene.json";
  write(file, kGood);

  render::Renderer renderer;
  app::SceneReloader reloader(file.string());
  reloader.attach(renderer);
  const ImageRGBf before = renderOnce(renderer);
  EXPECT_FALSE(reloader.poll()) << "unchanged file: nothing to do";

  // 1. Invalid JSON: the error names the file; the scene and the image stay as they were.
  std::string broken = kGood;
  broken.pop_back();  // drop the closing brace
  write(file, broken);
  EXPECT_FALSE(reloader.poll());
  EXPECT_NE(reloader.error().find(file.string()), std::string::npos) << reloader.error();
  EXPECT_EQ(reloader.scene().objects.size(), 1u);
  const ImageRGBf after_json = renderOnce(renderer);
  ASSERT_EQ(after_json.px.size(), before.px.size());
  for (size_t i = 0; i < before.px.size(); ++i) ASSERT_EQ(after_json.px[i], before.px[i]) << i;

  // 2. A missing HDR: the error names the missing file.
  std::string missing = kGood;
  missing.erase(missing.find(R"("environment")"));
  missing += R"("environment": {"type": "hdr", "path": "no_such_sky.hdr"}})";
  write(file, missing);
  EXPECT_FALSE(reloader.poll());
  EXPECT_NE(reloader.error().find("no_such_sky.hdr"), std::string::npos) << reloader.error();
  const ImageRGBf after_hdr = renderOnce(renderer);
  for (size_t i = 0; i < before.px.size(); ++i) ASSERT_EQ(after_hdr.px[i], before.px[i]) << i;

  // 3. A good edit loads, clears the error and changes the image.
  std::string edited = kGood;
  edited.replace(edited.find("0.9, 0.2, 0.1"), 13, "0.1, 0.2, 0.9");
  write(file, edited);
  EXPECT_TRUE(reloader.poll());
  EXPECT_TRUE(reloader.error().empty());
  const ImageRGBf after_good = renderOnce(renderer);
  size_t changed = 0;
  for (size_t i = 0; i < before.px.size(); ++i) changed += after_good.px[i] != before.px[i];
  EXPECT_GT(changed, before.px.size() / 10);
  fs::remove_all(dir);
}
