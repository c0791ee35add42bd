// What the glTF features do to the G-buffer, read back from the GPU: the vertex color (COLOR_0)
// tints base color and alpha, a material can opt out, and KHR_texture_transform moves the texture
// lookup; in the specialized and the uber build.
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "render_fixture.hpp"
#include "halfvec/shading/shading.hpp"

using namespace hv;

namespace {

constexpr int kSize = 32;
const size_t kCenter = size_t(kSize / 2) * kSize + kSize / 2;

// One 8-bit sRGB code: what the SRGB8 base color target can be off by.
float srgbCode(float linear) {
  return glsl::srgbEncode(linear);
}

Scene tintedPlane(glm::vec4 vertex_color, bool uber) {
  Material m;
  m.base_color = {0.8f, 0.6f, 0.4f};
  Scene s = planeScene(m);
  for (Vertex& v : s.meshes[0].vertices) v.color = vertex_color;
  s.meshes[0].has_colors = true;
  s.settings.uber = uber;
  return s;
}

GBufferReadback renderGBuffer(const Scene& s) {
  render::Renderer r;
  r.setScene(s);
  r.render(kSize, kSize);
  return r.readGBuffer();
}

}  // namespace

TEST(GltfShading, VertexColorTintsBaseColor) {
  testContext();
  const glm::vec4 tint(0.5f, 1.0f, 0.25f, 1.0f);
  for (bool uber : {false, true}) {
    SCOPED_TRACE(uber ? "uber" : "specialized");
    const GBufferReadback g = renderGBuffer(tintedPlane(tint, uber));
    for (int k = 0; k < 3; ++k) {
      const float want = 0.8f - 0.2f * float(k);  // 0.8, 0.6, 0.4
      EXPECT_NEAR(srgbCode(g.base_color[kCenter][k]), srgbCode(want * tint[k]),
                  1.0f / 255.0f + 1e-5f)
          << "channel " << k;
    }
  }
}

TEST(GltfShading, MaterialOptsOutOfVertexColor) {
  testContext();
  for (bool uber : {false, true}) {
    SCOPED_TRACE(uber ? "uber" : "specialized");
    Scene s = tintedPlane({0.1f, 0.1f, 0.1f, 1.0f}, uber);
    s.materials[0].vertex_color = false;
    const GBufferReadback g = renderGBuffer(s);
    EXPECT_NEAR(srgbCode(g.base_color[kCenter][0]), srgbCode(0.8f), 1.0f / 255.0f + 1e-5f);
  }
}

TEST(GltfShading, VertexAlphaFeedsTheAlphaMask) {
  testContext();
  for (bool uber : {false, true}) {
    SCOPED_TRACE(uber ? "uber" : "specialized");
    for (float alpha : {0.25f, 0.75f}) {
      Scene s = tintedPlane({1.0f, 1.0f, 1.0f, alpha}, uber);
      s.materials[0].alpha_mode = AlphaMode::Mask;
      s.materials[0].alpha_cutoff = 0.5f;
      const GBufferReadback g = renderGBuffer(s);
      // Below the cutoff the plane is discarded: background (model 0).
      EXPECT_EQ(g.model[kCenter] != 0, alpha > 0.5f) << "vertex alpha " << alpha;
    }
  }
}

// KHR_texture_transform's matrix (T * R * S, the extension's order and rotation sense) as the
// shared header computes it, against the product written out with glm.
TEST(GltfShading, TextureTransformMatchesTheExtensionsMatrix) {
  const glm::vec2 offset(0.25f, -0.5f), scale(2.0f, 3.0f);
  const float rotation = 0.3f;
  const glm::mat3 t(1, 0, 0, 0, 1, 0, offset.x, offset.y, 1);  // column-major
  const glm::mat3 r(std::cos(rotation), -std::sin(rotation), 0, std::sin(rotation),
                    std::cos(rotation), 0, 0, 0, 1);
  const glm::mat3 sc(scale.x, 0, 0, 0, scale.y, 0, 0, 0, 1);
  for (const glm::vec2 uv : {glm::vec2(0.0f), glm::vec2(1.0f, 0.0f), glm::vec2(0.3f, 0.7f)}) {
    const glm::vec3 want = t * r * sc * glm::vec3(uv, 1.0f);
    const glm::vec2 got =
        glsl::applyTextureTransform(uv, glsl::textureTransformLinear(scale, rotation), offset);
    EXPECT_NEAR(got.x, want.x, 1e-6f);
    EXPECT_NEAR(got.y, want.y, 1e-6f);
  }
}

// A 2x1 texture, red | green, sampled nearest: an offset of half the width or a rotation by pi
// moves every lookup to the other texel; no transform keeps it.
TEST(GltfShading, TextureTransformMovesTheLookup) {
  testContext();
  auto sample = [](const TextureRef& ref, bool uber) {
    Material m;
    m.base_color = glm::vec3(1.0f);
    m.base_color_tex = ref;
    m.base_color_tex.image = 0;
    m.base_color_tex.sampler.min = m.base_color_tex.sampler.mag = Filter::Nearest;
    m.base_color_tex.sampler.mipmaps = false;
    Scene s = planeScene(m, 2.0f);
    s.images.push_back({"red|green", 2, 1, {255, 0, 0, 255, 0, 255, 0, 255}});
    s.settings.uber = uber;
    const GBufferReadback g = renderGBuffer(s);
    // A quarter in from the left: well inside one texel whatever the plane's UV orientation.
    return g.base_color[size_t(kSize / 2) * kSize + kSize / 4];
  };
  for (bool uber : {false, true}) {
    SCOPED_TRACE(uber ? "uber" : "specialized");
    const glm::vec3 plain = sample({}, uber);
    ASSERT_TRUE((plain.x > 0.9f && plain.y < 0.1f) || (plain.y > 0.9f && plain.x < 0.1f))
        << plain.x << " " << plain.y;
    TextureRef shifted;
    shifted.uv_offset = {0.5f, 0.0f};
    TextureRef turned;
    turned.uv_rotation = 3.14159265f;
    for (const TextureRef& ref : {shifted, turned}) {
      const glm::vec3 moved = sample(ref, uber);
      EXPECT_NEAR(moved.x, plain.y, 0.01f);
      EXPECT_NEAR(moved.y, plain.x, 0.01f);
    }
  }
}

// KHR_materials_clearcoat's textures in the G-buffer's coat target: the weight texture's R and the
// roughness texture's G multiply the factors (a 2-texel image: the two halves of the plane); the
// coat's normal map tilts the coat's normal and leaves the base's alone; a coat without a normal
// map keeps the vertex normal. Specialized and uber builds.
TEST(GltfShading, ClearCoatTexturesReachTheCoatTarget) {
  testContext();
  auto coatPlane = [](bool uber, bool normal_map) {
    Material m;
    m.model = ShadingModel::ClearCoat;
    m.clearcoat = 0.8f;
    m.clearcoat_roughness = 0.5f;
    Scene s = planeScene(m, 2.0f);
    // Image 0: R 255 | 64 (weight), G 128 | 255 (roughness); image 1: a normal tilted along +x.
    s.images.push_back({"coat", 2, 1, {255, 128, 0, 255, 64, 255, 0, 255}});
    s.images.push_back({"tilt", 1, 1, {200, 128, 200, 255}});
    Material& pm = s.materials.back();
    for (TextureRef* t : {&pm.clearcoat_tex, &pm.clearcoat_roughness_tex}) {
      t->image = 0;
      t->sampler.min = t->sampler.mag = Filter::Nearest;
      t->sampler.mipmaps = false;
    }
    if (normal_map) {
      pm.clearcoat_normal_tex.image = 1;
      pm.clearcoat_normal_tex.sampler.mipmaps = false;
    }
    s.settings.uber = uber;
    return renderGBuffer(s);
  };
  for (bool uber : {false, true}) {
    SCOPED_TRACE(uber ? "uber" : "specialized");
    const GBufferReadback g = coatPlane(uber, true);
    ASSERT_TRUE(g.hasCoat());
    const size_t left = size_t(kSize / 2) * kSize + kSize / 4,
                 right = size_t(kSize / 2) * kSize + 3 * kSize / 4;
    const float w[2] = {g.clearcoat[left], g.clearcoat[right]};
    const float r[2] = {g.clearcoat_roughness[left], g.clearcoat_roughness[right]};
    // Which texel lands on which half depends on the plane's UVs: either order.
    const bool swapped = w[0] < w[1];
    EXPECT_NEAR(w[swapped ? 1 : 0], 0.8f, 2e-3f);
    EXPECT_NEAR(w[swapped ? 0 : 1], 0.8f * 64.0f / 255.0f, 2e-3f);
    EXPECT_NEAR(r[swapped ? 1 : 0], 0.5f * 128.0f / 255.0f, 2e-3f);
    EXPECT_NEAR(r[swapped ? 0 : 1], 0.5f, 2e-3f);
    // The coat's normal is tilted by its map; the base's is the plane's.
    const float tilt = glm::dot(g.coat_normal[kCenter], g.normal[kCenter]);
    EXPECT_LT(tilt, 0.95f);
    EXPECT_GT(tilt, 0.5f);
    const GBufferReadback flat = coatPlane(uber, false);
    EXPECT_GT(glm::dot(flat.coat_normal[kCenter], flat.normal[kCenter]), 0.9999f);
  }
}
