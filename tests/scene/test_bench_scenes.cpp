// samples/bench/floor_spheres_N_lights_R.json: the bench scenes docs/performance.md tabulates hold
// what their names say (N point lights of range R over the visible floor, a floor and nine
// spheres, no environment), so a table row and its file cannot drift apart.
#include <gtest/gtest.h>

#include <string>

#include "halfvec/scene/scene_loader.hpp"

using namespace hv;

TEST(BenchScenes, FloorAndNineSpheresAtEachLightCount) {
  const std::string dir = std::string(HV_SOURCE_DIR) + "/samples/bench/";
  for (int n : {4, 8, 16, 32, 256, 1024}) {
    for (const auto& [tag, range] : {std::pair{"5m", 5.0f}, std::pair{"1p5m", 1.5f}}) {
      const std::string file =
          dir + "floor_spheres_" + std::to_string(n) + "_lights_" + tag + ".json";
      SCOPED_TRACE(file);
      const Scene s = loadScene(file);
      EXPECT_EQ(s.environment.kind, EnvironmentKind::None);
      EXPECT_EQ(s.objects.size(), 10u);  // the floor and nine spheres
      ASSERT_EQ(s.lights.size(), size_t(n));
      for (const Light& l : s.lights) {
        EXPECT_EQ(l.type, LightType::Point);
        EXPECT_EQ(l.range, range);
        EXPECT_GE(l.position.y, 0.3f);
        EXPECT_LE(l.position.y, 1.5f);
        EXPECT_LE(std::abs(l.position.x), 6.0f);
      }
    }
  }
}
