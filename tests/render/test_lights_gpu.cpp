// Light pass on the GPU: the same shared code as the CPU (hv::glsl::evaluateLight) at read-back
// G-buffer pixels, and tiled culling equal to the brute-force baseline.
#include <algorithm>
#include <cmath>
#include <random>

#include <glm/gtc/matrix_transform.hpp>

#include "render_fixture.hpp"
#include "halfvec/render/variant_key.hpp"
#include "halfvec/scene/enums.hpp"
#include "halfvec/shading/light_gpu.hpp"
#include "halfvec/shading/shading.hpp"

using namespace hv;

namespace {

Scene litPlane(LightType type) {
  Material m;
  m.base_color = {0.7f, 0.5f, 0.3f};
  m.metallic = 0.3f;
  m.roughness = 0.4f;
  m.cavity = 0.8f;
  Scene s = planeScene(m);
  Light l;
  l.type = type;
  l.position = {0.3f, 0.5f, -0.2f};
  l.intensity = 3.0f;
  l.radius = type == LightType::Point ? 0.0f : 0.15f;
  l.length = type == LightType::Tube ? 0.6f : 0.0f;
  l.axis = glm::normalize(glm::vec3(1, 0, 1));
  l.range = 5.0f;
  s.lights.push_back(l);
  return s;
}

// `count` lights cycling point, sphere, tube at random positions (x in +-half_xz, y in [y0, y1],
// z in +-half_xz plus z_shift), colors with channels c uniform in [0.2, 1], range range0 +
// range_span * c; radius and length for the types that have them.
struct RandomLights {
  int count = 0;
  uint32_t seed = 1;
  float half_xz = 4.0f, y0 = 0.05f, y1 = 1.0f, z_shift = 0.0f;
  float intensity = 0.05f, range0 = 0.4f, range_span = 0.6f, radius = 0.03f, length = 0.2f;
};

void addRandomLights(Scene& s, const RandomLights& p) {
  std::mt19937 rng(p.seed);
  std::uniform_real_distribution<float> u(-p.half_xz, p.half_xz), h(p.y0, p.y1), c(0.2f, 1.0f);
  for (int i = 0; i < p.count; ++i) {
    Light l;
    l.type = static_cast<LightType>(i % 3);
    l.position = {u(rng), h(rng), u(rng) + p.z_shift};
    l.color = {c(rng), c(rng), c(rng)};
    l.intensity = p.intensity;
    l.range = p.range0 + p.range_span * c(rng);
    l.radius = l.type == LightType::Point ? 0.0f : p.radius;
    l.length = l.type == LightType::Tube ? p.length : 0.0f;
    s.lights.push_back(l);
  }
}

// The culling's cases at the camera: a point light whose culling sphere holds the camera, and a
// small sphere light just in front of it, crossing the near plane.
void addLightsAtTheCamera(Scene& s) {
  Light inside;
  inside.position = s.camera.position + glm::vec3(0.2f, -0.1f, -0.05f);
  inside.range = 3.0f;
  inside.intensity = 0.5f;
  s.lights.push_back(inside);
  Light near_plane = inside;
  near_plane.type = LightType::Sphere;
  near_plane.radius = 0.05f;
  near_plane.position = s.camera.position + glm::vec3(0.0f, 0.0f, -0.12f);
  near_plane.range = 1.0f;
  s.lights.push_back(near_plane);
}

// One tiled frame with DebugOptions::cull_few_lights = few_lights: its image, its list entries
// and whether the one-dispatch culling ran (the stages' timer names say which path did).
struct CulledFrame {
  ImageRGBf hdr;
  size_t entries = 0;
  bool few_ran = false;
};
CulledFrame cullFrame(Scene s, int w, int h, size_t few_lights) {
  s.settings.culling = Culling::Tiled;  // not auto: the tiled side is the one tested
  render::Renderer r;
  render::DebugOptions o;
  o.cull_few_lights = few_lights;
  o.cull_stage_timers = true;
  r.setDebugOptions(o);
  r.setScene(s);
  const render::FrameStats stats = r.render(w, h);
  CulledFrame f;
  f.few_ran = std::any_of(stats.passes.begin(), stats.passes.end(),
                          [](const auto& p) { return p.first == "light_cull_few"; });
  f.entries = stats.tile_light_entries;
  f.hdr = r.readHdr();
  return f;
}

}  // namespace

// Every light type: GPU HDR = CPU evaluateLight on the read-back G-buffer, to the precision of the
// RGBA16F target (11-bit mantissa: 2^-11 relative) plus float differences (stated: 2e-3 relative).
TEST(LightPass, GpuMatchesSharedCpuCode) {
  testContext();
  for (LightType type : {LightType::Point, LightType::Sphere, LightType::Tube}) {
    Scene s = litPlane(type);
    render::Renderer r;
    r.setScene(s);
    const int w = 64, h = 64;
    r.render(w, h);
    const auto g = r.readGBuffer();
    const auto hdr = r.readHdr();
    const auto frame = render::makeFrameBlock(s, w, h);
    const glsl::GpuLight light = toGlsl(packLight(s.lights[0]));
    int checked = 0;
    float worst = 0.0f;
    for (int y = 2; y < h; y += 7) {
      for (int x = 3; x < w; x += 7) {
        const size_t i = size_t(y) * w + x;
        const glm::vec2 uv((x + 0.5f) / w, 1.0f - (y + 0.5f) / h);
        const glm::vec3 P = glsl::reconstructWorldPosition(uv, g.depth[i], frame.inv_view_proj);
        const glm::vec3 V = glm::normalize(s.camera.position - P);
        const glsl::Surface surf = glsl::makeSurface(g.normal[i], g.base_color[i], g.metallic[i],
                                                     g.roughness[i], g.cavity[i]);
        const glm::vec3 cpu = glsl::evaluateLight(light, surf, P, V);
        for (int k = 0; k < 3; ++k) {
          worst = std::max(worst, std::abs(hdr.px[i][k] - cpu[k]) / (cpu[k] + 1e-6f));
          EXPECT_NEAR(hdr.px[i][k], cpu[k], 4e-3f * cpu[k] + 1e-5f)
              << hv::toString(type) << " pixel " << x << "," << y << " channel " << k;
        }
        ++checked;
      }
    }
    EXPECT_GT(checked, 50);
    std::printf("%s: max relative GPU-CPU difference %.2e\n",
                std::string(hv::toString(type)).c_str(), worst);
  }
}

// Tiled culling must find every light that touches a pixel: same image as brute force within
// floating-point summation-order tolerance (stated: 1e-3 relative + 1e-5 absolute per channel).
TEST(LightPass, TiledEqualsBruteForceWith4096Lights) {
  testContext();
  Material m;
  m.base_color = glm::vec3(0.8f);
  m.roughness = 0.5f;
  Scene s = planeScene(m, 8.0f);
  s.camera.position = {0.0f, 3.0f, 4.0f};
  s.camera.up = {0.0f, 1.0f, 0.0f};
  RandomLights lights;
  lights.count = 4096;
  lights.seed = 7;
  addRandomLights(s, lights);
  const int w = 160, h2 = 96;
  s.settings.culling = Culling::Tiled;  // not auto: the tiled side is the one tested
  render::Renderer r;
  r.setScene(s);
  const auto stats = r.render(w, h2);
  const auto tiled = r.readHdr();
  // The list was sized from the CPU bound: no mid-frame read-back, and the bound held the lists.
  EXPECT_EQ(r.tileListReadbacks(), 0u);
  EXPECT_GT(stats.tile_light_entries, 1000u);
  EXPECT_GE(r.tileListCapacity(), stats.tile_light_entries);
  render::DebugOptions ssbo;
  ssbo.light_texel_limit = 1;  // the SSBO path of the light pass (no buffer textures)
  r.setDebugOptions(ssbo);
  r.render(w, h2);
  const auto tiled_ssbo = r.readHdr();
  // The read-back path (bound over the limit): a fresh renderer, so the list starts small and
  // has to grow from the exact total read back between the scan and the fill.
  render::Renderer r2;
  render::DebugOptions readback;
  readback.tile_bound_limit = 0;
  r2.setDebugOptions(readback);
  r2.setScene(s);
  const auto stats2 = r2.render(w, h2);
  const auto tiled_readback = r2.readHdr();
  EXPECT_EQ(r2.tileListReadbacks(), 1u);
  EXPECT_EQ(stats2.tile_light_entries, stats.tile_light_entries);
  // The batched culling path (count, reserve, fill per batch of lights), in 5 batches of 1,000.
  render::Renderer r3;
  render::DebugOptions batched;
  batched.cull_batch_lights = 1000;
  r3.setDebugOptions(batched);
  r3.setScene(s);
  const auto stats3 = r3.render(w, h2);
  const auto tiled_batched = r3.readHdr();
  EXPECT_EQ(stats3.tile_light_entries, stats.tile_light_entries);
  // Each tile's list is in light order whatever the run: the same image to the bit.
  EXPECT_EQ(tiled_batched.px, tiled.px);
  s.settings.culling = Culling::BruteForce;
  r.render(w, h2);
  const auto brute = r.readHdr();
  double max_rel = 0.0, mean = 0.0;
  for (size_t i = 0; i < tiled.px.size(); ++i) {
    for (int k = 0; k < 3; ++k) {
      const float a = tiled.px[i][k], b = brute.px[i][k];
      ASSERT_NEAR(a, b, 1e-3f * b + 1e-5f) << "pixel " << i;
      ASSERT_NEAR(tiled_ssbo.px[i][k], b, 1e-3f * b + 1e-5f) << "SSBO path, pixel " << i;
      ASSERT_NEAR(tiled_readback.px[i][k], b, 1e-3f * b + 1e-5f) << "read-back path, pixel " << i;
      ASSERT_NEAR(tiled_batched.px[i][k], b, 1e-3f * b + 1e-5f) << "batched path, pixel " << i;
      max_rel = std::max(max_rel, double(std::abs(a - b) / (b + 1e-6f)));
      mean += b;
    }
  }
  EXPECT_GT(mean / tiled.px.size(), 0.01) << "lights should light the plane";
}

// 65,536 lights (no small fixed cap): the culled tile lists outgrow the
// initial index list (grown before the fill from the CPU bound, no cap), and the tiled image still
// equals the sum of every light evaluated on the CPU (hv::glsl::evaluateLight over all 65,536
// lights) at sampled pixels. Tolerance: 3e-3 relative + 1e-5 (RGBA16F target: 2^-11 relative, plus
// float summation order).
TEST(LightPass, Tiled65536LightsMatchCpuSumOverAllLights) {
  testContext();
  Material m;
  m.base_color = glm::vec3(0.6f);
  m.roughness = 0.6f;
  Scene s = planeScene(m, 8.0f);
  s.camera.position = {0.0f, 3.0f, 4.0f};
  s.camera.up = {0.0f, 1.0f, 0.0f};
  RandomLights lights;
  lights.count = 65536;
  lights.seed = 11;
  lights.y1 = 0.5f;
  lights.intensity = 0.002f;
  lights.range0 = 0.3f;
  lights.range_span = 0.3f;
  lights.radius = 0.02f;
  lights.length = 0.1f;
  addRandomLights(s, lights);
  const int w = 96, h2 = 64;
  render::Renderer r;
  r.setScene(s);
  const auto stats = r.render(w, h2);
  EXPECT_GT(stats.tile_light_entries, size_t(65536)) << "lists should outgrow the initial list";
  const auto g = r.readGBuffer();
  const auto hdr = r.readHdr();
  const auto frame = render::makeFrameBlock(s, w, h2);
  std::vector<glsl::GpuLight> packed;
  for (const Light& l : s.lights) packed.push_back(toGlsl(packLight(l)));
  int checked = 0;
  double mean = 0.0;
  for (int y = 3; y < h2; y += 9) {
    for (int x = 5; x < w; x += 13) {
      const size_t i = size_t(y) * w + x;
      if (g.model[i] != static_cast<uint32_t>(ShadingModel::DefaultLit)) continue;
      const glm::vec2 uv((x + 0.5f) / w, 1.0f - (y + 0.5f) / h2);
      const glm::vec3 P = glsl::reconstructWorldPosition(uv, g.depth[i], frame.inv_view_proj);
      const glm::vec3 V = glm::normalize(s.camera.position - P);
      const glsl::Surface surf = glsl::makeSurface(g.normal[i], g.base_color[i], g.metallic[i],
                                                   g.roughness[i], g.cavity[i]);
      glm::vec3 cpu(0.0f);
      for (const auto& l : packed) cpu += glsl::evaluateLight(l, surf, P, V);
      mean += cpu.x;
      for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(hdr.px[i][k], cpu[k], 3e-3f * cpu[k] + 1e-5f)
            << "pixel " << x << "," << y << " channel " << k;
      }
      ++checked;
    }
  }
  EXPECT_GT(checked, 30);
  EXPECT_GT(mean / checked, 0.01) << "the lights should light the plane";
}

// The culling's harder cases, tiled vs brute force (tolerance as above): spheres and boxes at
// several depths in front of a floor (tiles straddling depth discontinuities), lights around and
// behind the camera, one whose sphere contains the camera, and lights crossing the near plane.
TEST(LightPass, TiledEqualsBruteForceDepthEdgesAndCameraInsideLights) {
  testContext();
  Material m;
  m.base_color = glm::vec3(0.8f);
  m.roughness = 0.4f;
  Scene s = planeScene(m, 12.0f);
  s.camera.position = {0.0f, 1.5f, 5.0f};
  s.camera.target = {0.0f, 0.5f, 0.0f};
  s.camera.up = {0.0f, 1.0f, 0.0f};
  s.camera.near_plane = 0.1f;
  s.meshes.push_back(makeSphere(0.5f, 24, 12));
  s.meshes.back().material = 0;
  s.meshes.push_back(makeBox(glm::vec3(0.3f, 0.6f, 0.3f)));
  s.meshes.back().material = 0;
  for (int i = 0; i < 6; ++i) {
    Object o;
    o.meshes = {1 + i % 2};
    o.transform =
        glm::translate(glm::mat4(1.0f), glm::vec3(-2.5f + float(i), 0.6f, 2.5f - 1.2f * float(i)));
    s.objects.push_back(o);
  }
  RandomLights lights;
  lights.count = 600;
  lights.seed = 3;
  lights.half_xz = 6.0f;
  lights.y1 = 2.5f;
  lights.z_shift = 1.0f;  // some behind the camera (z > 5)
  lights.range0 = 0.3f;
  lights.range_span = 1.5f;
  lights.length = 0.3f;
  addRandomLights(s, lights);
  addLightsAtTheCamera(s);

  const int w = 128, h2 = 72;
  s.settings.culling = Culling::Tiled;  // not auto: the tiled side is the one tested
  render::Renderer r;
  r.setScene(s);
  r.render(w, h2);
  const auto tiled = r.readHdr();
  s.settings.culling = Culling::BruteForce;
  r.render(w, h2);
  const auto brute = r.readHdr();
  double mean = 0.0;
  for (size_t i = 0; i < tiled.px.size(); ++i) {
    for (int k = 0; k < 3; ++k) {
      const float a = tiled.px[i][k], b = brute.px[i][k];
      ASSERT_NEAR(a, b, 1e-3f * b + 1e-5f) << "pixel " << i % w << "," << i / w;
      mean += b;
    }
  }
  EXPECT_GT(mean / tiled.px.size(), 0.01) << "lights should light the scene";
}

namespace {
// Largest relative difference between two images (and the mean of b), asserting tiled == brute
// force at every pixel within float summation-order tolerance: 1e-3 relative + 1e-5 absolute.
double expectTiledEqualsBrute(const ImageRGBf& tiled, const ImageRGBf& brute, int w) {
  double mean = 0.0;
  for (size_t i = 0; i < tiled.px.size(); ++i) {
    for (int k = 0; k < 3; ++k) {
      const float a = tiled.px[i][k], b = brute.px[i][k];
      EXPECT_NEAR(a, b, 1e-3f * b + 1e-5f) << "pixel " << i % size_t(w) << "," << i / size_t(w);
      if (std::abs(a - b) > 1e-3f * b + 1e-5f) return -1.0;  // one message is enough
      mean += b;
    }
  }
  return mean / double(tiled.px.size());
}
}  // namespace

// 16,384 small lights (range 0.1 to 0.25 m, radius 2 cm): many lights per tile group, few per
// tile; the fused culling at its largest light count (8 chunks of 2,048 per group). Tiled equals
// brute force, and two renderers produce the same image to the bit (each tile's list in light
// order, whatever the run).
TEST(LightPass, TiledEqualsBruteForceWith16384SmallLights) {
  testContext();
  Material m;
  m.base_color = glm::vec3(0.7f);
  m.roughness = 0.5f;
  Scene s = planeScene(m, 8.0f);
  s.camera.position = {0.0f, 3.0f, 4.0f};
  s.camera.up = {0.0f, 1.0f, 0.0f};
  RandomLights lights;
  lights.count = 16384;
  lights.seed = 5;
  lights.y1 = 0.3f;
  lights.intensity = 0.02f;
  lights.range0 = 0.1f;
  lights.range_span = 0.15f;
  lights.radius = 0.02f;
  lights.length = 0.1f;
  addRandomLights(s, lights);
  const int w = 96, h2 = 64;
  s.settings.culling = Culling::Tiled;  // not auto: the tiled side is the one tested
  render::Renderer r;
  r.setScene(s);
  const auto stats = r.render(w, h2);
  const auto tiled = r.readHdr();
  EXPECT_GT(stats.tile_light_entries, 2000u);
  render::Renderer again;
  again.setScene(s);
  again.render(w, h2);
  EXPECT_EQ(again.readHdr().px, tiled.px) << "renders must be reproducible";
  s.settings.culling = Culling::BruteForce;
  r.render(w, h2);
  EXPECT_GT(expectTiledEqualsBrute(tiled, r.readHdr(), w), 0.01) << "lights should light the plane";
}

// Lights centered on tile corners (their spheres straddle 2 to 4 tiles) at view distances before,
// on and just behind the near plane (0.1 m) and further away, with ranges of 0.15 to 0.6 m: the
// rectangles of spheres crossing the near plane (the whole screen), of spheres entirely nearer
// than it (none), and the tangent rectangles of the others at tile borders. Tiled equals brute
// force, at a size that leaves partial tiles on two edges.
TEST(LightPass, TiledEqualsBruteForceLightsStraddlingTilesAndNearPlane) {
  testContext();
  Material m;
  m.base_color = glm::vec3(0.8f);
  m.roughness = 0.45f;
  Scene s = planeScene(m, 6.0f);
  s.camera.position = {0.0f, 0.25f, 0.0f};
  s.camera.target = {0.0f, 0.05f, -1.0f};
  s.camera.up = {0.0f, 1.0f, 0.0f};
  s.camera.near_plane = 0.1f;
  const int w = 125, h2 = 70;  // partial tiles at the right and top edges, an odd width
  const auto frame = render::makeFrameBlock(s, w, h2);
  const glm::mat4 inv_view = glm::inverse(frame.view);
  int n = 0;
  for (int ty = 0; ty <= h2 / render::kTileHeight; ty += 3) {
    for (int tx = 0; tx <= w / render::kTileSize; tx += 3) {
      for (float z : {0.02f, 0.08f, 0.1f, 0.12f, 0.3f}) {
        const glm::vec2 ndc(2.0f * float(tx * render::kTileSize) / float(w) - 1.0f,
                            2.0f * float(ty * render::kTileHeight) / float(h2) - 1.0f);
        const glm::vec4 view(ndc.x * z / frame.proj[0][0], ndc.y * z / frame.proj[1][1], -z, 1.0f);
        Light l;
        l.type = static_cast<LightType>(n % 3);
        l.position = glm::vec3(inv_view * view);
        l.color = {0.3f + 0.1f * float(n % 7), 0.5f, 0.9f - 0.1f * float(n % 5)};
        l.intensity = 0.01f;
        l.range = 0.15f + 0.05f * float(n % 10);
        l.radius = l.type == LightType::Point ? 0.0f : 0.01f;
        l.length = l.type == LightType::Tube ? 0.05f : 0.0f;
        s.lights.push_back(l);
        ++n;
      }
    }
  }
  s.settings.culling = Culling::Tiled;  // not auto: the tiled side is the one tested
  render::Renderer r;
  r.setScene(s);
  r.render(w, h2);
  const auto tiled = r.readHdr();
  s.settings.culling = Culling::BruteForce;
  r.render(w, h2);
  EXPECT_GT(expectTiledEqualsBrute(tiled, r.readHdr(), w), 1e-3) << "lights should light the floor";
}

// A handful of lights (render::kCullFewLights) is culled in one dispatch (light_cull_few.comp)
// instead of the three stages; both must write the same lists: the same image to the bit and the
// same number of entries, and the image tiled equals brute force (tolerance as above). The scene
// has the staged path's hard cases: tiles straddling depth edges, a light whose sphere holds the
// camera, one crossing the near plane, one behind the camera, a spot (the cone test), every type.
TEST(LightPass, FewLightsCulledInOneDispatchAsByTheStages) {
  testContext();
  Material m;
  m.base_color = glm::vec3(0.8f);
  m.roughness = 0.4f;
  Scene s = planeScene(m, 12.0f);
  s.camera.position = {0.0f, 1.5f, 5.0f};
  s.camera.target = {0.0f, 0.5f, 0.0f};
  s.camera.up = {0.0f, 1.0f, 0.0f};
  s.camera.near_plane = 0.1f;
  s.meshes.push_back(makeSphere(0.5f, 24, 12));
  s.meshes.back().material = 0;
  for (int i = 0; i < 3; ++i) {
    Object o;
    o.meshes = {1};
    o.transform = glm::translate(glm::mat4(1.0f),
                                 glm::vec3(-1.5f + 1.5f * float(i), 0.5f, 1.5f - 1.5f * float(i)));
    s.objects.push_back(o);
  }
  RandomLights lights;
  lights.count = 10;
  lights.seed = 11;
  lights.half_xz = 4.0f;
  lights.y1 = 1.5f;
  lights.z_shift = 1.0f;
  lights.range0 = 0.8f;
  lights.range_span = 2.0f;
  lights.length = 0.3f;
  addRandomLights(s, lights);
  addLightsAtTheCamera(s);
  Light spot;  // a narrow cone onto the middle sphere
  spot.type = LightType::Spot;
  spot.position = {0.5f, 3.0f, 0.5f};
  spot.direction = glm::normalize(glm::vec3(-0.5f, -2.5f, -0.5f));
  spot.inner_cone_angle = 0.1f;
  spot.outer_cone_angle = 0.25f;
  spot.range = 6.0f;
  spot.intensity = 8.0f;
  s.lights.push_back(spot);
  ASSERT_LE(s.lights.size(), render::kCullFewLights);

  const int w = 125, h2 = 70;  // partial tiles at two edges
  const CulledFrame few = cullFrame(s, w, h2, render::kCullFewLights);
  const CulledFrame staged = cullFrame(s, w, h2, 0);
  EXPECT_TRUE(few.few_ran);
  EXPECT_FALSE(staged.few_ran);
  EXPECT_GT(few.entries, 0u);
  EXPECT_EQ(few.entries, staged.entries);
  EXPECT_EQ(few.hdr.px, staged.hdr.px) << "the two paths' lists must be the same, in light order";
  s.settings.culling = Culling::BruteForce;
  render::Renderer r;
  r.setScene(s);
  r.render(w, h2);
  EXPECT_GT(expectTiledEqualsBrute(few.hdr, r.readHdr(), w), 1e-3)
      << "lights should light the scene";
}

// Beyond kCullFewLights, lights that reach kCullFewCoverage of the tiles on average
// (kCullFewCoveringLights of them at most) take the one dispatch too, the same lists as the
// stages; as many small lights take the stages.
TEST(LightPass, CoveringLightsCulledInOneDispatch) {
  testContext();
  Material m;
  m.base_color = glm::vec3(0.8f);
  m.roughness = 0.5f;
  const int w = 96, h2 = 64;
  auto lightsOfRange = [&](float range) {
    Scene s = planeScene(m, 8.0f);
    s.camera.position = {0.0f, 3.0f, 4.0f};
    s.camera.up = {0.0f, 1.0f, 0.0f};
    RandomLights lights;
    lights.count = int(render::kCullFewCoveringLights);
    lights.seed = 13;
    lights.range0 = range;
    lights.range_span = 0.0f;
    addRandomLights(s, lights);
    return s;
  };
  static_assert(render::kCullFewCoveringLights > render::kCullFewLights);
  const CulledFrame large = cullFrame(lightsOfRange(30.0f), w, h2, render::kCullFewLights);
  const CulledFrame large_staged = cullFrame(lightsOfRange(30.0f), w, h2, 0);
  EXPECT_TRUE(large.few_ran) << "lights that cover the screen: one dispatch";
  EXPECT_FALSE(large_staged.few_ran);
  EXPECT_EQ(large.hdr.px, large_staged.hdr.px);
  const CulledFrame small = cullFrame(lightsOfRange(0.4f), w, h2, render::kCullFewLights);
  EXPECT_FALSE(small.few_ran) << "small lights: the stages";
  double mean = 0.0;
  for (const auto& p : small.hdr.px) mean += p.x;
  EXPECT_GT(mean, 0.0) << "the small lights should light the plane";
}

// culling: auto picks brute force for two point lights whose spheres hold the camera (every tile
// lists both: chooseCulling), and the image is the tiled one bit for bit: both sum the same
// lights in light order.
TEST(LightPass, AutoCullingOfAFewPointLightsRendersAsTiled) {
  testContext();
  Material m;
  m.base_color = glm::vec3(0.8f);
  m.roughness = 0.4f;
  Scene s = planeScene(m, 12.0f);
  s.camera.position = {0.0f, 1.5f, 5.0f};
  s.camera.target = {0.0f, 0.0f, 0.0f};
  s.camera.up = {0.0f, 1.0f, 0.0f};
  for (int i = 0; i < 2; ++i) {
    Light l;
    l.position = {-2.0f + 4.0f * float(i), 0.5f, -1.0f + float(i)};
    l.range = 30.0f;
    l.intensity = 2.0f;
    l.color = {0.4f + 0.3f * float(i), 0.8f, 1.0f - 0.3f * float(i)};
    s.lights.push_back(l);
  }
  ASSERT_EQ(s.settings.culling, Culling::Auto);
  ASSERT_EQ(render::deriveVariantKey(s).settings.culling, Culling::BruteForce)
      << render::chooseCulling(s).why;
  const int w = 128, h2 = 72;
  render::Renderer r;
  r.setScene(s);
  const render::FrameStats auto_stats = r.render(w, h2);
  const auto brute = r.readHdr();
  for (const auto& [pass, ms] : auto_stats.passes) EXPECT_NE(pass, "light_cull");
  s.settings.culling = Culling::Tiled;
  const render::FrameStats tiled_stats = r.render(w, h2);
  const auto tiled = r.readHdr();
  EXPECT_TRUE(std::any_of(tiled_stats.passes.begin(), tiled_stats.passes.end(),
                          [](const auto& p) { return p.first == "light_cull"; }));
  double mean = 0.0;
  ASSERT_EQ(tiled.px.size(), brute.px.size());
  for (size_t i = 0; i < tiled.px.size(); ++i) {
    for (int k = 0; k < 3; ++k) {
      ASSERT_EQ(tiled.px[i][k], brute.px[i][k]) << "pixel " << i % w << "," << i / w;
      mean += tiled.px[i][k];
    }
  }
  EXPECT_GT(mean / double(tiled.px.size()), 0.01) << "the lights should light the plane";
}

// The benchmark probes of the light pass (render::LightPassProbe, `halfvec bench --breakdown`)
// measure what they claim. Both start each lit pixel at setupProbeValue (shaders/common/
// probes.glsl) of its per-pixel setup, recomputed here on the CPU from the read-back G-buffer: the
// stored value proves the G-buffer fetches, position reconstruction and surface setup ran (a
// probe whose compiler dropped the setup would store something else). FetchOnly also walks each
// pixel's tile list and reads its lights: it adds the sum of the premultiplied colors of the
// lights in its tile (a light outside the view adds nothing). SetupOnly runs no light loop.
// Switching back to Shade gives the real image again. Tolerance: RGBA16F (2^-11 relative) plus
// float differences between the two compilers, as GpuMatchesSharedCpuCode: 4e-3 relative.
TEST(LightPass, BenchmarkProbesDoWhatTheyMeasure) {
  testContext();
  using Probe = render::LightPassProbe;
  auto probe = [](Probe p) {
    render::DebugOptions o;
    o.light_probe = p;
    return o;
  };
  Scene s = litPlane(LightType::Point);
  s.lights[0].color = {1.0f, 0.5f, 0.25f};
  Light sphere = litPlane(LightType::Sphere).lights[0];
  sphere.color = {0.25f, 1.0f, 0.5f};
  sphere.intensity = 2.0f;
  Light tube = litPlane(LightType::Tube).lights[0];
  tube.color = {0.5f, 0.25f, 1.0f};
  tube.intensity = 0.5f;
  Light far_away = s.lights[0];
  far_away.position = {100.0f, 0.5f, 0.0f};  // range 5: touches no visible tile
  far_away.intensity = 50.0f;
  s.lights.insert(s.lights.end(), {sphere, tube, far_away});
  glm::vec3 in_view(0.0f);  // every visible pixel is within range 5 of the first three
  for (int i = 0; i < 3; ++i) in_view += s.lights[i].color * s.lights[i].intensity;
  const int w = 64, h = 48;
  render::Renderer r;
  r.setScene(s);
  r.render(w, h);
  const auto shaded = r.readHdr();
  const auto g = r.readGBuffer();
  const auto frame = render::makeFrameBlock(s, w, h);
  // The probes' setup value of every pixel, from the CPU's copy of the shared code.
  std::vector<glm::vec3> setup(size_t(w) * h);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const size_t i = size_t(y) * w + x;
      ASSERT_EQ(g.model[i], static_cast<uint32_t>(ShadingModel::DefaultLit)) << "pixel " << i;
      const glm::vec2 uv((x + 0.5f) / w, 1.0f - (y + 0.5f) / h);
      const glm::vec3 P = glsl::reconstructWorldPosition(uv, g.depth[i], frame.inv_view_proj);
      const glsl::Surface surf = glsl::makeSurface(g.normal[i], g.base_color[i], g.metallic[i],
                                                   g.roughness[i], g.cavity[i]);
      setup[i] = glsl::setupProbeValue(
          surf, glsl::makeShadingPoint(surf, P, glm::normalize(s.camera.position - P)));
    }
  }
  auto expectNear = [](const ImageRGBf& img, const std::vector<glm::vec3>& want, const char* what) {
    for (size_t i = 0; i < want.size(); ++i) {
      for (int k = 0; k < 3; ++k) {
        ASSERT_NEAR(img.px[i][k], want[i][k], 4e-3f * want[i][k] + 1e-4f)
            << what << ", pixel " << i << " channel " << k;
      }
    }
  };

  r.setDebugOptions(probe(Probe::FetchOnly));
  r.render(w, h);
  std::vector<glm::vec3> want = setup;
  for (glm::vec3& v : want) v += in_view;
  expectNear(r.readHdr(), want, "FetchOnly = setup + lights in the tile");

  r.setDebugOptions(probe(Probe::SetupOnly));
  r.render(w, h);
  expectNear(r.readHdr(), setup, "SetupOnly = setup");

  r.setDebugOptions(probe(Probe::Shade));
  r.render(w, h);
  const auto again = r.readHdr();
  float lit = 0.0f;
  for (size_t i = 0; i < shaded.px.size(); ++i) {
    ASSERT_EQ(again.px[i], shaded.px[i]) << "pixel " << i;
    lit += shaded.px[i].x;
  }
  EXPECT_GT(lit / float(shaded.px.size()), 0.01f) << "the real pass should light the plane";
}
