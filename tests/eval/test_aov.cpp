// Engine AOVs (halfvec/eval/engine_aov.hpp): the four per-term images of the engine.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "halfvec/eval/engine_aov.hpp"
#include "halfvec/image/image.hpp"
#include "halfvec/platform/context.hpp"
#include "halfvec/render/renderer.hpp"
#include "halfvec/scene/primitives.hpp"

namespace fs = std::filesystem;
using namespace hv;

namespace {

// A sphere (emissive, default lit) on a floor, one light of each type and a uniform environment:
// every term is non-zero somewhere.
Scene aovScene() {
  Scene s;
  s.camera.position = {0.0f, 2.0f, 3.5f};
  s.camera.target = {0.0f, 0.3f, 0.0f};
  Material m;
  m.base_color = {0.7f, 0.5f, 0.3f};
  m.roughness = 0.3f;
  m.metallic = 0.3f;
  m.emissive = {0.2f, 0.1f, 0.05f};
  Material floor;
  floor.roughness = 0.6f;
  addMeshObject(s, makeSphere(0.7f, 32, 16), m, {0.0f, 0.7f, 0.0f});
  addMeshObject(s, makePlane(5.0f, 5.0f), floor, glm::vec3(0.0f));
  Light p;
  p.position = {1.0f, 2.0f, 1.0f};
  p.intensity = 4.0f;
  Light sp = p;
  sp.type = LightType::Sphere;
  sp.position = {-1.2f, 1.5f, 0.5f};
  sp.radius = 0.3f;
  Light tu = p;
  tu.type = LightType::Tube;
  tu.position = {0.0f, 2.0f, -1.0f};
  tu.radius = 0.05f;
  tu.length = 1.5f;
  s.lights = {p, sp, tu};
  s.environment.kind = EnvironmentKind::Uniform;
  s.environment.color = glm::vec3(0.3f);
  s.environment.cube_size = 32;
  s.environment.prefilter_samples = 32;
  return s;
}

}  // namespace

// The four AOVs plus the emissive sum to the full HDR image on lit pixels, to the precision of the
// RGBA16F target: each of the five renders rounds to 2^-11 relative, so 4e-3 of the full value
// (+ 1e-4 absolute) bounds the difference. Off lit pixels every AOV is 0; each AOV is non-zero on
// many pixels; the scene is left as it was.
TEST(EngineAov, AovsPlusEmissiveSumToTheFullImage) {
  auto ctx = createHeadlessContext();
  Scene s = aovScene();
  render::Renderer r;
  r.setScene(s);
  r.render(96, 72);
  const ImageRGBf full = r.readHdr();
  const auto aov = eval::renderEngineAovs(r, 96, 72);
  EXPECT_EQ(s.settings.direct_terms, 3);
  EXPECT_EQ(s.settings.ambient_terms, 3);
  const auto g = r.readGBuffer();
  int lit = 0, nonzero[4] = {0, 0, 0, 0};
  for (size_t i = 0; i < full.px.size(); ++i) {
    const bool is_lit = g.model[i] == static_cast<uint32_t>(ShadingModel::DefaultLit);
    glm::vec3 sum(0.0f);
    for (int k = 0; k < 4; ++k) {
      sum += aov[size_t(k)].px[i];
      if (!is_lit) {
        ASSERT_EQ(aov[size_t(k)].px[i], glm::vec3(0.0f)) << "pixel " << i << " aov " << k;
      } else if (aov[size_t(k)].px[i].x > 1e-3f) {
        ++nonzero[k];
      }
    }
    if (!is_lit) continue;
    ++lit;
    // Emissive of the pixel's material: the sphere's or 0 (floor), told apart by roughness.
    const glm::vec3 emissive =
        std::abs(g.roughness[i] - 0.3f) < 0.01f ? s.materials[0].emissive : glm::vec3(0.0f);
    for (int c = 0; c < 3; ++c) {
      ASSERT_NEAR(sum[c] + emissive[c], full.px[i][c], 4e-3f * full.px[i][c] + 1e-4f)
          << "pixel " << i << " channel " << c;
    }
  }
  EXPECT_GT(lit, 2000);
  for (int k = 0; k < 4; ++k) EXPECT_GT(nonzero[k], 200) << "aov " << k;
}
