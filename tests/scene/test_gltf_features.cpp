// glTF features beyond the core: COLOR_0 in each component type, KHR_texture_transform,
// KHR_materials_emissive_strength, KHR_materials_clearcoat, and the warnings for what the loader
// skips.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "halfvec/scene/gltf_loader.hpp"
#include "scene/gltf_test_files.hpp"

namespace fs = std::filesystem;
using hv::test::base64;
using hv::test::quad;
using hv::test::tempDir;
using nlohmann::json;

namespace {

std::string write(const json& j, const std::string& name) {
  const fs::path p = tempDir() / name;
  std::ofstream(p) << j.dump();
  return p.string();
}

struct Loaded {
  hv::Scene scene;
  std::vector<std::string> warnings;
};

Loaded load(const json& j, const std::string& name) {
  Loaded l;
  hv::GltfOptions opt;
  opt.warnings = &l.warnings;
  hv::loadGltf(write(j, name), glm::mat4(1.0f), l.scene, opt);
  return l;
}

std::string loadError(const json& j, const std::string& name) {
  hv::Scene scene;
  std::vector<std::string> w;
  hv::GltfOptions opt;
  opt.warnings = &w;
  try {
    hv::loadGltf(write(j, name), glm::mat4(1.0f), scene, opt);
  } catch (const hv::SceneError& e) {
    EXPECT_TRUE(scene.meshes.empty() && scene.materials.empty()) << "half-loaded scene";
    return e.what();
  }
  return "";
}

size_t countContaining(const std::vector<std::string>& w, const std::string& s) {
  size_t n = 0;
  for (const std::string& x : w) n += x.find(s) != std::string::npos;
  return n;
}

// Adds buffer `bytes` as a new buffer + bufferView + accessor of `count` elements; returns the
// accessor index.
int addAccessor(json& j, const std::vector<uint8_t>& bytes, int ctype, const char* type,
                size_t count, bool normalized) {
  const size_t b = j["buffers"].size();
  j["buffers"].push_back({{"byteLength", bytes.size()},
                          {"uri", "data:application/octet-stream;base64," + base64(bytes)}});
  const size_t v = j["bufferViews"].size();
  j["bufferViews"].push_back({{"buffer", b}, {"byteOffset", 0}, {"byteLength", bytes.size()}});
  json a = {{"bufferView", v}, {"componentType", ctype}, {"count", count}, {"type", type}};
  if (normalized) a["normalized"] = true;
  j["accessors"].push_back(a);
  return int(j["accessors"].size()) - 1;
}

template <class T>
std::vector<uint8_t> bytesOf(const std::vector<T>& v) {
  std::vector<uint8_t> b(v.size() * sizeof(T));
  std::memcpy(b.data(), v.data(), b.size());
  while (b.size() % 4) b.push_back(0);
  return b;
}

// The four vertex colours every COLOR_0 test writes, as RGBA in [0, 1].
const float kColors[4][4] = {{1.0f, 0.0f, 0.0f, 1.0f},
                             {0.0f, 1.0f, 0.0f, 0.5f},
                             {0.0f, 0.0f, 1.0f, 0.25f},
                             {1.0f, 1.0f, 1.0f, 0.0f}};

// A 2x2 24-bit BMP (stb_image decodes it; the pixel values do not matter to these tests).
std::vector<uint8_t> bmp2x2() {
  std::vector<uint8_t> b = {'B', 'M'};
  auto le32 = [&](uint32_t x) {
    for (int i = 0; i < 4; ++i) b.push_back(uint8_t(x >> (8 * i)));
  };
  auto le16 = [&](uint16_t x) {
    b.push_back(uint8_t(x));
    b.push_back(uint8_t(x >> 8));
  };
  le32(54 + 16), le32(0), le32(54);               // file size, reserved, pixel offset
  le32(40), le32(2), le32(2), le16(1), le16(24);  // BITMAPINFOHEADER, 2x2, 1 plane, 24 bpp
  le32(0), le32(16), le32(2835), le32(2835), le32(0), le32(0);
  for (int row = 0; row < 2; ++row) {
    for (int i = 0; i < 6; ++i) b.push_back(uint8_t(40 * (row + i)));
    b.push_back(0), b.push_back(0);  // rows padded to 4 bytes
  }
  return b;
}

// quad() with one image and texture, and the material's base colour, normal and emissive
// textures reading it.
json texturedQuad() {
  json j = quad();
  j["images"] = {{{"uri", "data:image/bmp;base64," + base64(bmp2x2())}}};
  j["textures"] = {{{"source", 0}}};
  j["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"] = {{"index", 0}};
  j["materials"][0]["normalTexture"] = {{"index", 0}};
  j["materials"][0]["emissiveTexture"] = {{"index", 0}};
  return j;
}

}  // namespace

// COLOR_0 in every component type glTF allows (3.7.2.1): VEC3/VEC4 of float, normalized
// unsigned byte and normalized unsigned short.
TEST(GltfVertexColor, EveryComponentType) {
  struct Case {
    const char* type;
    int ctype;
    float tolerance;
  };
  for (const Case c :
       {Case{"VEC3", 5126, 0.0f}, Case{"VEC4", 5126, 0.0f}, Case{"VEC3", 5121, 0.5f / 255 + 1e-6f},
        Case{"VEC4", 5121, 0.5f / 255 + 1e-6f}, Case{"VEC3", 5123, 0.5f / 65535 + 1e-7f},
        Case{"VEC4", 5123, 0.5f / 65535 + 1e-7f}}) {
    SCOPED_TRACE(std::string(c.type) + " componentType " + std::to_string(c.ctype));
    const int comps = std::string(c.type) == "VEC3" ? 3 : 4;
    std::vector<uint8_t> bytes;
    for (const auto& col : kColors) {
      for (int k = 0; k < comps; ++k) {
        if (c.ctype == 5126) {
          const auto* p = reinterpret_cast<const uint8_t*>(&col[k]);
          bytes.insert(bytes.end(), p, p + 4);
        } else if (c.ctype == 5121) {
          bytes.push_back(uint8_t(std::lround(col[k] * 255)));
        } else {
          const auto x = uint16_t(std::lround(col[k] * 65535));
          bytes.push_back(uint8_t(x)), bytes.push_back(uint8_t(x >> 8));
        }
      }
      // Unsigned byte/short vertex attributes are 4-byte aligned per element (glTF 3.6.2.4).
      while (c.ctype != 5126 && bytes.size() % 4) bytes.push_back(0);
    }
    json j = quad();
    const size_t elem = bytes.size() / 4;
    const int a = addAccessor(j, bytes, c.ctype, c.type, 4, c.ctype != 5126);
    j["bufferViews"].back()["byteStride"] = elem;
    j["meshes"][0]["primitives"][0]["attributes"]["COLOR_0"] = a;
    const Loaded l = load(j, "color.gltf");
    EXPECT_TRUE(l.warnings.empty()) << l.warnings.front();
    ASSERT_EQ(l.scene.meshes.size(), 1u);
    const hv::Mesh& m = l.scene.meshes[0];
    EXPECT_TRUE(m.has_colors);
    // No NORMAL: flat normals, one vertex per triangle corner; indices {0,1,2, 0,2,3}.
    const int corner[6] = {0, 1, 2, 0, 2, 3};
    ASSERT_EQ(m.vertices.size(), 6u);
    for (size_t v = 0; v < 6; ++v) {
      const float* want = kColors[corner[v]];
      for (int k = 0; k < 4; ++k) {
        const float expect = k < comps ? want[k] : 1.0f;  // VEC3: alpha 1
        EXPECT_NEAR(m.vertices[v].color[k], expect, c.tolerance) << "vertex " << v << " comp " << k;
      }
    }
  }
}

TEST(GltfVertexColor, WithoutColorsVerticesAreWhite) {
  const Loaded l = load(quad(), "nocolor.gltf");
  ASSERT_EQ(l.scene.meshes.size(), 1u);
  EXPECT_FALSE(l.scene.meshes[0].has_colors);
  for (const hv::Vertex& v : l.scene.meshes[0].vertices) EXPECT_EQ(v.color, glm::vec4(1.0f));
}

TEST(GltfVertexColor, RejectsWhatGltfForbids) {
  {  // integer colours must be normalized
    json j = quad();
    const int a = addAccessor(j, std::vector<uint8_t>(16, 255), 5121, "VEC4", 4, false);
    j["meshes"][0]["primitives"][0]["attributes"]["COLOR_0"] = a;
    const std::string e = loadError(j, "color_unnorm.gltf");
    EXPECT_NE(e.find("accessors[3].normalized"), std::string::npos) << e;
    EXPECT_NE(e.find("COLOR_0"), std::string::npos) << e;
  }
  {  // signed bytes are not a colour type
    json j = quad();
    const int a = addAccessor(j, std::vector<uint8_t>(16, 100), 5120, "VEC4", 4, true);
    j["meshes"][0]["primitives"][0]["attributes"]["COLOR_0"] = a;
    const std::string e = loadError(j, "color_byte.gltf");
    EXPECT_NE(e.find("accessors[3].componentType"), std::string::npos) << e;
  }
  {  // a VEC2 colour
    json j = quad();
    const int a = addAccessor(j, bytesOf(std::vector<float>(8, 0.5f)), 5126, "VEC2", 4, false);
    j["meshes"][0]["primitives"][0]["attributes"]["COLOR_0"] = a;
    const std::string e = loadError(j, "color_vec2.gltf");
    EXPECT_NE(e.find("accessors[3].type"), std::string::npos) << e;
  }
  {  // fewer colours than positions
    json j = quad();
    const int a = addAccessor(j, bytesOf(std::vector<float>(9, 0.5f)), 5126, "VEC3", 3, false);
    j["meshes"][0]["primitives"][0]["attributes"]["COLOR_0"] = a;
    const std::string e = loadError(j, "color_count.gltf");
    EXPECT_NE(e.find("COLOR_0"), std::string::npos) << e;
    EXPECT_NE(e.find("count differs"), std::string::npos) << e;
  }
}

TEST(GltfVertexColor, FloatColorsClampedToUnitRange) {
  json j = quad();
  const int a = addAccessor(j, bytesOf(std::vector<float>{2, -1, 0.5, 0, 0, 0, 0, 0, 0, 0, 0, 0}),
                            5126, "VEC3", 4, false);
  j["meshes"][0]["primitives"][0]["attributes"]["COLOR_0"] = a;
  j["meshes"][0]["primitives"][0]["attributes"]["NORMAL"] = addAccessor(
      j, bytesOf(std::vector<float>{0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1}), 5126, "VEC3", 4, false);
  const Loaded l = load(j, "color_clamp.gltf");
  EXPECT_EQ(l.scene.meshes[0].vertices[0].color, glm::vec4(1.0f, 0.0f, 0.5f, 1.0f));
}

// KHR_texture_transform: each of offset, rotation, scale and texCoord reaches the TextureRef of
// the textureInfo that carries it, and only that one.
TEST(GltfTextureTransform, EachKindPerTexture) {
  json j = texturedQuad();
  j["extensionsUsed"] = {"KHR_texture_transform"};
  j["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_1"] = 2;
  auto& mat = j["materials"][0];
  mat["pbrMetallicRoughness"]["baseColorTexture"]["extensions"]["KHR_texture_transform"] = {
      {"offset", {0.25, -0.5}}};
  mat["normalTexture"]["extensions"]["KHR_texture_transform"] = {{"rotation", 1.5707963}};
  mat["emissiveTexture"]["extensions"]["KHR_texture_transform"] = {{"scale", {2, 3}},
                                                                   {"texCoord", 1}};
  const Loaded l = load(j, "xform.gltf");
  EXPECT_TRUE(l.warnings.empty()) << l.warnings.front();
  const hv::Material& m = l.scene.materials.at(0);
  EXPECT_EQ(m.base_color_tex.uv_offset, glm::vec2(0.25f, -0.5f));
  EXPECT_EQ(m.base_color_tex.uv_rotation, 0.0f);
  EXPECT_EQ(m.base_color_tex.uv_scale, glm::vec2(1.0f));
  EXPECT_EQ(m.base_color_tex.texcoord, 0);
  EXPECT_TRUE(m.base_color_tex.transformed());
  EXPECT_FLOAT_EQ(m.normal_tex.uv_rotation, 1.5707963f);
  EXPECT_EQ(m.normal_tex.uv_offset, glm::vec2(0.0f));
  EXPECT_EQ(m.emissive_tex.uv_scale, glm::vec2(2.0f, 3.0f));
  EXPECT_EQ(m.emissive_tex.texcoord, 1);  // the extension's texCoord overrides the textureInfo's
  EXPECT_FALSE(m.metallic_roughness_tex.transformed());
}

TEST(GltfTextureTransform, BadValuesNamed) {
  json j = texturedQuad();
  auto& ext = j["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"]["extensions"];
  ext["KHR_texture_transform"] = {{"offset", {1}}};
  std::string e = loadError(j, "xform_bad.gltf");
  EXPECT_NE(e.find("baseColorTexture.extensions.KHR_texture_transform.offset"), std::string::npos)
      << e;
  ext["KHR_texture_transform"] = {{"texCoord", 2}};
  e = loadError(j, "xform_tc.gltf");
  EXPECT_NE(e.find("texCoord 2"), std::string::npos) << e;
  ext["KHR_texture_transform"] = {{"rotation", "a lot"}};
  e = loadError(j, "xform_rot.gltf");
  EXPECT_NE(e.find("KHR_texture_transform.rotation"), std::string::npos) << e;
}

TEST(GltfEmissiveStrength, ScalesTheEmissiveFactor) {
  json j = quad();
  j["extensionsUsed"] = {"KHR_materials_emissive_strength"};
  j["materials"][0]["emissiveFactor"] = {1.0, 0.5, 0.25};
  j["materials"][0]["extensions"]["KHR_materials_emissive_strength"] = {{"emissiveStrength", 8}};
  const Loaded l = load(j, "emissive_strength.gltf");
  EXPECT_TRUE(l.warnings.empty()) << l.warnings.front();
  EXPECT_EQ(l.scene.materials.at(0).emissive, glm::vec3(8.0f, 4.0f, 2.0f));
  j["materials"][0]["extensions"]["KHR_materials_emissive_strength"]["emissiveStrength"] = -1;
  const std::string e = loadError(j, "emissive_strength_neg.gltf");
  EXPECT_NE(e.find("KHR_materials_emissive_strength.emissiveStrength"), std::string::npos) << e;
}

// KHR_materials_clearcoat: the two factors make a clear_coat material; its three textures are
// read with their texCoord and the normal map's scale; on a blended material they warn (the
// forward pass applies the factors alone); a factor outside [0, 1] and a textureInfo without an
// index are errors naming the field.
TEST(GltfClearCoat, FactorsAndTexturesImported) {
  json j = texturedQuad();
  j["extensionsUsed"] = {"KHR_materials_clearcoat"};
  auto& cc = j["materials"][0]["extensions"]["KHR_materials_clearcoat"];
  cc = {{"clearcoatFactor", 0.9}, {"clearcoatRoughnessFactor", 0.2}};
  Loaded l = load(j, "clearcoat.gltf");
  EXPECT_TRUE(l.warnings.empty()) << l.warnings.front();
  const hv::Material& m = l.scene.materials.at(0);
  EXPECT_EQ(m.model, hv::ShadingModel::ClearCoat);
  EXPECT_FLOAT_EQ(m.clearcoat, 0.9f);
  EXPECT_FLOAT_EQ(m.clearcoat_roughness, 0.2f);
  EXPECT_FALSE(m.clearcoat_tex.valid());
  cc["clearcoatTexture"] = {{"index", 0}};
  cc["clearcoatRoughnessTexture"] = {{"index", 0}, {"texCoord", 1}};
  cc["clearcoatNormalTexture"] = {{"index", 0}, {"scale", 0.5}};
  l = load(j, "clearcoat_tex.gltf");
  EXPECT_TRUE(l.warnings.empty()) << l.warnings.front();
  const hv::Material& t = l.scene.materials.at(0);
  EXPECT_TRUE(t.clearcoat_tex.valid());
  EXPECT_EQ(t.clearcoat_roughness_tex.texcoord, 1);
  EXPECT_FLOAT_EQ(t.clearcoat_normal_tex.scale, 0.5f);
  j["materials"][0]["alphaMode"] = "BLEND";
  l = load(j, "clearcoat_blend.gltf");
  EXPECT_EQ(countContaining(l.warnings, "the coat's textures are not applied on a blended"), 1u);
  j["materials"][0].erase("alphaMode");
  cc["clearcoatNormalTexture"] = {{"scale", 0.5}};
  std::string e = loadError(j, "clearcoat_noindex.gltf");
  EXPECT_NE(e.find("clearcoatNormalTexture.index: expected a texture index"), std::string::npos)
      << e;
  cc["clearcoatNormalTexture"] = {{"index", 7}};
  e = loadError(j, "clearcoat_range.gltf");
  EXPECT_NE(e.find("clearcoatNormalTexture: texture index out of range"), std::string::npos) << e;
  cc["clearcoatNormalTexture"] = {{"index", 0}, {"texCoord", "one"}};
  e = loadError(j, "clearcoat_tc.gltf");
  EXPECT_NE(e.find("clearcoatNormalTexture.texCoord: expected an integer"), std::string::npos) << e;
  cc = {{"clearcoatFactor", 0.0}};
  EXPECT_EQ(load(j, "clearcoat_zero.gltf").scene.materials.at(0).model,
            hv::ShadingModel::DefaultLit);
  cc = {{"clearcoatFactor", 2}};
  e = loadError(j, "clearcoat_bad.gltf");
  EXPECT_NE(e.find("KHR_materials_clearcoat.clearcoatFactor: expected 0..1, got 2"),
            std::string::npos)
      << e;
}

// Every extension the loader does not read warns once, naming it, wherever it is used; the
// ones it reads do not warn.
TEST(GltfUnsupported, ExtensionsWarnOnceByName) {
  json j = texturedQuad();
  j["extensionsUsed"] = {"KHR_materials_transmission", "KHR_materials_sheen",
                         "KHR_texture_transform", "EXT_mesh_gpu_instancing"};
  j["materials"][0]["extensions"]["KHR_materials_transmission"] = {{"transmissionFactor", 1}};
  j["materials"][0]["extensions"]["KHR_materials_sheen"] = json::object();
  j["materials"][0]["extensions"]["KHR_materials_ior"] = {{"ior", 1.3}};  // not declared
  j["materials"][0]["normalTexture"]["extensions"]["KHR_materials_specular"] = json::object();
  j["nodes"][0]["extensions"]["EXT_mesh_gpu_instancing"] = json::object();
  const Loaded l = load(j, "exts.gltf");
  for (const char* name : {"KHR_materials_transmission", "KHR_materials_sheen", "KHR_materials_ior",
                           "KHR_materials_specular", "EXT_mesh_gpu_instancing"}) {
    EXPECT_EQ(countContaining(l.warnings, name), 1u) << name;
  }
  EXPECT_EQ(countContaining(l.warnings, "KHR_texture_transform"), 0u);
  EXPECT_EQ(l.warnings.size(), 5u);
  EXPECT_EQ(countContaining(l.warnings, "materials[0].extensions: extension KHR_materials_ior"),
            1u);
}

TEST(GltfUnsupported, RequiredExtensionIsAnErrorNamingIt) {
  json j = quad();
  j["extensionsUsed"] = {"KHR_texture_transform", "KHR_draco_mesh_compression"};
  j["extensionsRequired"] = {"KHR_texture_transform", "KHR_draco_mesh_compression"};
  const std::string e = loadError(j, "required.gltf");
  EXPECT_NE(e.find("extensionsRequired[1]"), std::string::npos) << e;
  EXPECT_NE(e.find("KHR_draco_mesh_compression"), std::string::npos) << e;
  // The extensions it reads may be required.
  j["extensionsUsed"] = {"KHR_texture_transform", "KHR_materials_emissive_strength",
                         "KHR_mesh_quantization"};
  j["extensionsRequired"] = j["extensionsUsed"];
  EXPECT_NO_THROW(load(j, "required_ok.gltf"));
}

TEST(GltfUnsupported, SkinsMorphTargetsAnimationsAndAttributesWarn) {
  json j = quad();
  auto& attrs = j["meshes"][0]["primitives"][0]["attributes"];
  const int joints = addAccessor(j, std::vector<uint8_t>(16, 0), 5121, "VEC4", 4, false);
  const int weights =
      addAccessor(j, bytesOf(std::vector<float>(16, 0.25f)), 5126, "VEC4", 4, false);
  attrs["JOINTS_0"] = joints;
  attrs["WEIGHTS_0"] = weights;
  attrs["TEXCOORD_2"] = 2;
  attrs["COLOR_1"] = addAccessor(j, bytesOf(std::vector<float>(12, 1.0f)), 5126, "VEC3", 4, false);
  j["meshes"][0]["primitives"][0]["targets"] = {{{"POSITION", 0}}};
  j["meshes"][0]["weights"] = {0.5};
  // tinygltf wants a skin's inverseBindMatrices (optional in glTF): one identity matrix.
  const int ibm =
      addAccessor(j, bytesOf(std::vector<float>{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}),
                  5126, "MAT4", 1, false);
  j["skins"] = {{{"joints", {1}}, {"inverseBindMatrices", ibm}}};
  j["nodes"][0]["skin"] = 0;
  json channel = {{"sampler", 0}, {"target", {{"node", 1}, {"path", "scale"}}}};
  json sampler = {{"input", 2}, {"output", 0}};
  json animation;
  animation["channels"] = json::array({channel});
  animation["samplers"] = json::array({sampler});
  j["animations"] = json::array({animation});
  const Loaded l = load(j, "skinned.gltf");
  for (const char* what :
       {"JOINTS_0", "WEIGHTS_0", "TEXCOORD_2", "COLOR_1", "morph targets", "skin", "animation"}) {
    EXPECT_GE(countContaining(l.warnings, what), 1u) << what;
  }
  EXPECT_EQ(countContaining(l.warnings, "JOINTS_0"), 1u);
  EXPECT_EQ(l.warnings.size(), 7u);
  for (const std::string& w : l.warnings) EXPECT_NE(w.find("skinned.gltf"), std::string::npos) << w;
}
