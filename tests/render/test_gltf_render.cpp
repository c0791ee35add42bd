// glTF models from the shared assets rendered headless: every model loads and renders with a
// finite HDR output, and the normal-map orientation tests (NormalTangentTest, generated tangents;
// NormalTangentMirrorTest, supplied tangents with w = +-1) shade their normal-mapped cells the same
// way round as the real geometry next to them. Skipped, with the reason, without the assets.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <limits>

#include "render_fixture.hpp"
#include "halfvec/scene/gltf_loader.hpp"
#include "shared_assets.hpp"

namespace fs = std::filesystem;
using namespace hv;
using hv::test::assetsDir;
using hv::test::gltfFiles;

namespace {

// World-space bounds of everything in the scene.
void sceneBounds(const Scene& s, glm::vec3& lo, glm::vec3& hi) {
  lo = glm::vec3(std::numeric_limits<float>::max());
  hi = -lo;
  for (const Object& o : s.objects)
    for (int m : o.meshes)
      for (const Vertex& v : s.meshes[size_t(m)].vertices) {
        const glm::vec3 p = glm::vec3(o.transform * glm::vec4(v.position, 1.0f));
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
      }
}

// Frames the model from +z (the glTF front) with a point light near the camera and a uniform
// environment, so every channel (direct and ambient) is exercised.
void frameFromFront(Scene& s, float fov_deg) {
  glm::vec3 lo, hi;
  sceneBounds(s, lo, hi);
  const glm::vec3 c = 0.5f * (lo + hi);
  const float r = std::max(0.5f * glm::length(hi - lo), 1e-3f);
  const float dist = r / std::tan(glm::radians(0.5f * fov_deg)) + r;
  s.camera.position = c + glm::vec3(0.0f, 0.0f, dist);
  s.camera.target = c;
  s.camera.fov_y_deg = fov_deg;
  s.camera.near_plane = std::max(dist - 2.0f * r, dist * 1e-3f);
  Light l;
  l.position = c + glm::vec3(0.3f * r, 0.5f * r, dist * 0.8f);
  l.intensity = 5.0f * dist * dist;
  l.range = 4.0f * dist;
  s.lights.push_back(l);
  s.environment.kind = EnvironmentKind::Uniform;
  s.environment.color = glm::vec3(0.3f);
  s.environment.cube_size = 32;
  s.environment.prefilter_samples = 32;
}

struct RenderCheck {
  size_t non_finite = 0, negative = 0, drawn = 0;
};

RenderCheck renderAndCheck(render::Renderer& r, const Scene& s, int size) {
  r.setScene(s);
  r.render(size, size);
  const ImageRGBf hdr = r.readHdr();
  const GBufferReadback g = r.readGBuffer();
  RenderCheck c;
  for (size_t i = 0; i < hdr.px.size(); ++i) {
    for (int k = 0; k < 3; ++k) {
      const float v = hdr.px[i][k];
      if (!std::isfinite(v)) ++c.non_finite;
      if (v < 0.0f) ++c.negative;
    }
    if (g.model[i] != 0) ++c.drawn;
  }
  return c;
}

}  // namespace

// Every model in gltf/ and every set under gltf-asset-generator/Positive: loads, renders at
// 64x64 with no NaN, Inf or negative HDR value. Prints the pass/fail count.
TEST(GltfRender, SharedModelsRenderFinite) {
  const fs::path root = assetsDir();
  if (root.empty() || !fs::is_directory(root / "gltf"))
    GTEST_SKIP() << "no shared assets (set HV_ASSETS_DIR or -DHV_ASSETS_DIR; looked in '" << root
                 << "')";
  testContext();
  render::Renderer r;
  int pass = 0, fail = 0, empty = 0;
  std::vector<fs::path> files = gltfFiles(root / "gltf");
  const size_t sample_models = files.size();  // these must draw; generator sets may not
  if (fs::is_directory(root / "gltf-asset-generator" / "Positive")) {
    auto more = gltfFiles(root / "gltf-asset-generator" / "Positive");
    files.insert(files.end(), more.begin(), more.end());
  }
  for (size_t f = 0; f < files.size(); ++f) {
    const fs::path& p = files[f];
    Scene s;
    std::vector<std::string> warnings;
    GltfOptions opt;
    opt.warnings = &warnings;
    try {
      loadGltf(p.string(), glm::mat4(1.0f), s, opt);
    } catch (const SceneError& e) {
      ADD_FAILURE() << e.what();
      ++fail;
      continue;
    }
    frameFromFront(s, 40.0f);
    const RenderCheck c = renderAndCheck(r, s, 64);
    const bool ok = c.non_finite == 0 && c.negative == 0;
    EXPECT_EQ(c.non_finite, 0u) << p;
    EXPECT_EQ(c.negative, 0u) << p;
    if (f < sample_models) {
      EXPECT_GT(c.drawn, 0u) << p;
    }
    if (c.drawn == 0) {  // e.g. only points/lines (skipped with a warning), or alpha cutoff > 1
      ++empty;
      std::cout << "  drew no pixel: " << p.filename().string()
                << (warnings.empty() ? std::string() : " (" + warnings.front() + ")") << "\n";
    }
    ok ? ++pass : ++fail;
  }
  std::cout << "[ glTF render ] " << pass << " finite, " << fail << " failed, " << empty
            << " drew no pixel, of " << files.size() << " files\n";
  EXPECT_GE(pass, 100);
}

namespace {

// The orientation measure. Each test cell of NormalTangent(Mirror)Test is a dome: a real
// hemisphere of geometry on the left of each pair, a flat quad whose normal map encodes the same
// dome on the right (see the models' README and screenshot.png: every cell reflects a level
// horizon, i.e. every cell's normal field is an outward dome). A dome's world normal points away
// from its centre: on its right half n.x > 0, on its upper half n.y > 0. A flipped green channel
// (the README's incorrect-flipped-y.png) flips n.y on the normal-mapped cells; a wrong tangent
// handedness (supplied-tangents-ignored.png) flips n.x on the mirrored ones. So per cell we take
// the mean of n.x * sign(x - cx) and of n.y * sign(cy - y) over its tilted pixels; both must be
// clearly positive. Cells are the connected regions of pixels whose normal tilts more than ~11
// degrees from the view axis.
struct CellResult {
  int cells = 0, bad_x = 0, bad_y = 0, bad = 0;  // bad: either component the wrong way
};

CellResult domeOrientation(const GBufferReadback& g) {
  const int w = g.width, h = g.height;
  std::vector<int> label(size_t(w) * size_t(h), -1);
  auto tilted = [&](size_t i) { return g.model[i] != 0 && g.normal[i].z < 0.98f; };
  CellResult res;
  std::vector<size_t> stack, members;
  for (size_t start = 0; start < label.size(); ++start) {
    if (label[start] >= 0 || !tilted(start)) continue;
    members.clear();
    stack.assign(1, start);
    label[start] = res.cells;
    while (!stack.empty()) {
      const size_t i = stack.back();
      stack.pop_back();
      members.push_back(i);
      const int x = int(i % size_t(w)), y = int(i / size_t(w));
      const int nx[4] = {x - 1, x + 1, x, x}, ny[4] = {y, y, y - 1, y + 1};
      for (int k = 0; k < 4; ++k) {
        if (nx[k] < 0 || ny[k] < 0 || nx[k] >= w || ny[k] >= h) continue;
        const size_t j = size_t(ny[k]) * size_t(w) + size_t(nx[k]);
        if (label[j] < 0 && tilted(j)) {
          label[j] = res.cells;
          stack.push_back(j);
        }
      }
    }
    if (members.size() < 40) continue;  // specks on edges, not a cell
    double cx = 0.0, cy = 0.0;
    for (size_t i : members) {
      cx += double(i % size_t(w));
      cy += double(i / size_t(w));
    }
    cx /= double(members.size());
    cy /= double(members.size());
    double sx = 0.0, sy = 0.0;
    for (size_t i : members) {
      const double x = double(i % size_t(w)), y = double(i / size_t(w));
      sx += g.normal[i].x * (x > cx ? 1.0 : -1.0);
      sy += g.normal[i].y * (y < cy ? 1.0 : -1.0);  // image rows grow downwards
    }
    sx /= double(members.size());
    sy /= double(members.size());
    ++res.cells;
    if (sx < 0.1) ++res.bad_x;
    if (sy < 0.1) ++res.bad_y;
    if (sx < 0.1 || sy < 0.1) ++res.bad;
  }
  return res;
}

Scene orientationScene(const fs::path& file) {
  Scene s;
  std::vector<std::string> warnings;
  GltfOptions opt;
  opt.warnings = &warnings;
  loadGltf(file.string(), glm::mat4(1.0f), s, opt);
  frameFromFront(s, 20.0f);
  return s;
}

void checkOrientation(const char* model, bool mirrored) {
  const fs::path file =
      assetsDir() / "gltf" / model / "glTF-Binary" / (std::string(model) + ".glb");
  if (assetsDir().empty() || !fs::exists(file))
    GTEST_SKIP() << "no shared assets: " << file << " not found (set HV_ASSETS_DIR)";
  testContext();
  render::Renderer r;
  Scene s = orientationScene(file);
  r.setScene(s);
  r.render(512, 512);
  const CellResult good = domeOrientation(r.readGBuffer());
  std::cout << "[ " << model << " ] " << good.cells << " cells, " << good.bad_x
            << " with n.x the wrong way, " << good.bad_y << " with n.y the wrong way\n";
  EXPECT_GE(good.cells, 28) << "15 pairs of cells expected";
  EXPECT_EQ(good.bad_x, 0);
  EXPECT_EQ(good.bad_y, 0);

  // Negative control: the same model with its normal map's green channel inverted (the mistake
  // of incorrect-flipped-y.png) must fail the measure on the normal-mapped cells (half of them;
  // a cell whose UVs are rotated by 90 degrees shows the flip in n.x instead of n.y).
  ASSERT_GE(s.materials.size(), 1u);
  const int img = s.materials[0].normal_tex.image;
  ASSERT_GE(img, 0);
  std::vector<uint8_t>& px = s.images[size_t(img)].rgba;
  for (size_t i = 1; i < px.size(); i += 4) px[i] = uint8_t(255 - px[i]);
  r.setScene(s);
  r.render(512, 512);
  const CellResult flipped = domeOrientation(r.readGBuffer());
  std::cout << "[ " << model << " green flipped ] " << flipped.cells << " cells, " << flipped.bad
            << " the wrong way\n";
  EXPECT_GE(flipped.bad, good.cells / 2 - 2);

  if (!mirrored) return;
  // Second control (supplied-tangents-ignored.png): dropping the supplied handedness (w = +1
  // everywhere) must break the cells whose UVs are mirrored.
  for (size_t i = 1; i < px.size(); i += 4) px[i] = uint8_t(255 - px[i]);  // undo the flip
  for (Mesh& m : s.meshes)
    for (Vertex& v : m.vertices) v.tangent.w = 1.0f;
  r.setScene(s);
  r.render(512, 512);
  const CellResult no_w = domeOrientation(r.readGBuffer());
  std::cout << "[ " << model << " w ignored ] " << no_w.cells << " cells, " << no_w.bad
            << " the wrong way\n";
  EXPECT_GE(no_w.bad, 4);
}

}  // namespace

TEST(GltfRender, NormalTangentTestOrientation) {
  checkOrientation("NormalTangentTest", false);
}
TEST(GltfRender, NormalTangentMirrorTestOrientation) {
  checkOrientation("NormalTangentMirrorTest", true);
}
