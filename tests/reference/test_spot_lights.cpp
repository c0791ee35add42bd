// Spot lights on the GPU against the CPU reference and against their own point and sphere
// lights: a spot over a floor is the point light inside the inner cone, 0 outside the outer one
// and the point light times KHR_lights_punctual's profile between (docs/lights.md, "Spot
// lights"); the culling's cone sphere touches fewer tiles than the range sphere and drops no lit
// pixel.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "halfvec/reference/reference.hpp"
#include "halfvec/render/renderer.hpp"
#include "halfvec/scene/primitives.hpp"
#include "halfvec/shading/light_gpu.hpp"
#include "halfvec/shading/shading.hpp"
#include "render/render_fixture.hpp"

using namespace hv;

namespace {

constexpr float kInner = 0.3f, kOuter = 0.6f;

// A floor seen from above and a spot 2 m over it aiming straight down: its cone's edge, a
// circle of radius 2 tan(0.6) = 1.37 m, lies inside the view.
Scene floorScene(float radius) {
  Scene s;
  s.camera.position = {0.0f, 5.0f, 1.5f};
  s.camera.target = {0.0f, 0.0f, 0.0f};
  Material m;
  m.base_color = {0.6f, 0.5f, 0.4f};
  m.roughness = 0.4f;
  m.metallic = 0.1f;
  addMeshObject(s, makePlane(8.0f, 8.0f), m, glm::vec3(0.0f));
  Light l;
  l.type = LightType::Spot;
  l.position = {0.2f, 2.0f, 0.1f};
  l.direction = {0.0f, -1.0f, 0.0f};
  l.radius = radius;
  l.inner_cone_angle = kInner;
  l.outer_cone_angle = kOuter;
  l.intensity = 6.0f;
  l.range = 8.0f;
  s.lights.push_back(l);
  s.environment.kind = EnvironmentKind::None;
  s.settings.falloff_plus_one = false;  // physical mode used for accuracy comparisons
  return s;
}

Scene asShape(Scene s) {
  for (Light& l : s.lights) l.type = lightShape(l);
  return s;
}

// Calls f(i, P) for every lit pixel i of frame `f` (w x h) with its world position P, as the
// light pass reconstructs it from the depth.
template <class F>
void forEachLitPixel(const Scene& s, const GBufferReadback& g, int w, int h, F&& f) {
  const glm::mat4 inv_vp = referenceInvViewProj(s.camera, w, h);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const size_t i = size_t(y) * size_t(w) + size_t(x);
      if (g.model[i] != static_cast<uint32_t>(ShadingModel::DefaultLit)) continue;
      const glm::vec2 uv((float(x) + 0.5f) / float(w), 1.0f - (float(y) + 0.5f) / float(h));
      f(i, glsl::reconstructWorldPosition(uv, g.depth[i], inv_vp));
    }
  }
}

}  // namespace

// The point spot against the reference (both exact: the point light's tolerance, 4e-3 relative
// over the RGBA16F target, tests/reference/test_engine_vs_reference.cpp) and against the point
// light the engine renders without the cone, region by region of the cone.
TEST(SpotLights, PointSpotOverAFloorFollowsTheCone) {
  const int w = 96, h = 72;
  const Scene s = floorScene(0.0f);
  const RenderedFrame spot = renderFrame(s, w, h), point = renderFrame(asShape(s), w, h);
  ReferenceOptions o;
  o.samples = 4;  // point lights are analytic: no noise
  const auto ref = renderReference(s, spot.g, o);
  const float ci = std::cos(kInner), co = std::cos(kOuter);
  int inner = 0, edge = 0, outside = 0;
  forEachLitPixel(s, spot.g, w, h, [&](size_t i, glm::vec3 P) {
    const float c = glm::dot(glm::normalize(P - s.lights[0].position), s.lights[0].direction);
    const float t = std::clamp((c - co) / (ci - co), 0.0f, 1.0f);
    for (int k = 0; k < 3; ++k) {
      const float e = spot.hdr.px[i][k], p = point.hdr.px[i][k];
      ASSERT_NEAR(e, ref.image.px[i][k], 4e-3f * ref.image.px[i][k] + 1e-5f) << "pixel " << i;
      if (c > ci + 1e-3f) {
        ASSERT_NEAR(e, p, 1e-5f * p) << "inner cone, pixel " << i;
      } else if (c < co - 1e-3f) {
        ASSERT_EQ(e, 0.0f) << "outside the outer cone, pixel " << i;
      } else {
        // The profile t^2 (half-float rounding of both images, 2 x 2^-11 relative).
        ASSERT_NEAR(e, p * t * t, 1e-3f * p + 1e-6f) << "cone edge, pixel " << i << " t " << t;
      }
    }
    inner += c > ci + 1e-3f;
    outside += c < co - 1e-3f;
    edge += c <= ci + 1e-3f && c >= co - 1e-3f;
  });
  EXPECT_GT(inner, 300);
  EXPECT_GT(edge, 300);
  EXPECT_GT(outside, 1000);
}

// A sphere spot is its sphere light times the cone of the direction to its center, in the engine
// (both specular methods) and in the reference (the same emitter samples, each scaled).
TEST(SpotLights, SphereSpotIsTheSphereTimesTheCone) {
  const int w = 64, h = 48;
  for (SphereSpecular method : {SphereSpecular::RepresentativePoint, SphereSpecular::Ltc}) {
    Scene s = floorScene(0.25f);
    s.settings.sphere_specular = method;
    const RenderedFrame spot = renderFrame(s, w, h), sphere = renderFrame(asShape(s), w, h);
    ReferenceOptions o;
    o.samples = 16;
    const auto ref_spot = renderReference(s, spot.g, o);
    const auto ref_sphere = renderReference(asShape(s), spot.g, o);
    const GpuLight gl = packLight(s.lights[0]);
    int edge = 0;
    forEachLitPixel(s, spot.g, w, h, [&](size_t i, glm::vec3 P) {
      const float cone =
          glsl::spotAttenuation(glm::normalize(s.lights[0].position - P), gl.axis_length);
      edge += cone > 0.0f && cone < 1.0f;
      for (int k = 0; k < 3; ++k) {
        const float b = sphere.hdr.px[i][k] * cone;
        ASSERT_NEAR(spot.hdr.px[i][k], b, 1e-3f * b + 1e-6f) << "engine, pixel " << i;
        const float rb = ref_sphere.image.px[i][k] * cone;
        ASSERT_NEAR(ref_spot.image.px[i][k], rb, 1e-4f * rb + 1e-7f) << "reference, pixel " << i;
      }
    });
    EXPECT_GT(edge, 100);
  }
}

// 48 narrow spots (outer 0.15-0.35 rad) of range 6 aimed at the floor from 3 m: tiled culling with
// the cone's sphere and the cone itself against each block's and tile's surface box
// (sphereOutsideCone, cull.glsl) against the range sphere (the same lights as points), and the
// culled image against brute force (the tolerance of LightPass.TiledEqualsBruteForceWith4096Lights:
// summation order, 1e-3 relative + 1e-5), with no pixel lit by brute force left dark. With the
// cone's sphere alone the entries were 4,714 of the points' 10,258 (0.46, measured before the
// cone test existed); the cone test must take at least a fifth more of them away.
TEST(SpotLights, ConeCullingTouchesFewerTilesAndMissesNoPixel) {
  testContext();
  Scene s = floorScene(0.0f);
  s.camera.position = {0.0f, 7.0f, 5.0f};
  s.lights.clear();
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  for (int i = 0; i < 48; ++i) {
    Light l;
    l.type = LightType::Spot;
    l.position = {8.0f * u(rng) - 4.0f, 3.0f, 8.0f * u(rng) - 4.0f};
    l.direction = glm::normalize(glm::vec3(u(rng) - 0.5f, -1.0f, u(rng) - 0.5f));
    l.outer_cone_angle = 0.15f + 0.2f * u(rng);
    l.inner_cone_angle = 0.5f * l.outer_cone_angle;
    l.radius = i % 2 ? 0.05f : 0.0f;  // point and sphere spots
    l.intensity = 20.0f;
    l.range = 6.0f;
    l.color = {u(rng), u(rng), u(rng)};
    s.lights.push_back(l);
  }
  const int w = 160, h = 96;
  s.settings.culling = Culling::Tiled;
  render::Renderer r;
  r.setScene(s);
  const size_t cone_tiles = r.render(w, h).tile_light_entries;
  const ImageRGBf tiled = r.readHdr();
  const Scene points = asShape(s);  // the renderer keeps a reference to its scene
  render::Renderer rp;
  rp.setScene(points);
  const size_t range_tiles = rp.render(w, h).tile_light_entries;
  std::printf("tile-light entries: cones %zu, range spheres %zu (%.2f)\n", cone_tiles, range_tiles,
              double(cone_tiles) / double(range_tiles));
  EXPECT_LT(cone_tiles, range_tiles / 2);
  EXPECT_LT(cone_tiles, size_t(0.8 * 4714));
  s.settings.culling = Culling::BruteForce;
  render::Renderer rb;
  rb.setScene(s);
  rb.render(w, h);
  const ImageRGBf brute = rb.readHdr();
  size_t lit = 0;
  for (size_t i = 0; i < tiled.px.size(); ++i) {
    for (int k = 0; k < 3; ++k) {
      const float a = tiled.px[i][k], b = brute.px[i][k];
      ASSERT_NEAR(a, b, 1e-3f * b + 1e-5f) << "pixel " << i;
      if (b > 0.0f) {
        ASSERT_GT(a, 0.0f) << "a lit pixel culled away: " << i;
      }
    }
    lit += brute.px[i][0] + brute.px[i][1] + brute.px[i][2] > 0.0f;
  }
  EXPECT_GT(lit, tiled.px.size() / 10);
}

// "shadows": true on a spot: a point light's cube map. A sphere 1 m under the spot (hard filter)
// darkens the floor points whose ray to the light passes through it, 5 cm inside its silhouette
// (below 2% of the unshadowed value), and leaves the floor points whose ray clears it by 5 cm as
// they are without shadows (the half-float tolerance of the cone test above).
TEST(SpotLights, ShadowsFromAPointLightsCube) {
  const int w = 96, h = 72;
  Scene lit = floorScene(0.0f);
  Material m;
  const glm::vec3 center = lit.lights[0].position - glm::vec3(0.0f, 1.0f, 0.0f);
  const float r = 0.3f;
  addMeshObject(lit, makeSphere(r, 48, 24), m, center);
  Scene shadowed = lit;
  shadowed.lights[0].shadows = true;
  shadowed.settings.shadow_filter = ShadowFilter::Hard;
  const RenderedFrame a = renderFrame(lit, w, h), b = renderFrame(shadowed, w, h);
  const glm::vec3 light = lit.lights[0].position;
  int dark = 0, clear = 0;
  forEachLitPixel(lit, a.g, w, h, [&](size_t i, glm::vec3 P) {
    if (std::abs(P.y) > 1e-2f || a.hdr.px[i][0] <= 0.0f) return;  // lit floor points only
    // Distance from the sphere's center to the segment from P to the light.
    const glm::vec3 d = glm::normalize(light - P);
    const float t = glm::dot(center - P, d);
    const float miss = glm::length(center - (P + d * t));
    for (int k = 0; k < 3; ++k) {
      const float unshadowed = a.hdr.px[i][k], v = b.hdr.px[i][k];
      if (miss < r - 0.05f) {
        ASSERT_LT(v, 0.02f * unshadowed) << "in the shadow, pixel " << i;
      } else if (miss > r + 0.05f) {
        ASSERT_NEAR(v, unshadowed, 1e-3f * unshadowed + 1e-6f) << "clear, pixel " << i;
      }
    }
    dark += miss < r - 0.05f;
    clear += miss > r + 0.05f;
  });
  EXPECT_GT(dark, 100);
  EXPECT_GT(clear, 300);
}
