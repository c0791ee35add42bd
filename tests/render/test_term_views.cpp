// Per-term debug views (DebugView::DirectDiffuse .. Emissive): each renders only its term, so
// over the pixels of surfaces the four light terms plus the emissive view add up to the normal
// frame; background pixels are black; a metal has no diffuse; the views are tone-mapped like
// the normal image.
#include <cmath>
#include <iostream>

#include <glm/gtc/matrix_transform.hpp>

#include "render_fixture.hpp"
#include "halfvec/shading/shading.hpp"

using namespace hv;

namespace {

constexpr int kW = 96, kH = 64;

// A dielectric floor (material 0), a metal sphere (1), an emissive lit box (2) and an unlit
// emissive box (3) under a point and a sphere light and a uniform environment; the top rows
// show the background beyond the floor.
Scene termScene() {
  Scene s;
  s.camera.position = {0.0f, 1.5f, 5.0f};
  s.camera.target = {0.0f, 0.5f, 0.0f};
  s.camera.fov_y_deg = 45.0f;
  Material floor;
  floor.name = "floor";
  floor.base_color = glm::vec3(0.7f);
  floor.roughness = 0.6f;
  Material metal;
  metal.name = "metal";
  metal.base_color = {0.95f, 0.7f, 0.3f};
  metal.metallic = 1.0f;
  metal.roughness = 0.35f;
  Material glow;
  glow.name = "glow";
  glow.base_color = glm::vec3(0.5f);
  glow.emissive = {1.5f, 0.6f, 0.2f};
  Material unlit;
  unlit.name = "unlit";
  unlit.model = ShadingModel::Unlit;
  unlit.emissive = {0.2f, 0.8f, 0.3f};
  s.materials = {floor, metal, glow, unlit};
  const Mesh meshes[] = {makePlane(8.0f, 8.0f), makeSphere(0.7f, 48, 24), makeBox(glm::vec3(0.4f)),
                         makeBox(glm::vec3(0.25f))};
  const glm::vec3 at[] = {
      {0.0f, 0.0f, 0.0f}, {-0.9f, 0.7f, 0.0f}, {0.9f, 0.4f, 0.0f}, {0.1f, 0.25f, 1.3f}};
  for (int i = 0; i < 4; ++i) {
    s.meshes.push_back(meshes[i]);
    s.meshes.back().material = i;
    Object o;
    o.meshes = {i};
    o.transform = glm::translate(glm::mat4(1.0f), at[i]);
    s.objects.push_back(o);
  }
  Light point;
  point.position = {0.0f, 2.5f, 2.0f};
  point.intensity = 20.0f;
  Light sphere;
  sphere.type = LightType::Sphere;
  sphere.position = {-2.0f, 1.5f, 1.0f};
  sphere.radius = 0.2f;
  sphere.intensity = 15.0f;
  s.lights = {point, sphere};
  s.environment.kind = EnvironmentKind::Uniform;
  s.environment.color = {0.25f, 0.3f, 0.35f};
  s.environment.cube_size = 32;
  s.environment.prefilter_samples = 64;
  s.settings.dither = false;
  return s;
}

constexpr render::DebugView kTerms[] = {
    render::DebugView::DirectDiffuse, render::DebugView::DirectSpecular,
    render::DebugView::AmbientDiffuse, render::DebugView::AmbientSpecular,
    render::DebugView::Emissive};

}  // namespace

TEST(TermViews, NamesRoundTrip) {
  for (size_t i = 0; i < render::kDebugViewCount; ++i) {
    const auto v = render::DebugView(i);
    EXPECT_EQ(render::debugViewFromString(render::toString(v)), v);
  }
  EXPECT_EQ(render::debugViewFromString("ambient_specular"), render::DebugView::AmbientSpecular);
  EXPECT_FALSE(render::termView(render::DebugView::Normal));
  EXPECT_EQ(render::termView(render::DebugView::DirectSpecular), (render::TermView{2, 0, false}));
}

TEST(TermViews, SumToTheFrameAndShowOnlyTheirTerm) {
  testContext();
  Scene scene = termScene();
  render::Renderer r;
  r.setScene(scene);
  r.render(kW, kH);
  const ImageRGBf full = r.readHdr();
  const GBufferReadback g = r.readGBuffer();
  std::vector<ImageRGBf> term;
  for (render::DebugView v : kTerms) {
    r.render(kW, kH, v);
    term.push_back(r.readHdr());
    // Tone-mapped like the normal image: the 8-bit output is outputTransform of this HDR (no
    // dither; exposure 1; default Reinhard + gamma 2.2) to within 8-bit rounding.
    const ImageRGBA8 ldr = r.readLdr();
    int off = 0;
    for (size_t i = 0; i < term.back().px.size(); ++i) {
      const glm::vec3 want = glsl::outputTransform(term.back().px[i]) * 255.0f;
      for (int c = 0; c < 3; ++c)
        off += std::abs(float(ldr.px[4 * i + size_t(c)]) - want[c]) > 1.01f;
    }
    EXPECT_EQ(off, 0) << render::toString(v) << ": channels off the tone curve";
  }
  enum { DD, DS, AD, AS, EM };

  // HDR is RGBA16F: every stored value is rounded to 11 significant bits (relative 4.9e-4), the
  // full frame up to three times (G-buffer, light, ambient pass), each term once or twice.
  const float kRel = 3e-3f, kAbs = 1e-4f;
  int surface = 0, background = 0, bad_sum = 0, bad_background = 0;
  int metal = 0, metal_diffuse = 0, metal_no_ambient_spec = 0, metal_direct_spec = 0;
  int floor_px = 0, floor_no_ambient_diffuse = 0, floor_direct_diffuse = 0;
  int unlit = 0, unlit_lit = 0, glow = 0, bad_glow = 0, emissive_elsewhere = 0;
  float worst = 0.0f;
  for (size_t i = 0; i < full.px.size(); ++i) {
    const glm::vec3 f = full.px[i];
    if (g.model[i] == uint32_t(ShadingModel::Background)) {
      ++background;
      for (const auto& t : term) bad_background += t.px[i] != glm::vec3(0.0f);
      EXPECT_GT(f.b, 0.3f) << "the normal frame shows the environment";
      continue;
    }
    ++surface;
    glm::vec3 sum(0.0f);
    for (const auto& t : term) sum += t.px[i];
    for (int c = 0; c < 3; ++c) {
      const float err = std::abs(sum[c] - f[c]);
      worst = std::max(worst, err / std::max(f[c], 1e-3f));
      bad_sum += err > kRel * f[c] + kAbs;
    }
    const glm::vec3 em = term[EM].px[i];
    if (g.model[i] == uint32_t(ShadingModel::Unlit)) {
      ++unlit;
      for (int k : {DD, DS, AD, AS}) unlit_lit += term[size_t(k)].px[i] != glm::vec3(0.0f);
    } else if (g.metallic[i] > 0.99f) {
      ++metal;
      metal_diffuse += term[DD].px[i] != glm::vec3(0.0f) || term[AD].px[i] != glm::vec3(0.0f);
      metal_no_ambient_spec += !(term[AS].px[i].r > 0.0f);
      metal_direct_spec += term[DS].px[i].r > 0.0f;
      emissive_elsewhere += em != glm::vec3(0.0f);
    } else if (em != glm::vec3(0.0f)) {
      ++glow;
      bad_glow += glm::length(em - glm::vec3(1.5f, 0.6f, 0.2f)) > 2e-3f;
    } else {
      ++floor_px;
      floor_no_ambient_diffuse += !(term[AD].px[i].g > 0.0f);
      floor_direct_diffuse += term[DD].px[i].g > 0.0f;
    }
  }
  std::cout << "surface " << surface << " background " << background << " metal " << metal
            << " floor " << floor_px << " glow " << glow << " unlit " << unlit
            << "; worst relative |sum - frame| " << worst << "\n";
  // The scene is what the checks below assume.
  ASSERT_GT(background, kW * 4);
  ASSERT_GT(metal, 200);
  ASSERT_GT(floor_px, 1000);
  ASSERT_GT(glow, 100);
  ASSERT_GT(unlit, 30);

  EXPECT_EQ(bad_sum, 0) << "terms + emissive != frame beyond " << kRel << " relative";
  EXPECT_EQ(bad_background, 0) << "term views draw the background";
  EXPECT_EQ(unlit_lit, 0) << "light terms on unlit pixels";
  EXPECT_EQ(metal_diffuse, 0) << "metallic = 1 has no diffuse";
  EXPECT_EQ(metal_no_ambient_spec, 0) << "the environment is reflected everywhere on the metal";
  EXPECT_GT(metal_direct_spec, metal / 4) << "the lights' highlights on the metal";
  EXPECT_EQ(emissive_elsewhere, 0);
  EXPECT_EQ(bad_glow, 0) << "the emissive view is the material's emissive";
  EXPECT_EQ(floor_no_ambient_diffuse, 0) << "the floor is lit by the environment everywhere";
  EXPECT_GT(floor_direct_diffuse, floor_px / 2) << "the floor is lit by the lights";

  // Back to the normal view: the scene's own masks again, the same frame.
  r.render(kW, kH);
  const ImageRGBf again = r.readHdr();
  int changed = 0;
  for (size_t i = 0; i < full.px.size(); ++i) changed += again.px[i] != full.px[i];
  EXPECT_EQ(changed, 0);
  EXPECT_EQ(scene.settings.direct_terms, 3);
  EXPECT_EQ(scene.settings.ambient_terms, 3);
}
