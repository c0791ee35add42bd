// The trade report's shadow rows (halfvec/eval/trade.hpp): a scene with a shadowed light gets a
// row per other shadow filter and for half and twice its map size (within the setting's range);
// a scene without one gets none and says why.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "halfvec/eval/trade.hpp"
#include "halfvec/scene/primitives.hpp"

namespace {

hv::Scene shadowScene(bool shadows) {
  hv::Scene s;
  s.camera.position = {0.0f, 1.5f, 3.0f};
  s.camera.target = {0.0f, 0.4f, 0.0f};
  hv::Material m;
  hv::addMeshObject(s, hv::makePlane(6.0f, 6.0f), m, glm::vec3(0.0f));
  hv::addMeshObject(s, hv::makeSphere(0.5f, 32, 16), m, {0.0f, 0.5f, 0.0f});
  hv::Light l;
  l.type = hv::LightType::Sphere;
  l.position = {0.5f, 2.0f, 0.5f};
  l.radius = 0.2f;
  l.shadows = shadows;
  s.lights = {l};
  s.environment.kind = hv::EnvironmentKind::None;
  return s;
}

const hv::eval::TradeConfig* row(const hv::eval::TradePlan& p, const std::string& name) {
  for (const auto& c : p.configs) {
    if (c.name == name || std::find(c.aliases.begin(), c.aliases.end(), name) != c.aliases.end())
      return &c;
  }
  return nullptr;
}

}  // namespace

TEST(TradePlan, ShadowedLightsGetFilterAndMapSizeRows) {
  const hv::Scene s = shadowScene(true);
  const hv::eval::TradePlan p = hv::eval::tradePlan(s);
  for (const char* name : {"shadow_filter=hard", "shadow_filter=pcf", "shadow_map_size=512",
                           "shadow_map_size=2048", "shadow_resolution=half"}) {
    const hv::eval::TradeConfig* c = row(p, name);
    ASSERT_NE(c, nullptr) << name;
    EXPECT_EQ(c->group, "lights") << name;
  }
  EXPECT_EQ(row(p, "shadow_filter=hard")->settings.shadow_filter, hv::ShadowFilter::Hard);
  EXPECT_EQ(row(p, "shadow_map_size=512")->settings.shadow_map_size, 512);
  EXPECT_EQ(row(p, "shadow_map_size=2048")->settings.shadow_map_size, 2048);
  EXPECT_EQ(row(p, "shadow_resolution=half")->settings.shadow_resolution,
            hv::ShadowResolution::Half);
  EXPECT_EQ(row(p, "shadow_filter=pcss"), nullptr);  // the scene's own value: the scene row
  // At the range's top, only half.
  hv::Scene big = s;
  big.settings.shadow_map_size = 2048;
  const hv::eval::TradePlan pb = hv::eval::tradePlan(big);
  EXPECT_NE(row(pb, "shadow_map_size=1024"), nullptr);
  EXPECT_EQ(row(pb, "shadow_map_size=4096"), nullptr);
}

TEST(TradePlan, NoShadowRowsWithoutShadowedLights) {
  const hv::eval::TradePlan p = hv::eval::tradePlan(shadowScene(false));
  for (const auto& c : p.configs) EXPECT_EQ(c.name.rfind("shadow_", 0), std::string::npos);
  bool said = false;
  for (const std::string& why : p.skipped) {
    said = said || (why.find("shadow_map_size") != std::string::npos &&
                    why.find("no shadowed lights") != std::string::npos);
  }
  EXPECT_TRUE(said);
}
