// The Renderer's optional stages (halfvec/render/view_options.hpp), on the GPU, read back:
//  - FXAA leaves a flat (dithered) image unchanged bit for bit and lowers the contrast across a
//    slanted edge without leaving the range of the two sides;
//  - sphere and tube lights drawn as emitters show their surface radiance (emitterRadiance), are
//    not lit by the other lights, and stay out of the G-buffer;
//  - the highlight marks the picked object's pixels and leaves far pixels alone;
//  - each stage is timed as its own pass.
#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "render_fixture.hpp"
#include "halfvec/render/post_aa.hpp"
#include "halfvec/shading/shading.hpp"

using namespace hv;

namespace {

// Runs the FXAA pass on `img` (RGBA8, row 0 = bottom as GL stores it) and reads the result.
std::vector<uint8_t> fxaa(const std::vector<uint8_t>& img, int w, int h) {
  testContext();
  gl::Texture in = gl::createTexture2D("fxaa test input", GL_RGBA8, w, h);
  glTextureSubImage2D(in.id(), 0, 0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, img.data());
  gl::Texture out = gl::createTexture2D("fxaa test output", GL_RGBA8, w, h);
  gl::Framebuffer fbo = gl::createFramebuffer("fxaa test", {{&out}});
  gl::ProgramCache programs;
  render::FxaaPass pass;
  pass.run(programs, in.id(), fbo.id(), w, h);
  std::vector<uint8_t> res(img.size());
  glGetTextureImage(out.id(), 0, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(res.size()), res.data());
  return res;
}

// A step edge of slope 1/3 (x = 64 + y / 3): left dark (40), right bright (220), hard-aliased.
std::vector<uint8_t> slantedEdge(int w, int h) {
  std::vector<uint8_t> img(size_t(w) * h * 4);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const uint8_t v = x < 64 + y / 3 ? 40 : 220;
      uint8_t* p = &img[(size_t(y) * w + x) * 4];
      p[0] = p[1] = p[2] = v;
      p[3] = 255;
    }
  }
  return img;
}

// Sum over rows of the largest step between horizontal neighbors: a hard edge gives 180 per row.
double edgeContrast(const std::vector<uint8_t>& img, int w, int h) {
  double sum = 0;
  for (int y = 0; y < h; ++y) {
    int step = 0;
    for (int x = 1; x < w; ++x) {
      step = std::max(step, std::abs(int(img[(size_t(y) * w + x) * 4]) -
                                     int(img[(size_t(y) * w + x - 1) * 4])));
    }
    sum += step;
  }
  return sum / h;
}

// A camera at the origin looking down -Z at a sphere light and a tube light, nothing else in
// the scene, black environment.
Scene emitterScene() {
  Scene s;
  s.camera.position = {0, 0, 0};
  s.camera.target = {0, 0, -1};
  s.camera.fov_y_deg = 60.0f;
  Light sphere;
  sphere.type = LightType::Sphere;
  sphere.position = {-1.0f, 0.0f, -5.0f};
  sphere.radius = 0.5f;
  sphere.intensity = 4.0f;
  sphere.color = {1.0f, 0.5f, 0.25f};
  Light tube;
  tube.type = LightType::Tube;
  tube.position = {1.5f, 0.0f, -5.0f};
  tube.radius = 0.2f;
  tube.length = 2.0f;
  tube.axis = {0, 1, 0};
  tube.intensity = 3.0f;
  s.lights = {sphere, tube};
  s.environment.kind = EnvironmentKind::Uniform;
  s.environment.color = glm::vec3(0.0f);
  s.environment.cube_size = 16;
  s.environment.prefilter_samples = 8;
  return s;
}

// The pixel (row 0 = top) where world point p lands for a 200x200 image of `s`.
glm::ivec2 project(const Scene& s, glm::vec3 p, int w, int h) {
  const float t = std::tan(glm::radians(s.camera.fov_y_deg) * 0.5f);
  const glm::vec3 v = p - s.camera.position;  // the camera looks down -Z, +Y up
  const float x = v.x / (-v.z * t * float(w) / float(h)), y = v.y / (-v.z * t);
  return {int((x * 0.5f + 0.5f) * float(w)), int((0.5f - y * 0.5f) * float(h))};
}

}  // namespace

TEST(PostAA, FlatImageIsUnchanged) {
  const int w = 64, h = 48;
  std::vector<uint8_t> img(size_t(w) * h * 4);
  for (size_t i = 0; i < img.size(); i += 4) {
    const uint8_t v = uint8_t(128 + int((i / 4) * 7 % 3) - 1);  // +-1 code: the tone map's dither
    img[i] = img[i + 1] = img[i + 2] = v;
    img[i + 3] = 255;
  }
  EXPECT_EQ(fxaa(img, w, h), img);
}

TEST(PostAA, ReducesEdgeContrastOnASlantedEdge) {
  const int w = 128, h = 96;
  const std::vector<uint8_t> img = slantedEdge(w, h);
  const std::vector<uint8_t> out = fxaa(img, w, h);
  const double before = edgeContrast(img, w, h), after = edgeContrast(out, w, h);
  std::printf("largest step across the edge per row: %.1f before, %.1f after FXAA\n", before,
              after);
  EXPECT_NEAR(before, 180.0, 1e-9);
  EXPECT_LT(after, 0.8 * before);
  size_t changed = 0;
  for (size_t i = 0; i < out.size(); i += 4) {
    EXPECT_GE(out[i], 40);  // no overshoot beyond the two sides
    EXPECT_LE(out[i], 220);
    changed += out[i] != img[i];
  }
  EXPECT_GT(changed, size_t(h));  // at least a pixel per row along the edge
  // Far from the edge nothing moves.
  EXPECT_EQ(out[(size_t(10) * w + 5) * 4], 40);
  EXPECT_EQ(out[(size_t(10) * w + 120) * 4], 220);
}

TEST(Emitters, SurfacesShowTheirRadianceUnlitAndStayOutOfTheGBuffer) {
  testContext();
  Scene s = emitterScene();
  Light bright;  // a point light next to the sphere: an emitter must not be lit by it
  bright.position = {-1.0f, 0.0f, -4.0f};
  bright.intensity = 1000.0f;
  s.lights.push_back(bright);
  render::Renderer r;
  r.setScene(s);
  const int w = 200, h = 200;
  r.render(w, h);
  const ImageRGBf off = r.readHdr();
  render::ViewOptions o;
  o.emitters = true;
  r.setViewOptions(o);
  const render::FrameStats stats = r.render(w, h);
  const ImageRGBf on = r.readHdr();
  const GBufferReadback g = r.readGBuffer();

  const glm::ivec2 ps = project(s, s.lights[0].position, w, h);
  const glm::vec3 want_sphere =
      glsl::emitterRadiance(s.lights[0].color * s.lights[0].intensity, 0.5f, 0.0f);
  EXPECT_NEAR(off.at(ps.x, ps.y).x, 0.0f, 1e-6f);
  EXPECT_NEAR(on.at(ps.x, ps.y).x, want_sphere.x, 1e-2f * want_sphere.x);
  EXPECT_NEAR(on.at(ps.x, ps.y).z, want_sphere.z, 1e-2f * want_sphere.z);
  // The tube: its center and a point near its end (0.9 m up the 1 m half length).
  const glm::vec3 want_tube = glsl::emitterRadiance(glm::vec3(3.0f), 0.2f, 2.0f);
  for (float up : {0.0f, 0.9f}) {
    const glm::ivec2 pt = project(s, s.lights[1].position + glm::vec3(0, up, 0), w, h);
    EXPECT_NEAR(on.at(pt.x, pt.y).y, want_tube.y, 1e-2f * want_tube.y) << up;
  }
  // Not in the G-buffer: every pixel is still background, nothing lit.
  EXPECT_TRUE(std::all_of(g.model.begin(), g.model.end(), [](uint32_t m) { return m == 0; }));
  EXPECT_EQ(r.lightWork().lit_pixels, 0u);
  const bool timed = std::any_of(stats.passes.begin(), stats.passes.end(),
                                 [](const auto& p) { return p.first == "emitters"; });
  EXPECT_TRUE(timed);
}

TEST(Emitters, HiddenBehindGeometry) {
  testContext();
  Scene s = emitterScene();
  // A wall between the camera and the lights.
  s.materials.push_back(Material{});
  s.meshes.push_back(makeBox(glm::vec3(5.0f, 5.0f, 0.1f)));
  s.meshes.back().material = 0;
  Object wall;
  wall.meshes = {0};
  wall.transform = glm::translate(glm::mat4(1.0f), glm::vec3(0, 0, -3));
  s.objects.push_back(wall);
  render::Renderer r;
  render::ViewOptions o;
  o.emitters = true;
  r.setViewOptions(o);
  r.setScene(s);
  r.render(200, 200);
  const ImageRGBf img = r.readHdr();
  const glm::ivec2 ps = project(s, s.lights[0].position, 200, 200);
  const float want = glsl::emitterRadiance(s.lights[0].color * 4.0f, 0.5f, 0.0f).x;
  EXPECT_LT(img.at(ps.x, ps.y).x, 0.1f * want);
}

TEST(PostAA, RendererRunsItAsATimedPassOnTheOutput) {
  testContext();
  Scene s = emitterScene();
  render::Renderer r;
  r.setScene(s);
  render::ViewOptions o;
  o.aa = render::PostAA::Fxaa;
  o.emitters = true;
  r.setViewOptions(o);
  const render::FrameStats stats = r.render(160, 120);
  std::vector<std::string> names;
  for (const auto& p : stats.passes) names.push_back(p.first);
  EXPECT_NE(std::find(names.begin(), names.end(), "aa"), names.end());
  EXPECT_EQ(names.back(), "aa");
  // The output read back is the anti-aliased one: the emitters' edges are softened.
  const ImageRGBA8 aa = r.readLdr();
  o.aa = render::PostAA::None;
  r.setViewOptions(o);
  r.render(160, 120);
  const ImageRGBA8 plain = r.readLdr();
  EXPECT_NE(aa.px, plain.px);
}

TEST(Highlight, MarksThePickedObjectOnly) {
  testContext();
  Scene s;
  s.camera.position = {0, 0, 5};
  s.camera.target = {0, 0, 0};
  s.materials.push_back(Material{});
  for (float x : {-1.2f, 1.2f}) {
    s.meshes.push_back(makeSphere(0.5f, 32, 16));
    s.meshes.back().material = 0;
    Object o;
    o.meshes = {int(s.meshes.size()) - 1};
    o.transform = glm::translate(glm::mat4(1.0f), glm::vec3(x, 0, 0));
    s.objects.push_back(o);
  }
  s.environment.kind = EnvironmentKind::Uniform;
  s.environment.color = glm::vec3(0.5f);
  s.environment.cube_size = 16;
  s.environment.prefilter_samples = 8;
  render::Renderer r;
  r.setScene(s);
  r.render(200, 150);
  const ImageRGBA8 plain = r.readLdr();
  render::ViewOptions o;
  o.highlight_object = 1;
  r.setViewOptions(o);
  r.render(200, 150);
  const ImageRGBA8 marked = r.readLdr();
  auto differs = [&](int x, int y) {
    const uint8_t *a = plain.at(x, y), *b = marked.at(x, y);
    return a[0] != b[0] || a[1] != b[1] || a[2] != b[2];
  };
  const glm::ivec2 left = project(s, {-1.2f, 0, 0}, 200, 150);
  const glm::ivec2 right = project(s, {1.2f, 0, 0}, 200, 150);
  EXPECT_FALSE(differs(left.x, left.y));
  EXPECT_TRUE(differs(right.x, right.y));
  EXPECT_GT(int(marked.at(right.x, right.y)[0]), int(marked.at(right.x, right.y)[2]));  // orange
  EXPECT_FALSE(differs(100, 5));  // background far from both
}
