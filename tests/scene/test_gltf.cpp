#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "halfvec/scene/gltf_loader.hpp"
#include "scene/gltf_test_files.hpp"
#include "shared_assets.hpp"

namespace fs = std::filesystem;
using hv::test::assetsDir;
using hv::test::base64;
using hv::test::gltfFiles;
using hv::test::quad;
using hv::test::tempDir;
using nlohmann::json;

namespace {

std::string write(const json& j, const std::string& name) {
  const fs::path p = tempDir() / name;
  std::ofstream(p) << j.dump();
  return p.string();
}

std::string loadError(const json& j, const std::string& name) {
  hv::Scene scene;
  try {
    hv::loadGltf(write(j, name), glm::mat4(1.0f), scene);
  } catch (const hv::SceneError& e) {
    EXPECT_TRUE(scene.meshes.empty() && scene.materials.empty() && scene.objects.empty())
        << "half-loaded scene";
    return e.what();
  }
  return "";
}

}  // namespace

TEST(Gltf, LoadsHandBuiltQuad) {
  hv::Scene scene;
  scene.materials.push_back({});  // pre-existing content must keep its indices
  std::vector<std::string> warnings;
  hv::GltfOptions opt;
  opt.warnings = &warnings;
  hv::loadGltf(write(quad(), "quad.gltf"), glm::mat4(1.0f), scene, opt);
  ASSERT_EQ(scene.meshes.size(), 1u);
  ASSERT_EQ(scene.objects.size(), 2u);
  ASSERT_EQ(scene.materials.size(), 2u);
  const hv::Mesh& m = scene.meshes[0];
  EXPECT_EQ(m.material, 1);
  const hv::Material& mat = scene.materials[1];
  EXPECT_EQ(mat.alpha_mode, hv::AlphaMode::Mask);
  EXPECT_FLOAT_EQ(mat.alpha_cutoff, 0.3f);
  EXPECT_TRUE(mat.double_sided);
  EXPECT_FLOAT_EQ(mat.roughness, 0.75f);
  // No NORMAL: flat normals, one vertex per triangle corner, facing +Z (CCW quad).
  EXPECT_EQ(m.vertices.size(), 6u);
  for (const hv::Vertex& v : m.vertices) {
    EXPECT_NEAR(v.normal.z, 1.0f, 1e-6f);
    EXPECT_NEAR(v.tangent.x, 1.0f, 1e-5f);  // +u is +x
    // +v (down the image) is -y here; B = cross(N,T) * w must point up the image (+y), and
    // cross(N,T) = +y already, so w = +1.
    EXPECT_EQ(v.tangent.w, 1.0f);
  }
  // Child transform: parent translate * child scale.
  const glm::vec4 p = scene.objects[1].transform * glm::vec4(1, 0, 0, 1);
  EXPECT_NEAR(p.x, 3.0f, 1e-5f);
  EXPECT_NEAR(p.y, 2.0f, 1e-5f);
  EXPECT_NEAR(p.z, 3.0f, 1e-5f);
}

TEST(Gltf, StripAndFanConverted) {
  json j = quad();
  j["meshes"][0]["primitives"][0].erase("indices");
  j["meshes"][0]["primitives"][0]["mode"] = 6;  // fan 0 1 2 3 -> (1 2 0) (2 3 0)
  hv::Scene s;
  hv::loadGltf(write(j, "fan.gltf"), glm::mat4(1.0f), s);
  EXPECT_EQ(s.meshes[0].indices.size(), 6u);
  j["meshes"][0]["primitives"][0]["mode"] = 5;  // strip 0 1 2 3 -> 2 triangles
  hv::Scene s2;
  hv::loadGltf(write(j, "strip.gltf"), glm::mat4(1.0f), s2);
  EXPECT_EQ(s2.meshes[0].indices.size(), 6u);
  for (const hv::Vertex& v : s.meshes[0].vertices) EXPECT_GT(v.normal.z, 0.0f);  // fan is CCW
  // Strip order per glTF spec: triangle i = {i, i+1+i%2, i+2-i%2}. Flat normals de-index, so
  // compare positions.
  const float expect_x[6] = {0, 1, 1, 1, 0, 1};  // vertices 0 1 2, then 1 3 2
  for (size_t k = 0; k < 6; ++k) {
    EXPECT_EQ(s2.meshes[0].vertices[s2.meshes[0].indices[k]].position.x, expect_x[k]);
  }
}

TEST(Gltf, RejectsBadFiles) {
  EXPECT_NE(loadError(json::parse("{}"), "empty.gltf").find("empty.gltf"), std::string::npos);
  {
    std::ofstream(tempDir() / "broken.gltf") << "{ not json";
    hv::Scene s;
    EXPECT_THROW(hv::loadGltf((tempDir() / "broken.gltf").string(), glm::mat4(1.0f), s),
                 hv::SceneError);
  }
  {
    hv::Scene s;
    EXPECT_THROW(hv::loadGltf((tempDir() / "absent.glb").string(), glm::mat4(1.0f), s),
                 hv::SceneError);
  }
  json j = quad();
  j["accessors"][0]["count"] = 5;  // 5 * 12 bytes > 48
  EXPECT_NE(loadError(j, "oob.gltf").find("accessors[0].count: 5 elements"), std::string::npos);
  j = quad();
  j["bufferViews"][0]["byteLength"] = 4000;
  EXPECT_NE(loadError(j, "oob_view.gltf").find("bufferViews[0]"), std::string::npos);
  j = quad();
  // No POSITION: valid glTF, whose primitive a client "SHOULD skip" (3.7.2.1): skipped with a
  // warning (the Khronos validator accepts such files).
  j["meshes"][0]["primitives"][0]["attributes"].erase("POSITION");
  {
    const fs::path p = tempDir() / "nopos.gltf";
    std::ofstream(p, std::ios::binary) << j.dump();
    hv::Scene s;
    std::vector<std::string> warnings;
    hv::GltfOptions opt;
    opt.warnings = &warnings;
    EXPECT_NO_THROW(hv::loadGltf(p.string(), glm::mat4(1.0f), s, opt));
    EXPECT_TRUE(s.meshes.empty());
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("no POSITION"), std::string::npos) << warnings[0];
  }
  j = quad();
  j["accessors"][1]["count"] = 3;
  j["accessors"][1]["byteOffset"] = 0;
  j["accessors"][0]["count"] = 2;  // indices 2 >= 2 vertices
  j["accessors"][2]["count"] = 2;
  EXPECT_NE(loadError(j, "idx.gltf").find(">= vertex count"), std::string::npos);
  j = quad();
  j["extensionsRequired"] = {"KHR_draco_mesh_compression"};
  j["extensionsUsed"] = {"KHR_draco_mesh_compression"};
  EXPECT_NE(loadError(j, "ext.gltf").find("KHR_draco_mesh_compression"), std::string::npos);
  j = quad();
  j["accessors"][1]["componentType"] = 5126;  // float indices
  EXPECT_NE(loadError(j, "ftype.gltf").find("componentType"), std::string::npos);
  j = quad();
  j["buffers"][0]["uri"] = "missing.bin";
  EXPECT_NE(loadError(j, "missingbin.gltf").find("missing.bin"), std::string::npos);
}

TEST(Gltf, RejectsPrimitiveRestart) {
  json j = quad();
  // Rewrite the index buffer via a data URI whose index 2 is 65535.
  std::vector<uint8_t> buf(92, 0);
  const float pos[12] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
  const uint16_t idx[6] = {0, 1, 65535, 0, 2, 3};
  std::memcpy(buf.data(), pos, 48);
  std::memcpy(buf.data() + 48, idx, 12);
  j["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64(buf);
  EXPECT_NE(loadError(j, "restart.gltf").find("primitive-restart"), std::string::npos);
}

TEST(Gltf, BlendLoadsAsBlendWithoutWarning) {
  json j = quad();
  j["materials"][0]["alphaMode"] = "BLEND";
  hv::Scene s;
  std::vector<std::string> w;
  hv::GltfOptions opt;
  opt.warnings = &w;
  hv::loadGltf(write(j, "blend.gltf"), glm::mat4(1.0f), s, opt);
  EXPECT_TRUE(w.empty()) << w[0];
  EXPECT_EQ(s.materials[0].alpha_mode, hv::AlphaMode::Blend);
}

// ---- shared assets ----------------------------------------------------------------------------

namespace {

// Loads one glTF file of the shared assets into a fresh scene (warnings collected, not printed):
// the SceneError's message when it is rejected, else nullopt; `meshes` gets the mesh count.
std::optional<std::string> loadError(const fs::path& p, size_t* meshes = nullptr) {
  hv::Scene s;
  std::vector<std::string> w;
  hv::GltfOptions opt;
  opt.warnings = &w;
  try {
    hv::loadGltf(p.string(), glm::mat4(1.0f), s, opt);
  } catch (const hv::SceneError& e) {
    return std::string(e.what());
  }
  if (meshes) *meshes = s.meshes.size();
  return std::nullopt;
}

}  // namespace

TEST(GltfAssets, SampleModelsLoad) {
  const fs::path dir = assetsDir() / "gltf";
  if (assetsDir().empty() || !fs::is_directory(dir)) GTEST_SKIP() << "no shared assets at " << dir;
  int pass = 0, fail = 0;
  for (const fs::path& p : gltfFiles(dir)) {
    size_t meshes = 0;
    if (const auto err = loadError(p, &meshes)) {
      ADD_FAILURE() << *err;
      ++fail;
    } else {
      EXPECT_GT(meshes, 0u) << p;
      ++pass;
    }
  }
  std::cout << "[ gltf/ ] " << pass << " loaded, " << fail << " failed\n";
  EXPECT_EQ(pass, 5);
}

TEST(GltfAssets, AssetGeneratorPositiveLoads) {
  const fs::path dir = assetsDir() / "gltf-asset-generator" / "Positive";
  if (assetsDir().empty() || !fs::is_directory(dir)) GTEST_SKIP() << "no shared assets at " << dir;
  int pass = 0, fail = 0;
  for (const fs::path& p : gltfFiles(dir)) {
    if (const auto err = loadError(p)) {
      ADD_FAILURE() << *err;
      ++fail;
    } else {
      ++pass;
    }
  }
  std::cout << "[ Positive ] " << pass << " loaded, " << fail << " failed\n";
  EXPECT_GT(pass, 0);
}

TEST(GltfAssets, AssetGeneratorNegativeRejected) {
  const fs::path dir = assetsDir() / "gltf-asset-generator" / "Negative";
  if (assetsDir().empty() || !fs::is_directory(dir)) GTEST_SKIP() << "no shared assets at " << dir;
  int rejected = 0, accepted = 0;
  for (const fs::path& p : gltfFiles(dir)) {
    if (const auto err = loadError(p)) {
      EXPECT_NE(err->find(p.filename().string()), std::string::npos);
      ++rejected;
    } else if (p.filename().string().rfind("Mesh_NoPosition_", 0) == 0) {
      // Valid glTF (the Khronos validator: a warning), the primitive skipped as the spec asks:
      // "Negative" in the generator's sense, nothing to render.
      ++accepted;
    } else {
      ADD_FAILURE() << p << " was accepted";
      ++accepted;
    }
  }
  std::cout << "[ Negative ] " << rejected << " rejected, " << accepted << " accepted\n";
  EXPECT_GT(rejected, 0);
}
