// Click-to-pick (render::pick, CPU ray cast): the default scene's center pixel is the floor, a
// sphere's projected center is that sphere, the sky is nothing; and over a whole frame the picked
// material is the one the G-buffer shows, with a mirrored object and a single-sided plane seen
// from behind (culled by the G-buffer pass, so not pickable).
#include <filesystem>
#include <iostream>

#include <glm/gtc/matrix_transform.hpp>

#include "halfvec/render/frame_data.hpp"
#include "halfvec/render/pick.hpp"
#include "render_fixture.hpp"
#include "halfvec/scene/scene_loader.hpp"

using namespace hv;

namespace {

// Pixel (top-left origin) where world point `p` lands in a width x height frame.
glm::vec2 project(const Scene& s, int w, int h, glm::vec3 p) {
  const render::FrameBlock f = render::makeFrameBlock(s, w, h);
  const glm::vec4 c = f.view_proj * glm::vec4(p, 1.0f);
  return {(c.x / c.w * 0.5f + 0.5f) * float(w), (0.5f - c.y / c.w * 0.5f) * float(h)};
}

std::string pickedName(const Scene& s, int w, int h, glm::vec2 px) {
  const auto hit = render::pick(s, w, h, px);
  return hit ? s.materials.at(size_t(hit->material)).name : "(none)";
}

}  // namespace

TEST(Pick, DefaultScene) {
  const std::filesystem::path path =
      std::filesystem::path(HV_SOURCE_DIR) / "samples/scenes/default.json";
  const Scene s = loadScene(path.string());
  const int w = 960, h = 540;
  // The camera looks at (0, 0.6, 0), between the copper and the red sphere: the floor behind.
  EXPECT_EQ(pickedName(s, w, h, {w * 0.5f, h * 0.5f}), "floor");
  EXPECT_EQ(pickedName(s, w, h, project(s, w, h, {0.6f, 0.5f, 0.0f})), "plastic_red");
  EXPECT_EQ(pickedName(s, w, h, project(s, w, h, {-1.8f, 0.5f, 0.0f})), "gold");
  EXPECT_EQ(pickedName(s, w, h, {5.0f, 5.0f}), "(none)");  // sky
  const auto hit = render::pick(s, w, h, project(s, w, h, {0.6f, 0.5f, 0.0f}));
  ASSERT_TRUE(hit);
  EXPECT_EQ(s.objects.at(size_t(hit->object)).name, "red_sphere");
  // The ray meets the sphere (radius 0.5 at (0.6, 0.5, 0)) on its camera side.
  EXPECT_NEAR(glm::length(hit->position - glm::vec3(0.6f, 0.5f, 0.0f)), 0.5f, 0.01f);
  EXPECT_NEAR(hit->distance, glm::length(hit->position - s.camera.position), 1e-3f);
}

TEST(Pick, AgreesWithTheGBufferOverAFrame) {
  testContext();
  Scene s;
  s.camera.position = {0.0f, 1.0f, 5.0f};
  s.camera.target = {0.0f, 0.5f, 0.0f};
  s.camera.fov_y_deg = 50.0f;
  // Distinct base colors identify the materials in the G-buffer.
  const glm::vec3 colors[] = {
      {0.5f, 0.5f, 0.5f}, {0.9f, 0.1f, 0.1f}, {0.1f, 0.9f, 0.1f}, {0.1f, 0.1f, 0.9f}};
  for (int i = 0; i < 4; ++i) {
    Material m;
    m.name = std::to_string(i);  // (not "m" + ...: GCC 12 -Wrestrict false positive)
    m.base_color = colors[i];
    s.materials.push_back(m);
  }
  // floor (m0); a sphere mirrored in x (m1); a box (m2); a single-sided ceiling plane facing up
  // above the camera (m3): seen from below, culled.
  const Mesh meshes[] = {makePlane(10.0f, 10.0f), makeSphere(0.6f, 32, 16),
                         makeBox(glm::vec3(0.4f)), makePlane(2.0f, 2.0f)};
  const glm::mat4 transforms[] = {
      glm::mat4(1.0f),
      glm::scale(glm::translate(glm::mat4(1.0f), {-0.8f, 0.6f, 0.0f}), {-1.0f, 1.0f, 1.0f}),
      glm::rotate(glm::translate(glm::mat4(1.0f), {0.9f, 0.4f, 0.5f}), 0.5f, {0.0f, 1.0f, 0.0f}),
      glm::translate(glm::mat4(1.0f), {0.0f, 1.6f, 2.0f})};
  for (int i = 0; i < 4; ++i) {
    s.meshes.push_back(meshes[i]);
    s.meshes.back().material = i;
    Object o;
    o.meshes = {i};
    o.transform = transforms[i];
    s.objects.push_back(o);
  }
  s.environment.kind = EnvironmentKind::None;
  const int w = 80, h = 60;
  render::Renderer r;
  r.setScene(s);
  r.render(w, h);
  const GBufferReadback g = r.readGBuffer();
  int agree = 0, disagree = 0, background = 0, ceiling_behind = 0;
  int per_material[4] = {};
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const size_t i = size_t(y) * w + size_t(x);
      const auto hit = render::pick(s, w, h, {x + 0.5f, y + 0.5f});
      int shown = -1;  // the material whose base color the G-buffer holds
      if (g.model[i] != uint32_t(ShadingModel::Background)) {
        for (int m = 0; m < 4; ++m) {
          if (glm::length(g.base_color[i] - colors[m]) < 0.03f) shown = m;
        }
      }
      const int picked = hit ? hit->material : -1;
      if (picked >= 0) ++per_material[picked];
      background += picked < 0;
      ++(picked == shown ? agree : disagree);
      // Pixels whose ray passes the ceiling from below: it must not be picked.
      const glm::vec2 c0 = project(s, w, h, {-1.0f, 1.6f, 1.0f}),
                      c1 = project(s, w, h, {1.0f, 1.6f, 3.0f});
      if (x + 0.5f > std::min(c0.x, c1.x) && x + 0.5f < std::max(c0.x, c1.x) &&
          y + 0.5f > std::min(c0.y, c1.y) && y + 0.5f < std::max(c0.y, c1.y)) {
        ++ceiling_behind;
      }
    }
  }
  std::cout << "agree " << agree << ", disagree " << disagree << " (silhouettes), background "
            << background << ", floor/sphere/box " << per_material[0] << "/" << per_material[1]
            << "/" << per_material[2] << ", under the ceiling " << ceiling_behind << "\n";
  EXPECT_EQ(per_material[3], 0) << "the culled ceiling was picked";
  EXPECT_GT(ceiling_behind, 20) << "the ceiling is in view (the test's premise)";
  EXPECT_GT(per_material[0], 500);
  EXPECT_GT(per_material[1], 100);
  EXPECT_GT(per_material[2], 50);
  EXPECT_GT(background, 200);
  // Rasterization and the ray disagree only where a pixel center grazes an edge.
  EXPECT_LE(disagree, w * h / 100);

  // Double-sided, the ceiling is drawn and picked from below.
  s.materials[3].double_sided = true;
  const glm::vec2 under = project(s, w, h, {0.0f, 1.6f, 2.0f});
  const auto hit = render::pick(s, w, h, under);
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->material, 3);
}

TEST(Pick, LightsInView) {
  Scene s;
  s.camera.position = {0.0f, 0.0f, 0.0f};
  s.camera.target = {0.0f, 0.0f, -1.0f};
  s.camera.fov_y_deg = 60.0f;
  auto light = [](glm::vec3 p, float range, LightType type = LightType::Point, float len = 0.0f) {
    Light l;
    l.type = type;
    l.position = p;
    l.range = range;
    l.length = len;
    return l;
  };
  s.lights = {
      light({0.0f, 0.0f, -5.0f}, 1.0f),     // in front: in
      light({0.0f, 0.0f, 5.0f}, 1.0f),      // behind: out
      light({0.0f, 0.0f, 0.5f}, 1.0f),      // behind, but its range reaches the near plane: in
      light({0.0f, 0.0f, -1000.0f}, 1.0f),  // far ahead (no far plane): in
      light({20.0f, 0.0f, -5.0f}, 1.0f),    // far right: out
      light({20.0f, 0.0f, -5.0f}, 18.0f),   // far right, range reaches the frustum: in
      light({0.0f, 10.0f, -5.0f}, 1.0f),    // above: out
      light({0.0f, 10.0f, -5.0f}, 1.0f, LightType::Tube, 20.0f),  // vertical tube down into view
  };
  s.lights.back().axis = {0.0f, 1.0f, 0.0f};
  EXPECT_EQ(render::countLightsInView(s, 160, 90), 5u);
  EXPECT_EQ(render::countLightsInView(s, 0, 90), 0u);
}
