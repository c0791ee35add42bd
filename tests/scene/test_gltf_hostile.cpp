// Hostile glTF/GLB files: offsets and counts near 2^64, node chains deeper than any
// stack, node graphs that reuse nodes into billions of instances, images that decode into
// gigabytes, broken GLB containers. Each must be rejected with a SceneError that names the file
// and the element, leaving the scene unchanged (how fast: scripts/fuzz.sh replays them timed).
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>

#include "halfvec/scene/gltf_loader.hpp"
#include "scene/gltf_test_files.hpp"

namespace fs = std::filesystem;
using hv::test::base64;
using hv::test::quad;
using hv::test::tempDir;
using nlohmann::json;

namespace {

// Loads `bytes` as file `name` (written to disk, loaded by path); returns the error, "" if none.
std::string loadError(const std::string& bytes, const std::string& name,
                      const hv::GltfOptions& opt = {}) {
  const fs::path p = tempDir() / name;
  std::ofstream(p, std::ios::binary) << bytes;
  hv::Scene scene;
  std::string err;
  try {
    hv::loadGltf(p.string(), glm::mat4(1.0f), scene, opt);
  } catch (const hv::SceneError& e) {
    err = e.what();
    EXPECT_TRUE(scene.meshes.empty() && scene.materials.empty() && scene.objects.empty() &&
                scene.images.empty())
        << "half-loaded scene";
    EXPECT_NE(err.find(p.string()), std::string::npos) << "the message must name the file: " << err;
  }
  return err;
}

std::string loadError(const json& j, const std::string& name, const hv::GltfOptions& opt = {}) {
  return loadError(j.dump(), name, opt);
}

void put32(std::string& s, uint32_t v) {
  for (int i = 0; i < 4; ++i) s.push_back(char((v >> (8 * i)) & 0xFF));
}

// A GLB: header, JSON chunk (padded with spaces), BIN chunk (padded with zeros) when non-empty.
std::string glb(const json& j, std::string bin) {
  std::string text = j.dump();
  while (text.size() % 4) text.push_back(' ');
  while (bin.size() % 4) bin.push_back('\0');
  std::string out = "glTF";
  put32(out, 2);
  put32(out, uint32_t(12 + 8 + text.size() + (bin.empty() ? 0 : 8 + bin.size())));
  put32(out, uint32_t(text.size()));
  put32(out, 0x4E4F534Au);
  out += text;
  if (!bin.empty()) {
    put32(out, uint32_t(bin.size()));
    put32(out, 0x004E4942u);
    out += bin;
  }
  return out;
}

// The quad's buffer bytes (positions, indices, UVs) as the GLB's BIN chunk.
std::string quadBin() {
  std::string bin;
  const float pos[12] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
  const uint16_t idx[6] = {0, 1, 2, 0, 2, 3};
  const float uv[8] = {0, 1, 1, 1, 1, 0, 0, 0};
  bin.append(reinterpret_cast<const char*>(pos), sizeof pos);
  bin.append(reinterpret_cast<const char*>(idx), sizeof idx);
  bin.append(reinterpret_cast<const char*>(uv), sizeof uv);
  return bin;
}

json quadGlbJson() {
  json j = quad();
  j["buffers"][0].erase("uri");
  return j;
}

// A PNG whose header declares w x h (no image data: only the header is read before the check).
std::vector<uint8_t> pngHeaderOnly(uint32_t w, uint32_t h) {
  std::vector<uint8_t> p = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n',
                            0,    0,   0,   13,  'I',  'H',  'D',  'R'};
  for (uint32_t v : {w, h}) {
    for (int i = 3; i >= 0; --i) p.push_back(uint8_t(v >> (8 * i)));
  }
  p.insert(p.end(), {8, 6, 0, 0, 0, 0, 0, 0, 0});  // 8-bit RGBA, CRC (not checked by the reader)
  return p;
}

bool has(const std::string& err, const std::string& what) {
  return err.find(what) != std::string::npos;
}

}  // namespace

TEST(GltfHostile, OffsetsNear2To64AreRejected) {
  json j = quad();
  j["bufferViews"][0]["byteOffset"] = 18446744073709551600ull;  // wraps offset + length
  std::string e = loadError(j, "view_offset.gltf");
  EXPECT_TRUE(has(e, "bufferViews[0].byteOffset")) << e;
  j = quad();
  j["accessors"][0]["byteOffset"] = 18446744073709551600ull;
  e = loadError(j, "accessor_offset.gltf");
  EXPECT_TRUE(has(e, "accessors[0].byteOffset")) << e;
  j = quad();
  j["bufferViews"][0]["byteLength"] = 18446744073709551615ull;
  e = loadError(j, "view_length.gltf");
  EXPECT_TRUE(has(e, "bufferViews[0].byteLength")) << e;
  j = quad();
  j["bufferViews"][0]["byteStride"] = 4;  // smaller than a VEC3 float element
  e = loadError(j, "stride.gltf");
  EXPECT_TRUE(has(e, "bufferViews[0].byteStride")) << e;
}

TEST(GltfHostile, HugeCountsAreRejectedBeforeAllocating) {
  json j = quad();
  j["accessors"][0]["count"] = 18446744073709551615ull;
  std::string e = loadError(j, "count_max.gltf");
  EXPECT_TRUE(has(e, "accessors[0].count") && has(e, "max_vertices")) << e;
  j = quad();
  j["accessors"][0]["count"] = 1ull << 40;
  j["accessors"][0].erase("bufferView");  // zeros: nothing to check against but the budget
  e = loadError(j, "count_nobuffer.gltf");
  EXPECT_TRUE(has(e, "accessors[0].count")) << e;
  j = quad();
  j["accessors"][1]["count"] = 4611686018427387904ull;  // 2^62 indices
  e = loadError(j, "index_count.gltf");
  EXPECT_TRUE(has(e, "accessors[1].count")) << e;
  j = quad();
  j["accessors"][0]["count"] = 4;  // count * stride wraps: stride 2^62 is not a valid stride
  j["accessors"][0]["byteOffset"] = 47;
  e = loadError(j, "count_offset.gltf");
  EXPECT_TRUE(has(e, "accessors[0].count")) << e;
}

TEST(GltfHostile, SparseAccessorsChecked) {
  json j = quad();
  // Sparse TEXCOORD_0 with one index (read from the index buffer: 0) and values from UVs.
  j["accessors"][2]["sparse"] = {{"count", 1},
                                 {"indices", {{"bufferView", 1}, {"componentType", 5123}}},
                                 {"values", {{"bufferView", 2}}}};
  EXPECT_EQ(loadError(j, "sparse_ok.gltf"), "");
  j["accessors"][2]["sparse"]["count"] = 5;  // more than the accessor's 4 elements
  std::string e = loadError(j, "sparse_count.gltf");
  EXPECT_TRUE(has(e, "accessors[2].sparse.count")) << e;
  j["accessors"][2]["sparse"]["count"] = 1;
  j["accessors"][2]["sparse"]["indices"]["byteOffset"] = 2147483644;
  e = loadError(j, "sparse_offset.gltf");
  EXPECT_TRUE(has(e, "accessors[2].sparse.indices.byteOffset")) << e;
}

TEST(GltfHostile, DeepNodeChainIsRejectedWithoutRecursion) {
  json j = quad();
  const int n = 200000;
  json nodes = json::array();
  for (int i = 0; i < n; ++i) {
    json node = {{"mesh", 0}};
    if (i + 1 < n) node["children"] = {i + 1};
    nodes.push_back(node);
  }
  j["nodes"] = nodes;
  const std::string e = loadError(j, "deep.gltf");
  EXPECT_TRUE(has(e, "max_node_depth")) << e;
  // Within the limit the chain loads (iteratively): 1000 levels.
  json ok = quad();
  ok["nodes"] = json::array();
  for (int i = 0; i < 1000; ++i) {
    json node = {{"mesh", 0}};
    if (i + 1 < 1000) node["children"] = {i + 1};
    ok["nodes"].push_back(node);
  }
  hv::Scene scene;
  const fs::path p = tempDir() / "chain1000.gltf";
  std::ofstream(p) << ok.dump();
  hv::loadGltf(p.string(), glm::mat4(1.0f), scene);
  EXPECT_EQ(scene.objects.size(), 1000u);
}

TEST(GltfHostile, NodeReuseExplosionIsBounded) {
  // 64 nodes, each listing the next one 4 times: 4^63 instances if expanded.
  json j = quad();
  json nodes = json::array();
  for (int i = 0; i < 64; ++i) {
    json node = {{"mesh", 0}};
    if (i + 1 < 64) node["children"] = {i + 1, i + 1, i + 1, i + 1};
    nodes.push_back(node);
  }
  j["nodes"] = nodes;
  // The expansion is counted per node before anything is instanced: the error comes at once,
  // naming the root, instead of after 1,048,576 instances have been built (9 s in this test).
  const auto t0 = std::chrono::steady_clock::now();
  std::string e = loadError(j, "dag.gltf");
  EXPECT_TRUE(has(e, "nodes[0]") && has(e, "max_node_instances")) << e;
  std::printf("[          ] rejected in %.3f s\n",
              std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  // The instanced-triangle budget is checked on its own (lowered here).
  hv::GltfOptions opt;
  opt.limits.max_instanced_triangles = 5;
  j = quad();  // two instances of a 2-triangle mesh: 4 triangles, fits
  EXPECT_EQ(loadError(j, "two.gltf", opt), "");
  j["nodes"][1]["children"] = {2};
  j["nodes"].push_back({{"mesh", 0}});  // a third: 6 > 5
  e = loadError(j, "three.gltf", opt);
  EXPECT_TRUE(has(e, "nodes[0]") && has(e, "max_instanced_triangles")) << e;
  // Two roots: the total over the scene's roots counts (2 + 2 + 2 = 6 > 5 only with both).
  j["nodes"][1]["children"] = json::array();
  j["scenes"][0]["nodes"] = {0, 2};
  e = loadError(j, "roots.gltf", opt);
  EXPECT_TRUE(has(e, "nodes[2]") && has(e, "max_instanced_triangles")) << e;
  j["nodes"][1]["children"] = {2};
  j["scenes"][0]["nodes"] = {0};
  j["nodes"][2]["children"] = {0};  // a cycle
  e = loadError(j, "cycle.gltf");
  EXPECT_TRUE(has(e, "cycle")) << e;
}

TEST(GltfHostile, MeshBudgets) {
  hv::GltfOptions opt;
  opt.limits.max_triangles = 1;
  std::string e = loadError(quad(), "tris.gltf", opt);
  EXPECT_TRUE(has(e, "max_triangles")) << e;
  opt = {};
  opt.limits.max_vertices = 5;  // no NORMAL: flat normals need 6 vertices
  e = loadError(quad(), "verts.gltf", opt);
  EXPECT_TRUE(has(e, "meshes[0].primitives[0]") && has(e, "max_vertices")) << e;
}

TEST(GltfHostile, NonFiniteValuesAreRejected) {
  json j = quad();
  j["nodes"][0]["translation"] = {1e300, 0, 0};  // finite double, +inf as float
  std::string e = loadError(j, "translation.gltf");
  EXPECT_TRUE(has(e, "nodes[0].translation")) << e;
  j = quad();
  j["nodes"][0]["scale"] = {1e30, 1e30, 1e30};  // finite, but beyond the scene's range
  j["nodes"][1]["scale"] = {1e30, 1e30, 1e30};  // (and the child's world matrix is not finite)
  e = loadError(j, "world.gltf");
  EXPECT_TRUE(has(e, "nodes[0]") && has(e, "world scale beyond the scene's range")) << e;
  j = quad();
  j["materials"][0]["pbrMetallicRoughness"]["roughnessFactor"] = 1e300;
  e = loadError(j, "factor.gltf");
  EXPECT_TRUE(has(e, "materials[0].pbrMetallicRoughness.roughnessFactor")) << e;
}

TEST(GltfHostile, ImagesAreBoundedBeforeDecoding) {
  json j = quad();
  j["images"] = {{{"uri", "data:image/png;base64," + base64(pngHeaderOnly(16385, 16))}}};
  j["textures"] = {{{"source", 0}}};
  j["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"] = {{"index", 0}};
  std::string e = loadError(j, "bigimage.gltf");
  EXPECT_TRUE(has(e, "images[0]") && has(e, "max_image_side")) << e;
  hv::GltfOptions opt;
  opt.limits.max_image_pixels = 1000;
  j["images"][0]["uri"] = "data:image/png;base64," + base64(pngHeaderOnly(100, 100));
  e = loadError(j, "budget.gltf", opt);
  EXPECT_TRUE(has(e, "images[0]") && has(e, "max_image_pixels")) << e;
  // Within the budgets, but no image data to inflate to 4096 x 4096 pixels: rejected before
  // stb_image allocates 64 MiB for them (halfvec/core/png_bound.hpp).
  j["images"][0]["uri"] = "data:image/png;base64," + base64(pngHeaderOnly(4096, 4096));
  e = loadError(j, "nodata.gltf");
  EXPECT_TRUE(has(e, "images[0]") && has(e, "4096x4096") && has(e, "IDAT")) << e;
  // An image in a bufferView that reaches past its buffer (tinygltf would read out of bounds).
  json g = quadGlbJson();
  g["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", 80}, {"byteLength", 4000}});
  g["images"] = {{{"bufferView", 3}, {"mimeType", "image/png"}}};
  e = loadError(glb(g, quadBin()), "imageview.glb");
  EXPECT_TRUE(has(e, "bufferViews[3].byteLength")) << e;
}

TEST(GltfHostile, GlbContainerChecked) {
  const std::string good = glb(quadGlbJson(), quadBin());
  EXPECT_EQ(loadError(good, "good.glb"), "");
  std::string b = good;
  b[8] = char(b[8] + 4);  // header length != file size
  EXPECT_TRUE(has(loadError(b, "length.glb"), "header.length"));
  // BIN chunk length reaching 8 bytes past the file (accepted by tinygltf 2.7 alone).
  b = good;
  const size_t bin_at = 20 + size_t(uint8_t(good[12]) | uint8_t(good[13]) << 8);
  const uint32_t bin_len = uint32_t(good.size() - bin_at - 8) + 8;
  std::memcpy(&b[bin_at], &bin_len, 4);
  std::string e = loadError(b, "binlen.glb");
  EXPECT_TRUE(has(e, "chunks[1].chunkLength")) << e;
  b = good;
  b[12] = char(0xF0), b[15] = char(0x7F);  // JSON chunk of ~2 GB
  e = loadError(b, "jsonlen.glb");
  EXPECT_TRUE(has(e, "chunks[0].chunkLength")) << e;
  e = loadError(good.substr(0, 19), "short.glb");
  EXPECT_TRUE(has(e, "too short")) << e;
  json z = quadGlbJson();
  z["buffers"][0]["byteLength"] = 0;  // tinygltf 2.7 throws std::out_of_range on this
  e = loadError(glb(z, quadBin()), "zerobuf.glb");
  EXPECT_TRUE(has(e, "zerobuf.glb")) << e;
}

TEST(GltfHostile, DeepJsonIsRejected) {
  // tinygltf converts "extras" recursively: 100,000 nested arrays would overflow the stack.
  std::string text = quad().dump();
  text.pop_back();
  text += ",\"extras\":" + std::string(100000, '[') + std::string(100000, ']') + "}";
  const std::string e = loadError(text, "deepjson.gltf");
  EXPECT_TRUE(has(e, "max_json_depth")) << e;
}

// Regression: a 1e38 translation and an all-zero matrix were rejected with errors about
// "/camera/...", a camera the user never wrote (the framing of the model's bounds), and a node
// with scale 0 (valid glTF) was refused. Now: an out-of-range transform is reported at the node,
// by index and name; a singular one (scale 0) hides the node's mesh, with one warning.
TEST(GltfHostile, DegenerateNodeTransformsNamedOrLoaded) {
  json j = quad();
  j["nodes"][1]["name"] = "far away";
  j["nodes"][1]["translation"] = {1e38, 0, 0};
  std::string e = loadError(j, "far.gltf");
  EXPECT_TRUE(has(e, "nodes[1] (\"far away\")") && has(e, "world translation beyond")) << e;

  for (const bool matrix : {false, true}) {
    j = quad();
    if (matrix) {
      j["nodes"][1]["matrix"] = std::vector<double>(16, 0.0);
    } else {
      j["nodes"][1]["scale"] = {0, 0, 0};
    }
    const fs::path p = tempDir() / (matrix ? "zero_matrix.gltf" : "scale0.gltf");
    std::ofstream(p, std::ios::binary) << j.dump();
    hv::Scene scene;
    std::vector<std::string> warnings;
    hv::GltfOptions opt;
    opt.warnings = &warnings;
    EXPECT_NO_THROW(hv::loadGltf(p.string(), glm::mat4(1.0f), scene, opt)) << p;
    EXPECT_EQ(scene.objects.size(), 1u) << "nodes[1], of scale 0, has nothing to draw";
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_TRUE(has(warnings[0], "nodes[1]") && has(warnings[0], "singular transform"))
        << warnings[0];
  }
  // Scale 0 on one axis of a third node: the other two still draw.
  j = quad();
  j["nodes"].push_back(j["nodes"][1]);
  j["nodes"][0]["children"].push_back(2);
  j["nodes"][2]["scale"] = {1, 0, 1};
  const fs::path p = tempDir() / "flat.gltf";
  std::ofstream(p, std::ios::binary) << j.dump();
  hv::Scene scene;
  std::vector<std::string> warnings;
  hv::GltfOptions opt;
  opt.warnings = &warnings;
  hv::loadGltf(p.string(), glm::mat4(1.0f), scene, opt);
  EXPECT_EQ(scene.objects.size(), 2u);
  EXPECT_EQ(warnings.size(), 1u);
}
