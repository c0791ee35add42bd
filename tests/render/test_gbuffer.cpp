// G-buffer round trip: known materials rendered, read back and decoded; each channel within its
// quantization step of the input.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "render_fixture.hpp"
#include "halfvec/render/frame_data.hpp"
#include "halfvec/render/gpu_scene.hpp"
#include "halfvec/shading/shading.hpp"

using namespace hv;

namespace {
// Linear -> 8-bit sRGB -> linear: the exact value the SRGB8 target returns.
float srgbRoundTrip(float x) {
  float s = x <= 0.0031308f ? 12.92f * x : 1.055f * std::pow(x, 1.0f / 2.4f) - 0.055f;
  s = std::round(s * 255.0f) / 255.0f;
  return s <= 0.04045f ? s / 12.92f : std::pow((s + 0.055f) / 1.055f, 2.4f);
}
}  // namespace

// packMaterial fills hv::GpuMaterial, the record gbuffer.frag reads (gpu_records.glsl), by name:
// each field holds the scene value it is named for, the flags are the texture bits of the textures
// present, and the emissive texture's UV set is an integer like the others.
TEST(GBuffer, PackMaterialFillsTheNamedFields) {
  Material m;
  m.base_color = {0.1f, 0.2f, 0.3f};
  m.base_alpha = 0.4f;
  m.metallic = 0.5f;
  m.roughness = 0.6f;
  m.cavity = 0.7f;
  m.alpha_cutoff = 0.8f;
  m.alpha_mode = AlphaMode::Mask;
  m.emissive = {1.0f, 2.0f, 3.0f};
  m.model = ShadingModel::Unlit;
  m.vertex_color = false;
  m.normal_tex.image = 0;
  m.normal_tex.scale = 0.25f;
  m.normal_tex.texcoord = 1;
  m.occlusion_tex.scale = 0.75f;
  m.emissive_tex.image = 1;
  m.emissive_tex.texcoord = 1;
  m.emissive_tex.uv_offset = {0.5f, 0.0f};
  const GpuMaterial g = render::packMaterial(m);
  EXPECT_EQ(g.base_color, glm::vec4(0.1f, 0.2f, 0.3f, 0.4f));
  EXPECT_EQ(g.metallic, 0.5f);
  EXPECT_EQ(g.roughness, 0.6f);
  EXPECT_EQ(g.cavity, 0.7f);
  EXPECT_EQ(g.alpha_cutoff, 0.8f);
  EXPECT_EQ(g.alpha_mode, HV_ALPHA_MASK);
  EXPECT_EQ(g.emissive, glm::vec3(1.0f, 2.0f, 3.0f));
  EXPECT_EQ(g.shading_model, glsl::HV_MODEL_UNLIT);
  EXPECT_EQ(g.normal_scale, 0.25f);
  EXPECT_EQ(g.occlusion_strength, 0.75f);
  EXPECT_EQ(g.texcoord_base_color, 0u);
  EXPECT_EQ(g.texcoord_normal, 1u);
  EXPECT_EQ(g.texcoord_emissive, 1u);
  // Normal and emissive textures present; the emissive one transformed.
  EXPECT_EQ(g.texture_bits, HV_MAT_NORMAL_TEX | HV_MAT_EMISSIVE_TEX | HV_MAT_TEX_TRANSFORM_BIT);
  EXPECT_EQ(g.uv_offset[HV_MAT_SLOT_EMISSIVE], glm::vec4(0.5f, 0.0f, 0.0f, 0.0f));
  EXPECT_EQ(g.uv_linear[HV_MAT_SLOT_BASE_COLOR], glm::vec4(1.0f, 0.0f, 0.0f, 1.0f));
  Material opaque;  // vertex colours on by default, no texture
  EXPECT_EQ(render::packMaterial(opaque).alpha_mode, HV_ALPHA_OPAQUE);
  EXPECT_EQ(render::packMaterial(opaque).texture_bits, HV_MAT_VERTEX_COLOR_BIT);
  EXPECT_EQ(render::packMaterial(opaque).shading_model, glsl::HV_MODEL_DEFAULT_LIT);
}

TEST(GBuffer, RoundTripWithinQuantization) {
  testContext();
  const Material cases[] = {
      [] {
        Material m;
        m.base_color = {0.9f, 0.2f, 0.05f};
        m.metallic = 0.0f;
        m.roughness = 0.25f;
        m.cavity = 0.5f;
        return m;
      }(),
      [] {
        Material m;
        m.base_color = {0.01f, 0.5f, 1.0f};
        m.metallic = 1.0f;
        m.roughness = 1.0f;
        m.cavity = 1.0f;
        return m;
      }(),
      [] {
        Material m;
        m.base_color = {0.0f, 0.0f, 0.0f};
        m.metallic = 0.37f;
        m.roughness = 0.0f;
        m.cavity = 0.0f;
        m.model = ShadingModel::Unlit;
        return m;
      }(),
  };
  for (const Material& m : cases) {
    Scene s = planeScene(m);
    render::Renderer r;
    r.setScene(s);
    r.render(32, 32);
    auto g = r.readGBuffer();
    const size_t c = size_t(16) * 32 + 16;
    for (int k = 0; k < 3; ++k) {
      // Within one 8-bit sRGB code of the input (GL lets the encoder round either way).
      const float want = glsl::srgbEncode(m.base_color[k]);
      const float got = glsl::srgbEncode(g.base_color[c][k]);
      EXPECT_NEAR(got, want, 1.0f / 255.0f + 1e-5f) << "base color channel " << k;
      EXPECT_NEAR(g.base_color[c][k], srgbRoundTrip(m.base_color[k]), 0.01f);
    }
    EXPECT_NEAR(g.metallic[c], m.metallic, 0.5f / 255.0f + 1e-6f);
    // Roughness is stored in 16 bits (docs/gbuffer.md): half a 16-bit step.
    EXPECT_NEAR(g.roughness[c], m.roughness, 0.5f / 65535.0f + 1e-7f);
    EXPECT_NEAR(g.cavity[c], m.cavity, 0.5f / 255.0f + 1e-6f);
    EXPECT_EQ(g.model[c], static_cast<uint32_t>(m.model));
    // Plane normal +y; budget from docs/gbuffer.md (0.005 degrees).
    const float angle = std::acos(std::min(1.0f, glm::dot(g.normal[c], glm::vec3(0, 1, 0))));
    EXPECT_LT(glm::degrees(angle), 0.005f);
  }
}

// Roughness values between two 8-bit codes (where one byte would be off by up to half a code,
// 8% of the highlight peak at 0.1) come back within half a 16-bit code: both bytes of RT1 reach
// the target and the read-back decodes them as the passes do.
TEST(GBuffer, RoughnessKeeps16Bits) {
  testContext();
  for (float roughness : {0.045f, 0.0471f, 0.1f, 0.1013f, 0.2468f, 0.5f, 0.7531f, 0.999f}) {
    Material m;
    m.roughness = roughness;
    Scene s = planeScene(m);
    render::Renderer r;
    r.setScene(s);
    r.render(8, 8);
    auto g = r.readGBuffer();
    const float got = g.roughness[size_t(4) * 8 + 4];
    EXPECT_NEAR(got, roughness, 0.5f / 65535.0f + 1e-7f) << "roughness " << roughness;
  }
}

TEST(GBuffer, DepthReconstructsWorldPosition) {
  testContext();
  Scene s = planeScene(Material{});
  render::Renderer r;
  r.setScene(s);
  const int w = 48, h = 32;
  r.render(w, h);
  auto g = r.readGBuffer();
  const auto frame = render::makeFrameBlock(s, w, h);
  float worst = 0.0f;
  for (int y = 0; y < h; y += 5) {
    for (int x = 0; x < w; x += 5) {
      const float d = g.depth[size_t(y) * w + x];
      ASSERT_GT(d, 0.0f);
      // readback rows are top-down; GL uv has v up.
      const glm::vec2 uv((x + 0.5f) / w, 1.0f - (y + 0.5f) / h);
      const glm::vec3 p = glsl::reconstructWorldPosition(uv, d, frame.inv_view_proj);
      worst = std::max(worst, std::abs(p.y));  // the plane is y = 0
    }
  }
  EXPECT_LT(worst, 1e-4f) << "world position off the plane by " << worst;
}

// A normal facing away from the viewer on a face that faces it (normal maps and interpolated
// normals give them) is stored reflected about the plane across V (viewFacingNormal,
// gbuffer.glsl): every stored normal faces the viewer, and each is the reflection of the
// vertex normal within the RG16 encoding's step. The plane's vertex normals lean along +x, so
// seen from above the pixels at x > 0.4 m had N.V < 0.
TEST(GBuffer, NormalsFacingAwayAreStoredFacingTheViewer) {
  testContext();
  Scene s = planeScene(Material{});
  const glm::vec3 N0 = glm::normalize(glm::vec3(1.0f, 0.2f, 0.0f));
  for (Vertex& v : s.meshes[0].vertices) v.normal = N0;
  render::Renderer r;
  r.setScene(s);
  const int w = 64, h = 64;
  r.render(w, h);
  const auto g = r.readGBuffer();
  const auto frame = render::makeFrameBlock(s, w, h);
  int away = 0, lit = 0;
  float worst_facing = 1.0f, worst_angle = 0.0f;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const size_t i = size_t(y) * w + x;
      if (!isLit(ShadingModel(g.model[i]))) continue;
      ++lit;
      const glm::vec2 uv((x + 0.5f) / w, 1.0f - (y + 0.5f) / h);
      const glm::vec3 P = glsl::reconstructWorldPosition(uv, g.depth[i], frame.inv_view_proj);
      const glm::vec3 V = glm::normalize(s.camera.position - P);
      away += glm::dot(N0, V) < 0.0f;
      const glm::vec3 N = glm::normalize(g.normal[i]);
      worst_facing = std::min(worst_facing, glm::dot(N, V));
      const float c = glm::clamp(glm::dot(N, glsl::viewFacingNormal(N0, V)), -1.0f, 1.0f);
      worst_angle = std::max(worst_angle, std::acos(c));
    }
  }
  std::printf("normals facing away: %d of %d pixels; stored N.V >= %.2e, worst %.2e rad\n", away,
              lit, worst_facing, worst_angle);
  EXPECT_EQ(lit, w * h);
  EXPECT_GT(away, lit / 5);
  EXPECT_GT(worst_facing, -1e-3f);
  EXPECT_LT(worst_angle, 2e-3f) << "radians";
}

TEST(GBuffer, BackgroundIsMarked) {
  testContext();
  Scene s = planeScene(Material{}, 0.5f);  // small plane: corners see the background
  render::Renderer r;
  r.setScene(s);
  r.render(32, 32);
  auto g = r.readGBuffer();
  EXPECT_EQ(g.model[0], 0u);
  EXPECT_EQ(g.depth[0], 0.0f);
  EXPECT_EQ(g.model[size_t(16) * 32 + 16], static_cast<uint32_t>(ShadingModel::DefaultLit));
}

// The material reaches the shader per draw (a range of GpuScene's uniform buffer): four quads of
// four materials in one frame each read back their own material, and the ranges start on the
// driver's uniform-buffer offset alignment.
TEST(GBuffer, EachDrawReadsItsOwnMaterial) {
  testContext();
  Scene s = planeScene(Material{}, 0.1f);  // material 0: a small plane under the four quads
  s.objects[0].transform = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, -0.5f, 0.0f));
  const glm::vec2 at[4] = {{-0.5f, -0.5f}, {0.5f, -0.5f}, {-0.5f, 0.5f}, {0.5f, 0.5f}};
  for (int i = 0; i < 4; ++i) {
    Material m;
    m.base_color = glm::vec3(0.2f * float(i + 1), 0.5f, 1.0f - 0.2f * float(i));
    m.metallic = 0.25f * float(i);
    m.roughness = 0.1f + 0.2f * float(i);
    m.cavity = 1.0f - 0.1f * float(i);
    s.materials.push_back(m);
    s.meshes.push_back(makePlane(0.9f, 0.9f));
    s.meshes.back().material = i + 1;
    Object o;
    o.meshes = {i + 1};
    o.transform = glm::translate(glm::mat4(1.0f), glm::vec3(at[i].x, 0.0f, at[i].y));
    s.objects.push_back(o);
  }
  render::Renderer r;
  r.setScene(s);
  r.render(64, 64);
  const auto g = r.readGBuffer();
  std::vector<int> seen;
  for (int qy : {16, 48}) {
    for (int qx : {16, 48}) {
      const size_t c = size_t(qy) * 64 + size_t(qx);
      int found = -1;
      for (int i = 1; i <= 4; ++i) {
        const Material& m = s.materials[size_t(i)];
        if (std::abs(g.metallic[c] - m.metallic) < 1.0f / 255.0f &&
            std::abs(g.roughness[c] - m.roughness) < 1e-4f &&
            std::abs(g.cavity[c] - m.cavity) < 1.0f / 255.0f &&
            std::abs(g.base_color[c].x - m.base_color.x) < 0.01f) {
          found = i;
        }
      }
      EXPECT_GT(found, 0) << "pixel " << qx << "," << qy << " matches no quad's material";
      seen.push_back(found);
    }
  }
  std::sort(seen.begin(), seen.end());
  EXPECT_EQ(seen, (std::vector<int>{1, 2, 3, 4}));

  GLint align = 0;
  glGetIntegerv(GL_UNIFORM_BUFFER_OFFSET_ALIGNMENT, &align);
  const render::GpuScene gpu(s);
  RecordProperty("uniform_buffer_offset_alignment", align);
  RecordProperty("material_stride", int(gpu.materialStride()));
  EXPECT_GE(gpu.materialStride(), sizeof(GpuMaterial));
  EXPECT_EQ(gpu.materialStride() % size_t(std::max(align, 1)), 0u);
}

// The floor pass (DebugOptions::floor_pass) is timed as its own pass and leaves the frame's
// images exactly as they are without it.
TEST(FloorPass, TimedAndLeavesTheImageUnchanged) {
  testContext();
  hv::Material m;
  m.base_color = {0.5f, 0.6f, 0.7f};
  hv::Scene s = planeScene(m);
  hv::Light l;
  l.position = {0.0f, 1.0f, 0.0f};
  s.lights.push_back(l);
  hv::render::Renderer r;
  r.setScene(s);
  r.render(32, 24);
  const auto hdr = r.readHdr();
  const auto ldr = r.readLdr();
  hv::render::DebugOptions floor;
  floor.floor_pass = true;
  r.setDebugOptions(floor);
  const auto stats = r.render(32, 24);
  ASSERT_FALSE(stats.passes.empty());
  EXPECT_EQ(stats.passes.back().first, "floor");
  EXPECT_EQ(r.readHdr().px, hdr.px);
  EXPECT_EQ(r.readLdr().px, ldr.px);
}
