// Shadow maps (docs/lights.md, "Shadows"), the engine side on the GPU renderer: no acne at
// grazing light, a hard point-light shadow where the geometry puts it, penumbrae that widen with
// the light's radius and the receiver's distance from the occluder, the cache, the atlas budget,
// and scenes without shadowed lights rendering as before.
#include <gtest/gtest.h>

#include <algorithm>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "render_fixture.hpp"
#include "halfvec/gl/log.hpp"
#include "halfvec/render/frame_data.hpp"
#include "halfvec/render/shadows.hpp"
#include "halfvec/scene/primitives.hpp"
#include "halfvec/scene/enums.hpp"
#include "halfvec/scene/scene_loader.hpp"

using namespace hv;

namespace {

constexpr ShadowFilter kFilters[] = {ShadowFilter::Hard, ShadowFilter::Pcf, ShadowFilter::Pcss};

Material matte() {
  Material m;
  m.base_color = glm::vec3(0.5f);
  m.roughness = 0.9f;
  return m;
}

// The floor's direct light only: a black uniform environment.
Scene floorScene(float size = 10.0f) {
  return planeScene(matte(), size);
}

void addBox(Scene& s, glm::vec3 center, glm::vec3 half) {
  s.meshes.push_back(makeBox(half));
  s.meshes.back().material = 0;
  Object o;
  o.name = "box";
  o.meshes = {int(s.meshes.size()) - 1};
  o.transform = glm::translate(glm::mat4(1.0f), center);
  s.objects.push_back(o);
}

void addSphere(Scene& s, glm::vec3 center, float radius) {
  s.meshes.push_back(makeSphere(radius));
  s.meshes.back().material = 0;
  Object o;
  o.name = "sphere";
  o.meshes = {int(s.meshes.size()) - 1};
  o.transform = glm::translate(glm::mat4(1.0f), center);
  s.objects.push_back(o);
}

Light light(LightType type, glm::vec3 p, float radius, bool shadows) {
  Light l;
  l.type = type;
  l.position = p;
  l.intensity = 20.0f;
  l.radius = radius;
  l.range = 30.0f;
  l.shadows = shadows;
  return l;
}

ImageRGBf renderHdr(const Scene& s, int w, int h) {
  render::Renderer r;
  r.setScene(s);
  r.render(w, h);
  return r.readHdr();
}

float lum(const glm::vec3& c) {
  return c.x + c.y + c.z;
}

// Where pixel (x, y) (top-down) of a w x h frame of the scene's camera sees the plane y = 0.
glm::vec3 floorPoint(const Scene& s, int w, int h, int x, int y) {
  const render::FrameBlock f = render::makeFrameBlock(s, w, h);
  const glm::vec2 ndc(2.0f * (x + 0.5f) / w - 1.0f, 1.0f - 2.0f * (y + 0.5f) / h);
  glm::vec4 a = f.inv_view_proj * glm::vec4(ndc, 1.0f, 1.0f);  // reversed Z: near plane
  glm::vec4 b = f.inv_view_proj * glm::vec4(ndc, 0.5f, 1.0f);
  const glm::vec3 p0 = glm::vec3(a) / a.w, p1 = glm::vec3(b) / b.w;
  const float t = -p0.y / (p1.y - p0.y);
  return p0 + t * (p1 - p0);
}

// The ratio shadowed / unshadowed of the floor's radiance along the image row through its
// middle, and the 10%-90% width of its first rising edge in metres (from x0 outward).
struct Profile {
  std::vector<float> x, ratio;
};
Profile rowProfile(const Scene& s, const ImageRGBf& on, const ImageRGBf& off, int row) {
  Profile p;
  for (int x = 0; x < on.width; ++x) {
    const size_t i = size_t(row) * on.width + x;
    const float o = lum(off.px[i]);
    if (!(o > 0.0f)) continue;
    p.x.push_back(floorPoint(s, on.width, on.height, x, row).x);
    p.ratio.push_back(lum(on.px[i]) / o);
  }
  return p;
}
// The distance between where the ratio first passes `lo` and then `hi` going right from the
// profile's darkest point (linear interpolation between pixels).
float risingWidth(const Profile& p, float lo = 0.1f, float hi = 0.9f) {
  size_t i = size_t(std::min_element(p.ratio.begin(), p.ratio.end()) - p.ratio.begin());
  auto cross = [&](float level, size_t from) {
    for (size_t k = from; k + 1 < p.ratio.size(); ++k) {
      if (p.ratio[k] < level && p.ratio[k + 1] >= level) {
        const float t = (level - p.ratio[k]) / (p.ratio[k + 1] - p.ratio[k]);
        return std::pair<float, size_t>(p.x[k] + t * (p.x[k + 1] - p.x[k]), k);
      }
    }
    return std::pair<float, size_t>(NAN, p.ratio.size());
  };
  const auto a = cross(lo, i);
  const auto b = cross(hi, a.second);
  return b.first - a.first;
}

// Per-pixel shadow states of a w x h frame, -1 for pixels not judged, 0 lit, 1 shadowed: the
// truth's shadowed pixels, the pixels whose state differs, and those of them beyond one pixel
// of the true boundary (no neighbour has the other true state).
struct StateDiff {
  size_t shadowed = 0, lit = 0, wrong = 0, far_wrong = 0;
};
StateDiff compareStates(const std::vector<int>& truth, const std::vector<int>& seen, int w, int h) {
  StateDiff r;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const size_t i = size_t(y) * w + x;
      if (truth[i] < 0) continue;
      r.shadowed += truth[i] == 1;
      r.lit += truth[i] == 0;
      if (seen[i] == truth[i]) continue;
      ++r.wrong;
      bool near = false;
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
          const int xx = x + dx, yy = y + dy;
          if (xx < 0 || yy < 0 || xx >= w || yy >= h) continue;
          const int t = truth[size_t(yy) * w + xx];
          near = near || (t >= 0 && t != truth[i]);
        }
      }
      r.far_wrong += !near;
    }
  }
  return r;
}

// A sphere light over the floor, a sphere occluder between; camera above looking down the
// +x side of the shadow, where the penumbra is.
Scene penumbraScene(float light_radius, float occluder_height, ShadowFilter filter) {
  Scene s = floorScene(20.0f);
  s.camera.position = {1.2f, 3.0f, 0.0f};
  s.camera.target = {1.2f, 0.0f, 0.0f};
  s.camera.up = {0.0f, 0.0f, -1.0f};
  s.camera.fov_y_deg = 50.0f;
  addSphere(s, {0.0f, occluder_height, 0.0f}, 0.25f);
  s.lights.push_back(light(LightType::Sphere, {0.0f, 4.0f, 0.0f}, light_radius, true));
  s.settings.shadow_filter = filter;
  return s;
}

float penumbraWidthOf(const Scene& scene);

float penumbraWidth(float light_radius, float occluder_height, ShadowFilter filter) {
  return penumbraWidthOf(penumbraScene(light_radius, occluder_height, filter));
}

float penumbraWidthOf(const Scene& scene) {
  Scene on = scene;
  Scene off = on;
  off.lights[0].shadows = false;
  const int w = 320, h = 96;
  const ImageRGBf a = renderHdr(on, w, h), b = renderHdr(off, w, h);
  // The mean over the middle rows' widths (the sphere's shadow edge is round; rows near the
  // middle cross it nearly square).
  float sum = 0.0f;
  int n = 0;
  for (int row = h / 2 - 2; row <= h / 2 + 2; ++row) {
    const float wdt = risingWidth(rowProfile(on, a, b, row));
    if (std::isfinite(wdt)) {
      sum += wdt;
      ++n;
    }
  }
  return n ? sum / n : NAN;
}

// FNV-1a over the bytes of the HDR target's floats and the 8-bit output.
uint64_t frameHash(const render::Renderer& r) {
  uint64_t h = 1469598103934665603ull;
  auto add = [&](const void* p, size_t n) {
    const auto* b = static_cast<const unsigned char*>(p);
    for (size_t i = 0; i < n; ++i) h = (h ^ b[i]) * 1099511628211ull;
  };
  const ImageRGBf hdr = r.readHdr();
  add(hdr.px.data(), hdr.px.size() * sizeof(hdr.px[0]));
  const ImageRGBA8 ldr = r.readLdr();
  add(ldr.px.data(), ldr.px.size());
  return h;
}

std::string samplePath(const char* name) {
  return std::string(HV_SOURCE_DIR) + "/samples/scenes/" + name + ".json";
}

}  // namespace

// A flat floor lit at 80 degrees from its normal, nothing above it: every lit pixel must stay
// lit. Goal: fewer than 0.1% of the visible floor pixels wrongly shadowed.
TEST(Shadows, NoAcneAtGrazingLight) {
  testContext();
  const float a = glm::radians(80.0f);
  for (LightType type : {LightType::Point, LightType::Sphere}) {
    for (ShadowFilter f : kFilters) {
      Scene on = floorScene();
      on.lights.push_back(light(type, 3.0f * glm::vec3(std::sin(a), std::cos(a), 0.0f),
                                type == LightType::Sphere ? 0.2f : 0.0f, true));
      on.settings.shadow_filter = f;
      Scene off = on;
      off.lights[0].shadows = false;
      const ImageRGBf img = renderHdr(on, 256, 256), ref = renderHdr(off, 256, 256);
      size_t lit = 0, dark = 0;
      for (size_t i = 0; i < img.px.size(); ++i) {
        const float r = lum(ref.px[i]);
        if (!(r > 1e-6f)) continue;
        ++lit;
        if (lum(img.px[i]) < 0.98f * r) ++dark;
      }
      ASSERT_GT(lit, 50000u);
      const double frac = double(dark) / double(lit);
      std::printf("acne %s %s: %zu of %zu floor pixels (%.4f%%)\n", toString(type).data(),
                  toString(f).data(), dark, lit, 100.0 * frac);
      EXPECT_LT(frac, 0.001) << toString(type) << " " << toString(f);
    }
  }
}

// A point light over a box: with `hard`, a floor pixel is shadowed exactly where the segment to
// the light meets the box, up to one pixel at the boundary.
// A box floating 0.7 m above the floor (the boundary) and one resting on it (contact: a bias
// that detached the shadow would leave lit floor pixels at the box's foot).
TEST(Shadows, HardPointShadowBoundaryWithinOnePixel) {
  testContext();
  for (const float height : {1.0f, 0.3f}) {
    SCOPED_TRACE("box center at height " + std::to_string(height));
    Scene on = floorScene(20.0f);
    on.camera.position = {1.5f, 3.0f, 0.0f};
    on.camera.target = {0.8f, 0.0f, 0.0f};
    on.camera.up = {0.0f, 0.0f, -1.0f};
    on.camera.fov_y_deg = 40.0f;
    const glm::vec3 c(0.0f, height, 0.0f), half(0.3f);
    addBox(on, c, half);
    const glm::vec3 lp(-0.4f, 3.0f, 0.1f);
    on.lights.push_back(light(LightType::Point, lp, 0.0f, true));
    on.settings.shadow_filter = ShadowFilter::Hard;
    on.settings.shadow_map_size = 2048;
    Scene off = on;
    off.lights[0].shadows = false;
    const int w = 256, h = 256;
    const ImageRGBf img = renderHdr(on, w, h), ref = renderHdr(off, w, h);
    // Analytic: the segment from the floor point to the light meets the box (slab test).
    auto blocked = [&](glm::vec3 p) {
      const glm::vec3 d = lp - p;
      float t0 = 0.0f, t1 = 1.0f;
      for (int k = 0; k < 3; ++k) {
        const float lo = (c[k] - half[k] - p[k]) / d[k], hi = (c[k] + half[k] - p[k]) / d[k];
        t0 = std::max(t0, std::min(lo, hi));
        t1 = std::min(t1, std::max(lo, hi));
      }
      return t0 <= t1;
    };
    // -1: not a visible floor pixel; 0 lit; 1 shadowed.
    std::vector<int> truth(size_t(w) * h, -1), seen(size_t(w) * h, -1);
    for (int y = 0; y < h; ++y) {
      for (int x = 0; x < w; ++x) {
        const size_t i = size_t(y) * w + x;
        const glm::vec3 p = floorPoint(on, w, h, x, y);
        // Floor pixels only: the box covers some of the image (its pixels see no floor point).
        if (!(lum(ref.px[i]) > 0.0f) || std::abs(p.x) > 5.0f || std::abs(p.z) > 5.0f) continue;
        const glm::vec3 d = glm::normalize(p - on.camera.position);
        const glm::vec3 e = on.camera.position;
        float tn = 0.0f, tf = 1e9f;  // does the eye ray meet the box before the floor?
        for (int k = 0; k < 3; ++k) {
          const float lo = (c[k] - half[k] - e[k]) / d[k], hi = (c[k] + half[k] - e[k]) / d[k];
          tn = std::max(tn, std::min(lo, hi));
          tf = std::min(tf, std::max(lo, hi));
        }
        if (tn <= tf) continue;
        truth[i] = blocked(p) ? 1 : 0;
        seen[i] = lum(img.px[i]) < 0.5f * lum(ref.px[i]) ? 1 : 0;
      }
    }
    const StateDiff diff = compareStates(truth, seen, w, h);
    std::printf(
        "hard boundary, box at %.1f m: %zu shadowed floor pixels, %zu differ, %zu beyond "
        "one pixel\n",
        height, diff.shadowed, diff.wrong, diff.far_wrong);
    EXPECT_GT(diff.shadowed, 500u);
    EXPECT_EQ(diff.far_wrong, 0u);
  }
}

// Alpha-masked casters (glTF alphaMode MASK) cut their holes in the shadow map as in the
// G-buffer: a 1 m quad 1 m over the floor, masked by an 8 x 8 texture whose alpha is 0 in a
// block of 3 x 4 texels off its center, under a point light 3 m up (hard filter, map 2048). The
// floor is seen from below the quad, so the eye rays never cross it. Truth: the segment from the
// floor point to the light crosses the quad's plane at a texel of alpha 1. Without the mask in
// the shadow pass, the hole's footprint (about 0.56 x 0.75 m on the floor) would be shadowed.
TEST(Shadows, AlphaMaskedCasterCastsItsHoles) {
  testContext();
  Scene on = floorScene(20.0f);
  on.camera.position = {2.6f, 0.7f, 0.0f};
  on.camera.target = {0.0f, 0.0f, 0.0f};
  on.camera.up = {0.0f, 1.0f, 0.0f};
  on.camera.fov_y_deg = 50.0f;
  constexpr int kTex = 8;
  auto opaque = [](int col, int row) { return !(col >= 1 && col <= 3 && row >= 2 && row <= 5); };
  ImageData mask{"mask", kTex, kTex, std::vector<uint8_t>(size_t(kTex) * kTex * 4, 255)};
  for (int row = 0; row < kTex; ++row) {
    for (int col = 0; col < kTex; ++col) {
      mask.rgba[size_t(row * kTex + col) * 4 + 3] = opaque(col, row) ? 255 : 0;
    }
  }
  on.images.push_back(mask);
  Material cut = matte();
  cut.alpha_mode = AlphaMode::Mask;
  cut.alpha_cutoff = 0.5f;
  cut.base_color_tex.image = 0;
  cut.base_color_tex.sampler.mag = Filter::Nearest;
  cut.base_color_tex.sampler.min = Filter::Nearest;
  cut.base_color_tex.sampler.mipmaps = false;
  on.materials.push_back(cut);
  on.meshes.push_back(makePlane(1.0f, 1.0f));  // u = x + 0.5, v = z + 0.5
  on.meshes.back().material = 1;
  Object quad;
  quad.name = "masked quad";
  quad.meshes = {int(on.meshes.size()) - 1};
  const float qh = 1.0f;
  quad.transform = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, qh, 0.0f));
  on.objects.push_back(quad);
  const glm::vec3 lp(0.0f, 3.0f, 0.0f);
  on.lights.push_back(light(LightType::Point, lp, 0.0f, true));
  on.settings.shadow_filter = ShadowFilter::Hard;
  on.settings.shadow_map_size = 2048;
  Scene off = on;
  off.lights[0].shadows = false;
  const int w = 256, h = 256;
  render::Renderer r;
  r.setScene(on);
  r.render(w, h);
  const ImageRGBf img = r.readHdr(), ref = renderHdr(off, w, h);
  bool masked_program = false;
  for (const gl::VariantInfo& v : r.manifest().programs) {
    if (v.name != "shadow_masked") continue;
    masked_program = true;
    ASSERT_EQ(v.reasons.size(), 1u);  // the manifest says why it was compiled
    EXPECT_NE(v.reasons[0].find("HV_SHADOW_ALPHA_MASK=1: "), std::string::npos) << v.reasons[0];
  }
  EXPECT_TRUE(masked_program) << "the masked variant of the shadow pass was not used";
  {  // The same quad opaque: the masked variant is not compiled.
    Scene solid = on;
    solid.materials[1].alpha_mode = AlphaMode::Opaque;
    render::Renderer rs;
    rs.setScene(solid);
    rs.render(64, 64);
    bool plain = false, masked = false;
    for (const gl::VariantInfo& v : rs.manifest().programs) {
      plain |= v.name == "shadow";
      masked |= v.name == "shadow_masked";
    }
    EXPECT_TRUE(plain);
    EXPECT_FALSE(masked);
  }
  // Where a segment from p towards the light crosses the quad's plane: -1 outside the quad, else
  // whether the texel there is opaque.
  auto quadAt = [&](glm::vec3 p, glm::vec3 to) {
    const float t = (qh - p.y) / (to.y - p.y);
    if (!(t > 0.0f && t < 1.0f)) return -1;
    const glm::vec3 q = p + t * (to - p);
    if (std::abs(q.x) >= 0.5f || std::abs(q.z) >= 0.5f) return -1;
    const int col = std::min(kTex - 1, int((q.x + 0.5f) * kTex));
    const int row = std::min(kTex - 1, int((q.z + 0.5f) * kTex));
    return opaque(col, row) ? 1 : 0;
  };
  std::vector<int> truth(size_t(w) * h, -1), seen(size_t(w) * h, -1);
  size_t in_hole = 0;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const size_t i = size_t(y) * w + x;
      if (!(lum(ref.px[i]) > 0.0f)) continue;
      const glm::vec3 p = floorPoint(on, w, h, x, y);
      if (std::abs(p.x) > 5.0f || std::abs(p.z) > 5.0f) continue;
      ASSERT_EQ(quadAt(on.camera.position, p), -1) << "the eye ray crosses the quad";
      const int q = quadAt(p, lp);
      truth[i] = q == 1 ? 1 : 0;
      in_hole += q == 0;
      seen[i] = lum(img.px[i]) < 0.5f * lum(ref.px[i]) ? 1 : 0;
    }
  }
  const StateDiff diff = compareStates(truth, seen, w, h);
  std::printf(
      "masked quad: %zu shadowed floor pixels, %zu lit through the hole, %zu differ, %zu beyond "
      "one pixel\n",
      diff.shadowed, in_hole, diff.wrong, diff.far_wrong);
  EXPECT_GT(diff.shadowed, 500u);
  EXPECT_GT(in_hole, 300u);
  EXPECT_EQ(diff.far_wrong, 0u);
}

// PCSS: the 10%-90% width of the penumbra grows with the light's radius and with the
// receiver's distance from the occluder (the occluder higher above the floor, the light fixed).
TEST(Shadows, PcssPenumbraWidensWithRadiusAndDistance) {
  testContext();
  const float small = penumbraWidth(0.1f, 1.0f, ShadowFilter::Pcss);
  const float large = penumbraWidth(0.3f, 1.0f, ShadowFilter::Pcss);
  const float high = penumbraWidth(0.3f, 2.0f, ShadowFilter::Pcss);
  std::printf("pcss penumbra 10-90%%: r 0.1 h 1: %.4f m, r 0.3 h 1: %.4f m, r 0.3 h 2: %.4f m\n",
              small, large, high);
  ASSERT_TRUE(std::isfinite(small) && std::isfinite(large) && std::isfinite(high));
  EXPECT_GT(large, 1.8f * small);
  EXPECT_GT(high, 1.5f * large);
  // The hard filter's edge is far narrower than either.
  const float hard = penumbraWidth(0.3f, 1.0f, ShadowFilter::Hard);
  EXPECT_LT(hard, 0.5f * large);
}

// Scenes whose lights have no shadows render bit for bit as before shadows existed: the hashes
// of the HDR and 8-bit frames of three sample scenes with `shadows` off, rendered by the commit
// before shadow maps (ddceaae) with this test's code, the environment read along R as then;
// default's hash is that render's with the normals at its spheres' outlines that face away from
// the viewer reflected (gbuffer.glsl, viewFacingNormal: 1 of its 57,600 pixels at 320x180), and
// default's and sphere_grid's with the glossy surfaces' ambient lookup of specularLookupMip
// (ibl.glsl: their roughness-0.05 spheres; area_lights has no environment). Renders
// are reproducible bit for bit on one implementation (docs/architecture.md); another implementation
// gives other bits, so the check runs on the llvmpipe the hashes were taken on.
TEST(Shadows, SceneWithoutShadowedLightsRendersAsBefore) {
  hv::Context& ctx = testContext();
  if (ctx.renderer().find("llvmpipe") == std::string::npos) {
    GTEST_SKIP() << "hashes taken on llvmpipe; this is " << ctx.renderer();
  }
  const struct {
    const char* scene;
    uint64_t hash;
  } cases[] = {{"default", 0x305c72b9b41f2fabull},
               {"area_lights", 0xfba0068bc57b1451ull},
               {"sphere_grid", 0x3dcf0e947c0ea14aull}};
  for (const auto& c : cases) {
    Scene s = loadScene(samplePath(c.scene));
    for (Light& l : s.lights) l.shadows = false;
    // The ambient lookup along R and the sky's sun in the sky, as then (ibl_direction and
    // sky_sun changed them on purpose, docs/ibl.md).
    s.settings.ibl_direction = IblDirection::Reflect;
    s.settings.sky_sun = SkySun::Environment;
    render::Renderer r;
    r.setScene(s);
    EXPECT_EQ(r.variantKey().shadows, false);
    const render::FrameStats st = r.render(192, 108);
    for (const auto& [pass, ms] : st.passes) EXPECT_NE(pass, "shadows") << c.scene;
    const uint64_t h = frameHash(r);
    std::printf("%s: 0x%016" PRIx64 "\n", c.scene, h);
    EXPECT_EQ(h, c.hash) << c.scene;
  }
}

// The maps are rendered once and kept until a light or a caster moves; intensity and color
// change no map.
TEST(Shadows, MapsAreCachedUntilALightOrACasterMoves) {
  testContext();
  Scene s = penumbraScene(0.2f, 1.0f, ShadowFilter::Pcss);
  s.lights.push_back(light(LightType::Point, {1.0f, 3.0f, 1.0f}, 0.0f, true));
  render::Renderer r;
  r.setScene(s);
  render::FrameStats st = r.render(64, 64);
  EXPECT_EQ(st.shadow_maps, 2u);
  EXPECT_EQ(st.shadow_maps_rendered, 2u);
  const ImageRGBf first = r.readHdr();
  st = r.render(64, 64);
  EXPECT_EQ(st.shadow_maps_rendered, 0u);
  EXPECT_EQ(r.readHdr().px, first.px);  // the cached maps shade the same
  s.lights[0].intensity *= 2.0f;
  r.updateLights();
  EXPECT_EQ(r.render(64, 64).shadow_maps_rendered, 0u);
  s.lights[1].position.x += 0.1f;
  r.updateLights();
  EXPECT_EQ(r.render(64, 64).shadow_maps_rendered, 1u);
  s.objects[1].transform = glm::translate(s.objects[1].transform, glm::vec3(0.0f, 0.1f, 0.0f));
  EXPECT_EQ(r.render(64, 64).shadow_maps_rendered, 2u);
  EXPECT_EQ(r.render(64, 64).shadow_maps_rendered, 0u);
  // A light turned off and on again: its map comes back (the light buffer was re-uploaded).
  s.lights[0].shadows = false;
  r.updateLights();
  st = r.render(64, 64);
  EXPECT_EQ(st.shadow_maps, 1u);
  s.lights[0].shadows = true;
  r.updateLights();
  st = r.render(64, 64);
  EXPECT_EQ(st.shadow_maps, 2u);
}

// The atlas holds shadowAtlasCapacity(size) lights; the others render unshadowed, and the
// warning names them.
TEST(Shadows, LightsBeyondTheAtlasAreUnshadowedAndNamed) {
  testContext();
  EXPECT_EQ(render::shadowAtlasCapacity(2048), 1u);
  EXPECT_EQ(render::shadowAtlasCapacity(1024), 4u);
  EXPECT_EQ(render::shadowAtlasCapacity(512), 16u);
  Scene two = penumbraScene(0.2f, 1.0f, ShadowFilter::Pcss);
  two.lights.push_back(light(LightType::Point, {0.5f, 3.0f, 0.0f}, 0.0f, true));
  two.settings.shadow_map_size = 2048;
  std::vector<std::string> warnings;
  auto old = log::setSink([&](log::Level l, std::string_view m) {
    if (l == log::Level::Warning) warnings.emplace_back(m);
  });
  render::Renderer r;
  r.setScene(two);
  const render::FrameStats st = r.render(96, 96);
  r.render(96, 96);  // not repeated while the same lights are over
  log::setSink(old);
  EXPECT_EQ(st.shadow_maps, 1u);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("light 1 (point at [0.5, 3, 0])"), std::string::npos) << warnings[0];
  EXPECT_NE(warnings[0].find("shadow_map_size"), std::string::npos) << warnings[0];
  // The second light shades as if it had no shadows.
  Scene one = two;
  one.lights[1].shadows = false;
  const ImageRGBf a = r.readHdr(), b = renderHdr(one, 96, 96);
  EXPECT_EQ(a.px, b.px);
}

// The manifest says why the light programs have shadow code.
TEST(Shadows, VariantKeyNamesTheShadowedLights) {
  Scene s = penumbraScene(0.2f, 1.0f, ShadowFilter::Pcf);
  const render::VariantKey k = render::deriveVariantKey(s);
  EXPECT_TRUE(k.shadows);
  bool found = false;
  for (const render::KeyDefine& d : render::lightDefines(k, s)) {
    if (d.name == "HV_SHADOWS") {
      found = true;
      EXPECT_EQ(d.value, "1");
      EXPECT_NE(d.why.find("light 0 (sphere"), std::string::npos) << d.why;
    }
    if (d.name == "HV_SHADOW_FILTER") {
      EXPECT_EQ(d.value, "1");
    }
  }
  EXPECT_TRUE(found);
  s.lights[0].shadows = false;
  const render::VariantKey none = render::deriveVariantKey(s);
  EXPECT_FALSE(none.shadows);
  EXPECT_EQ(none.settings.shadow_filter, ShadowFilter::Pcss);  // canonical: changes no code
  for (const render::KeyDefine& d : render::lightDefines(none, s)) {
    if (d.name == "HV_SHADOWS") {
      EXPECT_EQ(d.value, "0");
    }
    if (d.name == "HV_SHADOW_FILTER") {  // the table's default, and why it changes no code
      EXPECT_EQ(d.value, std::to_string(int(ShadowFilter::Pcss)));
      EXPECT_NE(d.why.find("no shadowed lights"), std::string::npos) << d.why;
    }
  }
  render::VariantKey bad = none;
  bad.settings.shadow_map_size = 512;
  EXPECT_EQ(render::validateKey(bad),
            std::vector<std::string>{"shadow options without shadowed lights"});
}

// A capsule's penumbra stretches along its axis: the filter's ellipse has half-axis
// r + (len / 2) sin(axis, D) along the segment's projection, r across (emitterExtent). The same
// capsule (radius 0.05 m, length 0.8 m) with its axis along the measured row (x) and across it
// (z).
TEST(Shadows, PcssCapsulePenumbraStretchesAlongItsAxis) {
  testContext();
  float widths[2];
  for (int k = 0; k < 2; ++k) {
    Scene s = penumbraScene(0.05f, 1.0f, ShadowFilter::Pcss);
    s.lights[0].type = LightType::Tube;
    s.lights[0].length = 0.8f;
    s.lights[0].axis = k == 0 ? glm::vec3(1, 0, 0) : glm::vec3(0, 0, 1);
    widths[k] = penumbraWidthOf(s);
  }
  std::printf("capsule penumbra 10-90%%: along the axis %.4f m, across it %.4f m\n", widths[0],
              widths[1]);
  ASSERT_TRUE(std::isfinite(widths[0]) && std::isfinite(widths[1]));
  EXPECT_GT(widths[0], 2.0f * widths[1]);
}
