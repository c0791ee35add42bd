// Blended surfaces (glTF alphaMode BLEND): the forward pass composites them back to front over the
// opaque image with their alpha as coverage, and lights them with the code the deferred passes run.
#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <iostream>

#include "render_fixture.hpp"

using namespace hv;

namespace {

constexpr int kSize = 64;

Material emitting(glm::vec3 emissive, float alpha, AlphaMode mode) {
  Material m;
  m.base_color = glm::vec3(0.0f);
  m.emissive = emissive;
  m.base_alpha = alpha;
  m.alpha_mode = mode;
  return m;
}

// Adds a horizontal square of side `size` at height y drawn with material `mat`.
void addPlane(Scene& s, int mat, float size, float y) {
  s.meshes.push_back(makePlane(size, size));
  s.meshes.back().material = mat;
  Object o;
  o.meshes = {int(s.meshes.size()) - 1};
  o.transform = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, y, 0.0f));
  s.objects.push_back(o);
}

// An opaque blue emitter (the floor of planeScene, 2 m below the camera) under a red layer (alpha
// 0.5) at 0.5 m and a green one (alpha 0.25) at 1 m; in the scene in `near_first` order or not.
// Black environment, no lights: each surface shows its emissive only.
Scene layers(bool near_first) {
  Scene s = planeScene(emitting({0.0f, 0.0f, 2.0f}, 1.0f, AlphaMode::Opaque));
  s.materials.push_back(emitting({4.0f, 0.0f, 0.0f}, 0.5f, AlphaMode::Blend));
  s.materials.push_back(emitting({0.0f, 4.0f, 0.0f}, 0.25f, AlphaMode::Blend));
  if (near_first) {
    addPlane(s, 2, 0.5f, 1.0f);
    addPlane(s, 1, 0.5f, 0.5f);
  } else {
    addPlane(s, 1, 0.5f, 0.5f);
    addPlane(s, 2, 0.5f, 1.0f);
  }
  return s;
}

glm::vec3 at(const ImageRGBf& img, int x, int y) {
  const auto& p = img.px[size_t(y) * img.width + x];
  return {p[0], p[1], p[2]};
}

}  // namespace

// Over the centre both layers cover the floor: green over red over blue whatever order the scene
// lists them in (the pass sorts them back to front); near the edge neither covers it. Tolerance:
// the RGBA16F target's rounding of each blend step (2^-11 relative) with margin.
TEST(BlendGpu, LayersCompositeBackToFrontInAnyOrder) {
  testContext();
  const glm::vec3 blue(0, 0, 2), red(4, 0, 0), green(0, 4, 0);
  const glm::vec3 expected = 0.25f * green + 0.75f * (0.5f * red + 0.5f * blue);
  for (bool near_first : {true, false}) {
    SCOPED_TRACE(near_first ? "near layer first in the scene" : "far layer first in the scene");
    Scene s = layers(near_first);
    render::Renderer r;
    r.setScene(s);
    const render::FrameStats stats = r.render(kSize, kSize);
    const ImageRGBf img = r.readHdr();
    const glm::vec3 c = at(img, kSize / 2, kSize / 2);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(c[k], expected[k], 2e-3 * (1.0 + expected[k]));
    const glm::vec3 e = at(img, 2, kSize / 2);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(e[k], blue[k], 1e-6);
    bool forward = false;
    for (const auto& [name, ms] : stats.passes) forward |= name == "forward";
    EXPECT_TRUE(forward);
    EXPECT_NE(r.variantKey().text().find("blend"), std::string::npos);
  }
}

// A scene without blended materials runs no forward pass and compiles none.
TEST(BlendGpu, OpaqueSceneHasNoForwardPass) {
  testContext();
  Scene s = planeScene(emitting({0.0f, 0.0f, 2.0f}, 1.0f, AlphaMode::Opaque));
  render::Renderer r;
  r.setScene(s);
  const render::FrameStats stats = r.render(kSize, kSize);
  for (const auto& [name, ms] : stats.passes) EXPECT_NE(name, "forward");
  EXPECT_FALSE(r.variantKey().blend);
  for (const auto& p : r.manifest().programs) EXPECT_EQ(p.name.find("forward"), std::string::npos);
}

// An edit in place (the viewer's material panel) that makes a material blended moves it to the
// forward pass: over the black background, alpha 0.5 halves its emissive.
TEST(BlendGpu, EditingAMaterialToBlendMovesItToTheForwardPass) {
  testContext();
  Scene s = planeScene(emitting({0.0f, 0.0f, 2.0f}, 1.0f, AlphaMode::Opaque));
  render::Renderer r;
  r.setScene(s);
  r.render(kSize, kSize);
  EXPECT_NEAR(at(r.readHdr(), kSize / 2, kSize / 2).z, 2.0f, 1e-3);
  s.materials[0].alpha_mode = AlphaMode::Blend;
  s.materials[0].base_alpha = 0.5f;
  r.updateMaterials();
  const render::FrameStats stats = r.render(kSize, kSize);
  EXPECT_NEAR(at(r.readHdr(), kSize / 2, kSize / 2).z, 1.0f, 1e-3);
  bool forward = false;
  for (const auto& [name, ms] : stats.passes) forward |= name == "forward";
  EXPECT_TRUE(forward);
}

namespace {

// A lit floor (point, sphere and tube lights, one of them shadowed, the procedural sky) drawn
// opaque, or blended with alpha 1: the same image up to the G-buffer's quantization.
Scene litFloor(AlphaMode mode, bool accurate) {
  Material m;
  m.base_color = {0.7f, 0.5f, 0.3f};
  m.metallic = 0.3f;
  m.roughness = 0.45f;
  m.alpha_mode = mode;
  Scene s = planeScene(m);
  s.environment.kind = EnvironmentKind::Sky;
  s.camera.position = {0.0f, 1.5f, 2.5f};
  s.camera.up = {0.0f, 1.0f, 0.0f};
  Light p;
  p.position = {0.5f, 0.6f, 0.2f};
  p.intensity = 3.0f;
  p.range = 4.0f;
  p.shadows = true;
  Light sp = p;
  sp.type = LightType::Sphere;
  sp.position = {-0.6f, 0.4f, -0.3f};
  sp.radius = 0.15f;
  sp.shadows = false;
  Light t = sp;
  t.type = LightType::Tube;
  t.position = {0.0f, 0.3f, 0.8f};
  t.radius = 0.05f;
  t.length = 0.8f;
  s.lights = {p, sp, t};
  if (accurate) {
    s.settings.sphere_specular = SphereSpecular::Ltc;
    s.settings.tube_specular = TubeSpecular::Ltc;
  }
  return s;
}

}  // namespace

// The forward pass shades with the deferred passes' code: a floor blended with alpha 1 matches the
// same floor drawn opaque. What differs is the G-buffer's storage (8-bit sRGB base colour, 16-bit
// roughness and octahedral normal): within 1% of the lit pixels' mean radiance on average, 2% at
// the worst pixel.
TEST(BlendGpu, AlphaOneShadesAsTheDeferredPasses) {
  testContext();
  for (bool accurate : {false, true}) {
    SCOPED_TRACE(accurate ? "ltc spheres and tubes" : "representative point");
    ImageRGBf img[2];
    int i = 0;
    for (AlphaMode mode : {AlphaMode::Opaque, AlphaMode::Blend}) {
      Scene s = litFloor(mode, accurate);
      render::Renderer r;
      r.setScene(s);
      r.render(kSize, kSize);
      img[i++] = r.readHdr();
    }
    double sum = 0.0, diff = 0.0, worst = 0.0;
    int n = 0;
    for (int y = kSize / 2; y < kSize; ++y) {  // the floor fills the lower half
      for (int x = 0; x < kSize; ++x) {
        const glm::vec3 a = at(img[0], x, y), b = at(img[1], x, y);
        const double la = a.x + a.y + a.z, d = glm::length(a - b);
        sum += la;
        diff += d;
        worst = std::max(worst, d);
        ++n;
      }
    }
    const double mean = sum / n;
    ASSERT_GT(mean, 0.05);  // lit
    EXPECT_LT(diff / n, 0.01 * mean);
    EXPECT_LT(worst, 0.02 * mean);
    std::cout << "[ measured ] alpha-1 blend vs opaque: mean |diff| " << diff / n / mean
              << " of the mean, worst " << worst / mean << "\n";
  }
}
