// Hand-built glTF files for the loader tests: a small valid quad that tests then break.
#pragma once

#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace hv::test {

using nlohmann::json;
namespace fs = std::filesystem;

inline fs::path tempDir() {
  fs::path d = fs::temp_directory_path() / ("hv_test_gltf_" + std::to_string(::getpid()));
  fs::create_directories(d);
  return d;
}

inline std::string base64(const std::vector<uint8_t>& in) {
  static const char* t = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (size_t i = 0; i < in.size(); i += 3) {
    uint32_t v = uint32_t(in[i]) << 16;
    if (i + 1 < in.size()) v |= uint32_t(in[i + 1]) << 8;
    if (i + 2 < in.size()) v |= in[i + 2];
    out += t[(v >> 18) & 63];
    out += t[(v >> 12) & 63];
    out += i + 1 < in.size() ? t[(v >> 6) & 63] : '=';
    out += i + 2 < in.size() ? t[v & 63] : '=';
  }
  return out;
}

// A quad: 4 positions (float VEC3) at offset 0, then 6 uint16 indices at offset 48, then
// 4 UVs at offset 60. Returned as a model the tests then break.
inline json quad() {
  std::vector<uint8_t> buf;
  auto put = [&](const void* p, size_t n) {
    const auto* b = static_cast<const uint8_t*>(p);
    buf.insert(buf.end(), b, b + n);
  };
  const float pos[12] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
  const uint16_t idx[6] = {0, 1, 2, 0, 2, 3};
  const float uv[8] = {0, 1, 1, 1, 1, 0, 0, 0};
  put(pos, sizeof pos);
  put(idx, sizeof idx);
  put(uv, sizeof uv);
  json j;
  j["asset"] = {{"version", "2.0"}};
  j["buffers"] = {
      {{"byteLength", buf.size()}, {"uri", "data:application/octet-stream;base64," + base64(buf)}}};
  j["bufferViews"] = {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", 48}},
                      {{"buffer", 0}, {"byteOffset", 48}, {"byteLength", 12}},
                      {{"buffer", 0}, {"byteOffset", 60}, {"byteLength", 32}}};
  j["accessors"] = {{{"bufferView", 0},
                     {"componentType", 5126},
                     {"count", 4},
                     {"type", "VEC3"},
                     {"min", {0, 0, 0}},
                     {"max", {1, 1, 0}}},
                    {{"bufferView", 1}, {"componentType", 5123}, {"count", 6}, {"type", "SCALAR"}},
                    {{"bufferView", 2}, {"componentType", 5126}, {"count", 4}, {"type", "VEC2"}}};
  j["materials"] = {{{"name", "mat"},
                     {"pbrMetallicRoughness",
                      {{"baseColorFactor", {0.5, 0.25, 1, 1}},
                       {"metallicFactor", 0.5},
                       {"roughnessFactor", 0.75}}},
                     {"alphaMode", "MASK"},
                     {"alphaCutoff", 0.3},
                     {"doubleSided", true}}};
  j["meshes"] = {{{"primitives",
                   {{{"attributes", {{"POSITION", 0}, {"TEXCOORD_0", 2}}},
                     {"indices", 1},
                     {"material", 0}}}}}};
  j["nodes"] = {{{"mesh", 0}, {"translation", {1, 2, 3}}, {"children", {1}}},
                {{"mesh", 0}, {"scale", {2, 2, 2}}}};
  j["scenes"] = {{{"nodes", {0}}}};
  j["scene"] = 0;
  return j;
}

}  // namespace hv::test
