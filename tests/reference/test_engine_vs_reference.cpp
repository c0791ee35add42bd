// First accuracy measurement: the engine's point light against the reference over the GPU's own
// G-buffer. Point lights are exact in both, so they must agree to the precision of the RGBA16F
// target (stated: 4e-3 relative, measured 2.6e-3 in tests/render/test_lights_gpu.cpp).
#include <gtest/gtest.h>

#include <memory>

#include "halfvec/platform/context.hpp"
#include "halfvec/reference/reference.hpp"
#include "halfvec/render/renderer.hpp"
#include "halfvec/scene/primitives.hpp"

using namespace hv;

namespace {

// A sphere over a floor of base color `base` under one point light (physical falloff), rendered
// at 64x48; every lit pixel of the engine within 4e-3 relative (+1e-5) of the reference.
void expectPointLightAgrees(glm::vec3 base) {
  auto ctx = createHeadlessContext();
  Scene s;
  s.camera.position = {0.0f, 2.0f, 3.0f};
  s.camera.target = {0.0f, 0.0f, 0.0f};
  Material m;
  m.base_color = base;
  m.roughness = 0.35f;
  m.metallic = 0.2f;
  addMeshObject(s, makeSphere(0.8f, 48, 24), m, {0.0f, 0.8f, 0.0f});
  addMeshObject(s, makePlane(6.0f, 6.0f), m, glm::vec3(0.0f));
  Light l;
  l.position = {1.0f, 2.0f, 1.0f};
  l.intensity = 5.0f;
  l.range = 8.0f;
  s.lights.push_back(l);
  s.environment.kind = EnvironmentKind::None;
  s.settings.falloff_plus_one = false;  // physical mode used for accuracy comparisons
  render::Renderer r;
  r.setScene(s);
  r.render(64, 48);
  const auto g = r.readGBuffer();
  const auto engine = r.readHdr();
  ReferenceOptions o;
  o.samples = 4;  // point lights are analytic: no noise
  const auto ref = renderReference(s, g, o);
  int lit = 0;
  for (size_t i = 0; i < engine.px.size(); ++i) {
    if (g.model[i] != static_cast<uint32_t>(ShadingModel::DefaultLit)) continue;
    ++lit;
    for (int k = 0; k < 3; ++k) {
      ASSERT_NEAR(engine.px[i][k], ref.image.px[i][k], 4e-3f * ref.image.px[i][k] + 1e-5f)
          << "pixel " << i;
    }
  }
  EXPECT_GT(lit, 1000);
}

}  // namespace

TEST(EngineVsReference, PointLightAgreesWithinPrecision) {
  expectPointLightAgrees({0.6f, 0.5f, 0.4f});
}

// Dark channels (0.08, 0.05): the reference reads the base color as the passes fetch it
// (Renderer::readGBuffer, gbuffer_decode.comp). Decoded with the exact sRGB curve instead, the
// engine was 0.65% brighter than the reference there on llvmpipe, whose decode differs from the
// curve by that much, beyond the point light's tolerance.
TEST(EngineVsReference, DarkBaseColorAgreesWithinPrecision) {
  expectPointLightAgrees({0.7f, 0.08f, 0.05f});
}
