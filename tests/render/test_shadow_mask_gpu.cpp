// The shadow mask (settings.shadow_resolution half; shaders/common/shadow_mask.glsl): the
// visibility computed once per 2x2 pixels and upsampled by depth and normal agrees with the
// full-resolution lookup on the sample scene and under a directional light, takes no visibility
// across a silhouette or a crease, and bounds the shadowed lights by its layers.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "render_fixture.hpp"
#include "halfvec/gl/log.hpp"
#include "halfvec/render/shadows.hpp"
#include "halfvec/scene/enums.hpp"
#include "halfvec/scene/primitives.hpp"
#include "halfvec/scene/scene_loader.hpp"

using namespace hv;

namespace {

Material matte(glm::vec3 c = glm::vec3(0.5f)) {
  Material m;
  m.base_color = c;
  m.roughness = 0.9f;
  return m;
}

void addObject(Scene& s, Mesh mesh, const glm::mat4& transform) {
  mesh.material = 0;
  s.meshes.push_back(std::move(mesh));
  Object o;
  o.name = "object " + std::to_string(s.objects.size());
  o.meshes = {int(s.meshes.size()) - 1};
  o.transform = transform;
  s.objects.push_back(o);
}

Scene withResolution(Scene s, ShadowResolution r) {
  s.settings.shadow_resolution = r;
  return s;
}

float lum(const glm::vec3& c) {
  return c.x + c.y + c.z;
}

// Half against full over the pixels the full frame lights: sum |H - F| / sum F, and the share of
// those pixels off by more than a quarter of their value.
struct Agreement {
  double mean_rel = 0.0, far_share = 0.0;
  size_t pixels = 0;
};
Agreement agreement(const ImageRGBf& half, const ImageRGBf& full) {
  double diff = 0.0, sum = 0.0;
  size_t far = 0;
  Agreement a;
  for (size_t i = 0; i < full.px.size(); ++i) {
    const float f = lum(full.px[i]), h = lum(half.px[i]);
    if (!(f > 1e-4f)) continue;
    ++a.pixels;
    diff += std::abs(double(h) - double(f));
    sum += f;
    far += std::abs(h - f) > 0.25f * f;
  }
  a.mean_rel = sum > 0.0 ? diff / sum : 0.0;
  a.far_share = a.pixels ? double(far) / double(a.pixels) : 0.0;
  return a;
}

// Renders `s` at w x h at both resolutions and bounds their agreement (printed).
void expectAgreement(const std::string& name, const Scene& s, int w, int h, double mean_bound,
                     double far_bound) {
  const RenderedFrame full = renderFrame(withResolution(s, ShadowResolution::Full), w, h);
  const RenderedFrame half = renderFrame(withResolution(s, ShadowResolution::Half), w, h);
  const Agreement a = agreement(half.hdr, full.hdr);
  std::printf("%s: mean rel %.4f, off by > 25%%: %.4f of %zu pixels\n", name.c_str(), a.mean_rel,
              a.far_share, a.pixels);
  EXPECT_GT(a.pixels, 30000u) << name;
  EXPECT_LT(a.mean_rel, mean_bound) << name;
  EXPECT_LT(a.far_share, far_bound) << name;
  EXPECT_NE(a.mean_rel, 0.0) << name << ": the mask was not used";
}

}  // namespace

// shadows.json (a capsule and a sphere light, both shadowed, over a box and spheres), per
// filter: half against full. Bounds: measured when the test was written (printed), about x 2;
// the differences are the shadow edges, where half resolution interpolates between texels.
TEST(ShadowMask, AgreesWithFullResolutionOnTheSampleScene) {
  testContext();
  const Scene s = loadScene(std::string(HV_SOURCE_DIR) + "/samples/scenes/shadows.json");
  for (ShadowFilter f : {ShadowFilter::Hard, ShadowFilter::Pcf, ShadowFilter::Pcss}) {
    Scene sf = s;
    sf.settings.shadow_filter = f;
    expectAgreement(std::string(toString(f)), sf, 320, 180, 0.005, 0.006);
  }
}

// A sun (directional light: the mask's first layers) over a floor with a sphere: half against
// full, as above.
TEST(ShadowMask, DirectionalLightShadowsAgreeWithFullResolution) {
  testContext();
  Scene s = planeScene(matte(), 20.0f);
  s.camera.position = {0.0f, 3.0f, 3.0f};
  s.camera.target = {0.0f, 0.0f, 0.0f};
  addObject(s, makeSphere(0.5f), glm::translate(glm::mat4(1.0f), {0.0f, 0.7f, 0.0f}));
  Light sun;
  sun.type = LightType::Directional;
  sun.direction = glm::normalize(glm::vec3(0.4f, -1.0f, 0.2f));
  sun.intensity = 3.0f;
  sun.angular_diameter = 0.03f;
  sun.shadows = true;
  s.lights = {sun};
  expectAgreement("sun", s, 256, 192, 0.001, 0.004);
}

// A tall box on the floor, a point light beside it (`hard`: visibility is 0 or 1), seen
// obliquely: the box's lit faces border the floor in the box's shadow (silhouettes) and its
// faces meet at creases. Wherever a pixel's own surface (its neighbours within 2 pixels with the
// same normal and a depth within 5%) is all lit or all shadowed at full resolution, the
// half-resolution visibility (shadowed over unshadowed) must be the same: no texel of another
// surface may leak in. The pixels checked next to another surface are counted, so that the test can
// fail.
TEST(ShadowMask, UpsampleTakesNoVisibilityAcrossEdges) {
  testContext();
  Scene s = planeScene(matte(), 20.0f);
  s.camera.position = {2.5f, 2.2f, 3.0f};
  s.camera.target = {0.0f, 0.6f, 0.0f};
  addObject(s, makeBox({0.4f, 0.8f, 0.4f}),
            glm::rotate(glm::translate(glm::mat4(1.0f), {0.0f, 0.8f, 0.0f}), 0.4f, {0, 1, 0}));
  addObject(s, makeSphere(0.3f), glm::translate(glm::mat4(1.0f), {1.0f, 0.3f, 1.0f}));
  Light l;
  l.type = LightType::Point;
  l.position = {1.8f, 2.4f, -0.6f};
  l.intensity = 20.0f;
  l.range = 30.0f;
  l.shadows = true;
  s.lights = {l};
  s.settings.shadow_filter = ShadowFilter::Hard;
  const int w = 320, h = 240;
  Scene off = s;
  off.lights[0].shadows = false;
  const RenderedFrame u = renderFrame(off, w, h);
  const RenderedFrame full = renderFrame(withResolution(s, ShadowResolution::Full), w, h);
  const RenderedFrame half = renderFrame(withResolution(s, ShadowResolution::Half), w, h);
  auto ratio = [&](const ImageRGBf& img, size_t i) { return lum(img.px[i]) / lum(u.hdr.px[i]); };
  size_t checked = 0, near_other = 0, wrong = 0;
  for (int y = 2; y < h - 2; ++y) {
    for (int x = 2; x < w - 2; ++x) {
      const size_t i = size_t(y) * w + x;
      if (!(lum(u.hdr.px[i]) > 1e-3f)) continue;
      const float r = ratio(full.hdr, i);
      if (r > 0.02f && r < 0.98f) continue;
      bool uniform = true, other = false;
      for (int dy = -2; dy <= 2 && uniform; ++dy) {
        for (int dx = -2; dx <= 2; ++dx) {
          const size_t j = size_t(y + dy) * w + (x + dx);
          const bool same = glm::dot(u.g.normal[i], u.g.normal[j]) > 0.99f &&
                            std::abs(u.g.depth[j] - u.g.depth[i]) < 0.05f * u.g.depth[i];
          if (!same) {
            other = true;
            continue;
          }
          if (!(lum(u.hdr.px[j]) > 1e-3f) || (ratio(full.hdr, j) > 0.5f) != (r > 0.5f)) {
            uniform = false;
            break;
          }
        }
      }
      if (!uniform) continue;
      ++checked;
      near_other += other;
      const float rh = ratio(half.hdr, i);
      if (std::abs(rh - r) > 0.05f) {
        if (wrong < 12) {
          std::printf("pixel (%d, %d): full %.3f, half %.3f, N %.2f %.2f %.2f, depth %.5f\n", x, y,
                      r, rh, u.g.normal[i].x, u.g.normal[i].y, u.g.normal[i].z, u.g.depth[i]);
        }
        ++wrong;
      }
    }
  }
  std::printf("checked %zu pixels, %zu of them next to another surface; %zu wrong\n", checked,
              near_other, wrong);
  EXPECT_GT(checked, 30000u);
  EXPECT_GT(near_other, 1000u);
  EXPECT_EQ(wrong, 0u);
}

// The mask holds at most HV_SHADOW_MASK_MAX_CUBES lights with a cube: beyond, lights render
// unshadowed and the warning names them and the setting.
TEST(ShadowMask, LightsBeyondTheMaskAreUnshadowedAndNamed) {
  testContext();
  EXPECT_EQ(render::shadowLightCapacity(1024, true), 4u);
  EXPECT_EQ(render::shadowLightCapacity(256, false), 64u);
  EXPECT_EQ(render::shadowLightCapacity(256, true), size_t(HV_SHADOW_MASK_MAX_CUBES));
  Scene s = planeScene(matte(), 20.0f);
  for (int k = 0; k <= HV_SHADOW_MASK_MAX_CUBES; ++k) {
    Light l;
    l.type = LightType::Point;
    l.position = {0.1f * float(k) - 1.6f, 1.0f, 0.0f};
    l.intensity = 0.5f;
    l.range = 5.0f;
    l.shadows = true;
    s.lights.push_back(l);
  }
  s.settings.shadow_map_size = 64;
  s.settings.shadow_resolution = ShadowResolution::Half;
  std::vector<std::string> warnings;
  auto old = log::setSink([&](log::Level lv, std::string_view m) {
    if (lv == log::Level::Warning) warnings.emplace_back(m);
  });
  render::Renderer r;
  r.setScene(s);
  const render::FrameStats st = r.render(64, 64);
  log::setSink(old);
  EXPECT_EQ(st.shadow_maps, size_t(HV_SHADOW_MASK_MAX_CUBES));
  ASSERT_EQ(warnings.size(), 1u);
  const std::string last = "light " + std::to_string(HV_SHADOW_MASK_MAX_CUBES) + " (point";
  EXPECT_NE(warnings[0].find(last), std::string::npos) << warnings[0];
  EXPECT_NE(warnings[0].find("shadow_resolution"), std::string::npos) << warnings[0];
  // At full resolution the atlas (256 lights at 64^2) holds them all.
  s.settings.shadow_resolution = ShadowResolution::Full;
  r.setScene(s);
  EXPECT_EQ(r.render(64, 64).shadow_maps, size_t(HV_SHADOW_MASK_MAX_CUBES) + 1);
}

// One renderer through changes of the mask's shape (a light's shadow off, then the frame's
// size): each frame equals a fresh renderer's of the same scene and size, so nothing of the
// previous mask (its layers, its size) is read.
TEST(ShadowMask, ReshapedMaskEqualsAFreshRenderers) {
  testContext();
  Scene two = loadScene(std::string(HV_SOURCE_DIR) + "/samples/scenes/shadows.json");
  two.settings.shadow_resolution = ShadowResolution::Half;
  Scene one = two;
  one.lights[0].shadows = false;
  render::Renderer r;
  r.setScene(two);
  r.render(160, 90);
  r.setScene(one);
  r.render(160, 90);
  EXPECT_EQ(r.readHdr().px, renderFrame(one, 160, 90).hdr.px);
  r.render(161, 91);
  EXPECT_EQ(r.readHdr().px, renderFrame(one, 161, 91).hdr.px);
  r.setScene(two);
  r.render(161, 91);
  EXPECT_EQ(r.readHdr().px, renderFrame(two, 161, 91).hdr.px);
  // The same half-resolution size (81 x 46), another full one.
  r.render(162, 92);
  EXPECT_EQ(r.readHdr().px, renderFrame(two, 162, 92).hdr.px);
}
