// glTF import on top of tinygltf (Debian libtinygltf-dev). tinygltf parses JSON, loads buffers
// and decodes images (stb_image from Debian's libstb); everything else (accessor bounds, index
// validation, primitive conversion, materials) is checked and done here.
#define TINYGLTF_IMPLEMENTATION
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_INCLUDE_JSON  // nlohmann/json is already included below, outside the
                                  // hidden-visibility pragma tinygltf wraps around it
#include <nlohmann/json.hpp>
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-parameter"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#include <tiny_gltf.h>
#pragma GCC diagnostic pop

#include "halfvec/scene/gltf_loader.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <functional>
#include <map>
#include <set>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "tangents.hpp"

namespace hv {
namespace {

namespace fs = std::filesystem;

class Importer {
 public:
  Importer(std::string path, const tinygltf::Model& model, const Scene& scene,
           const GltfOptions& opt)
      : path_(std::move(path)), m_(model), opt_(opt) {
    image_base_ = int(scene.images.size());
    material_base_ = int(scene.materials.size());
    mesh_base_ = int(scene.meshes.size());
  }

  [[noreturn]] void fail(const std::string& element, const std::string& msg) const {
    throw SceneError(path_ + ": " + element + ": " + msg);
  }
  void warn(const std::string& msg) const { sceneWarning(path_ + ": " + msg, opt_.warnings); }

  void run(const glm::mat4& transform) {
    for (const std::string& ext : m_.extensionsRequired) {
      if (ext != "KHR_materials_pbrSpecularGlossiness" && ext != "KHR_mesh_quantization") {
        fail("extensionsRequired", "unsupported required extension " + ext);
      }
    }
    if (opt_.material_override < 0) {
      for (size_t i = 0; i < m_.images.size(); ++i) importImage(int(i));
      for (size_t i = 0; i < m_.materials.size(); ++i) importMaterial(int(i));
    }
    mesh_map_.assign(m_.meshes.size(), {});
    // Every mesh is validated even if no node uses it.
    for (size_t i = 0; i < m_.meshes.size(); ++i) importMesh(int(i));
    std::vector<int> roots;
    if (!m_.scenes.empty()) {
      const int s = m_.defaultScene >= 0 ? m_.defaultScene : 0;
      if (s >= int(m_.scenes.size())) fail("scene", "index " + std::to_string(s) + " out of range");
      roots = m_.scenes[size_t(s)].nodes;
    } else {  // no scenes: every node that is nobody's child is a root
      std::vector<bool> child(m_.nodes.size(), false);
      for (const auto& n : m_.nodes)
        for (int c : n.children)
          if (c >= 0 && c < int(child.size())) child[size_t(c)] = true;
      for (size_t i = 0; i < m_.nodes.size(); ++i)
        if (!child[i]) roots.push_back(int(i));
    }
    std::vector<bool> on_path(m_.nodes.size(), false);
    for (int r : roots) visit(r, transform, on_path, "scenes.nodes");
  }

  std::vector<ImageData> images;
  std::vector<Material> materials;
  std::vector<Mesh> meshes;
  std::vector<Object> objects;
  std::vector<GltfCamera> cameras;

 private:
  // ---- accessors ---------------------------------------------------------------------------
  // Reads accessor `index` as `count` x `comps` floats (normalized integers mapped to [0,1] or
  // [-1,1], plain integers converted), after checking type and every byte range.
  std::vector<float> readFloats(int index, const std::string& what,
                                std::initializer_list<int> types, std::initializer_list<int> ctypes,
                                bool require_normalized_ints) {
    const std::string el = "accessors[" + std::to_string(index) + "] (" + what + ")";
    if (index < 0 || index >= int(m_.accessors.size())) fail(what, "accessor index out of range");
    const tinygltf::Accessor& a = m_.accessors[size_t(index)];
    if (std::find(types.begin(), types.end(), a.type) == types.end()) fail(el, "unexpected type");
    if (std::find(ctypes.begin(), ctypes.end(), a.componentType) == ctypes.end()) {
      fail(el, "unsupported componentType " + std::to_string(a.componentType));
    }
    const bool is_float = a.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT;
    if (!is_float && require_normalized_ints && !a.normalized) {
      fail(el, "integer components must be normalized here");
    }
    const int comps = tinygltf::GetNumComponentsInType(uint32_t(a.type));
    std::vector<float> out(a.count * size_t(comps), 0.0f);
    if (a.bufferView >= 0) {
      readRaw(a.bufferView, a.byteOffset, a.count, comps, a.componentType, a.normalized, el,
              out.data());
    }
    if (a.sparse.isSparse) {
      const size_t n = size_t(std::max(0, a.sparse.count));
      std::vector<uint32_t> idx(n);
      std::vector<float> tmp(n);
      readRaw(a.sparse.indices.bufferView, size_t(std::max(0, a.sparse.indices.byteOffset)), n, 1,
              a.sparse.indices.componentType, false, el + ".sparse.indices", tmp.data());
      std::vector<float> vals(n * size_t(comps));
      readRaw(a.sparse.values.bufferView, size_t(std::max(0, a.sparse.values.byteOffset)), n, comps,
              a.componentType, a.normalized, el + ".sparse.values", vals.data());
      for (size_t i = 0; i < n; ++i) {
        const double k = tmp[i];
        if (k < 0 || k >= double(a.count)) fail(el + ".sparse.indices", "index out of range");
        std::copy_n(&vals[i * size_t(comps)], comps, &out[size_t(k) * size_t(comps)]);
      }
    }
    return out;
  }

  void readRaw(int view_index, size_t byte_offset, size_t count, int comps, int ctype,
               bool normalized, const std::string& el, float* out) {
    if (view_index < 0 || view_index >= int(m_.bufferViews.size())) {
      fail(el, "bufferView index " + std::to_string(view_index) + " out of range");
    }
    const tinygltf::BufferView& v = m_.bufferViews[size_t(view_index)];
    const std::string vel = "bufferViews[" + std::to_string(view_index) + "]";
    if (v.buffer < 0 || v.buffer >= int(m_.buffers.size())) fail(vel, "buffer index out of range");
    const std::vector<unsigned char>& data = m_.buffers[size_t(v.buffer)].data;
    if (v.byteOffset + v.byteLength > data.size()) {
      fail(vel, "byteOffset + byteLength (" + std::to_string(v.byteOffset + v.byteLength) +
                    ") exceeds buffer size " + std::to_string(data.size()));
    }
    const int csize = tinygltf::GetComponentSizeInBytes(uint32_t(ctype));
    if (csize <= 0) fail(el, "bad componentType " + std::to_string(ctype));
    const size_t elem = size_t(csize) * size_t(comps);
    const size_t stride = v.byteStride ? v.byteStride : elem;
    if (stride < elem) fail(el, "byteStride smaller than the element size");
    if (count > 0 && byte_offset + stride * (count - 1) + elem > v.byteLength) {
      fail(el, "accessor range (offset " + std::to_string(byte_offset) + ", " +
                   std::to_string(count) + " elements, stride " + std::to_string(stride) +
                   ") exceeds " + vel + ".byteLength " + std::to_string(v.byteLength));
    }
    const unsigned char* base = data.data() + v.byteOffset + byte_offset;
    for (size_t i = 0; i < count; ++i) {
      const unsigned char* p = base + i * stride;
      for (int c = 0; c < comps; ++c) {
        const unsigned char* q = p + size_t(c) * size_t(csize);
        float f = 0.0f;
        switch (ctype) {
          case TINYGLTF_COMPONENT_TYPE_FLOAT:
            std::memcpy(&f, q, 4);
            break;
          case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
            f = normalized ? *q / 255.0f : *q;
            break;
          case TINYGLTF_COMPONENT_TYPE_BYTE: {
            const int8_t x = int8_t(*q);
            f = normalized ? std::max(x / 127.0f, -1.0f) : x;
            break;
          }
          case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
            uint16_t x;
            std::memcpy(&x, q, 2);
            f = normalized ? x / 65535.0f : x;
            break;
          }
          case TINYGLTF_COMPONENT_TYPE_SHORT: {
            int16_t x;
            std::memcpy(&x, q, 2);
            f = normalized ? std::max(x / 32767.0f, -1.0f) : x;
            break;
          }
          case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
            uint32_t x;
            std::memcpy(&x, q, 4);
            f = float(x);
            break;
          }
          default:
            fail(el, "bad componentType " + std::to_string(ctype));
        }
        out[i * size_t(comps) + size_t(c)] = f;
      }
    }
  }

  std::vector<uint32_t> readIndices(int index, size_t vertex_count, const std::string& el) {
    if (index < 0 || index >= int(m_.accessors.size())) fail(el, "indices accessor out of range");
    const tinygltf::Accessor& a = m_.accessors[size_t(index)];
    const std::string ael = el + " indices (accessors[" + std::to_string(index) + "])";
    if (a.type != TINYGLTF_TYPE_SCALAR) fail(ael, "expected type SCALAR");
    uint32_t restart = 0;
    switch (a.componentType) {
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        restart = 0xFFu;
        break;
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
        restart = 0xFFFFu;
        break;
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
        restart = 0xFFFFFFFFu;
        break;
      default:
        fail(ael, "componentType " + std::to_string(a.componentType) +
                      " is not UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT");
    }
    if (a.normalized) fail(ael, "indices must not be normalized");
    if (a.bufferView < 0) fail(ael, "indices need a bufferView");
    // Read as raw integers (floats would lose 32-bit precision).
    const tinygltf::BufferView& v =
        m_.bufferViews.at(size_t(std::min<int>(a.bufferView, int(m_.bufferViews.size()) - 1)));
    std::vector<float> check(a.count);  // performs every bounds check
    readRaw(a.bufferView, a.byteOffset, a.count, 1, a.componentType, false, ael, check.data());
    const int csize = tinygltf::GetComponentSizeInBytes(uint32_t(a.componentType));
    const size_t stride = v.byteStride ? v.byteStride : size_t(csize);
    const unsigned char* base =
        m_.buffers[size_t(v.buffer)].data.data() + v.byteOffset + a.byteOffset;
    std::vector<uint32_t> out(a.count);
    for (size_t i = 0; i < a.count; ++i) {
      uint32_t x = 0;
      if (csize == 1) x = base[i * stride];
      if (csize == 2) {
        uint16_t s;
        std::memcpy(&s, base + i * stride, 2);
        x = s;
      }
      if (csize == 4) std::memcpy(&x, base + i * stride, 4);
      if (x == restart) {
        fail(ael, "index " + std::to_string(i) + " is the primitive-restart value " +
                      std::to_string(restart) + ", which glTF forbids");
      }
      if (x >= vertex_count) {
        fail(ael, "index " + std::to_string(i) + " = " + std::to_string(x) + " >= vertex count " +
                      std::to_string(vertex_count));
      }
      out[i] = x;
    }
    return out;
  }

  // ---- images, materials ---------------------------------------------------------------------
  void importImage(int i) {
    const tinygltf::Image& im = m_.images[size_t(i)];
    const std::string el = "images[" + std::to_string(i) + "]";
    ImageData out;
    out.name = im.name.empty() ? (im.uri.empty() ? el : im.uri) : im.name;
    if (im.image.empty() || im.width <= 0 || im.height <= 0) {
      fail(el,
           "image could not be loaded or decoded" + (im.uri.empty() ? "" : " (" + im.uri + ")"));
    }
    const int comps = im.component, bytes = std::max(1, im.bits / 8);
    if (comps < 1 || comps > 4 || (bytes != 1 && bytes != 2) ||
        im.image.size() < size_t(im.width) * size_t(im.height) * size_t(comps * bytes)) {
      fail(el, "unsupported pixel layout");
    }
    out.width = im.width;
    out.height = im.height;
    out.rgba.resize(size_t(im.width) * size_t(im.height) * 4);
    for (size_t p = 0; p < size_t(im.width) * size_t(im.height); ++p) {
      uint8_t c[4] = {0, 0, 0, 255};
      for (int k = 0; k < comps; ++k) {
        const size_t at = (p * size_t(comps) + size_t(k)) * size_t(bytes);
        c[k] = bytes == 1 ? im.image[at] : im.image[at + 1];  // 16-bit little endian: high byte
      }
      if (comps == 1) c[1] = c[2] = c[0];
      if (comps == 2) c[3] = c[1], c[1] = c[2] = c[0];  // grey + alpha
      std::memcpy(&out.rgba[p * 4], c, 4);
    }
    images.push_back(std::move(out));
  }

  TextureRef texture(int tex_index, int texcoord, const std::string& el) {
    TextureRef r;
    if (tex_index < 0) return r;
    if (tex_index >= int(m_.textures.size())) fail(el, "texture index out of range");
    const tinygltf::Texture& t = m_.textures[size_t(tex_index)];
    if (texcoord < 0 || texcoord > 1)
      fail(el, "texCoord " + std::to_string(texcoord) + " not supported (0 or 1)");
    r.texcoord = texcoord;
    if (t.source < 0) {
      warn(el + ": texture has no source image (extension-only source?); ignored");
      return r;
    }
    if (t.source >= int(m_.images.size())) fail(el, "texture source out of range");
    r.image = image_base_ + t.source;
    if (t.sampler >= 0) {
      if (t.sampler >= int(m_.samplers.size())) fail(el, "sampler index out of range");
      const tinygltf::Sampler& s = m_.samplers[size_t(t.sampler)];
      auto wrap = [&](int w) {
        switch (w) {
          case TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE:
            return Wrap::ClampToEdge;
          case TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT:
            return Wrap::MirroredRepeat;
          case TINYGLTF_TEXTURE_WRAP_REPEAT:
            return Wrap::Repeat;
          default:
            fail(el, "bad sampler wrap mode " + std::to_string(w));
        }
      };
      r.sampler.wrap_s = wrap(s.wrapS);
      r.sampler.wrap_t = wrap(s.wrapT);
      r.sampler.mag =
          s.magFilter == TINYGLTF_TEXTURE_FILTER_NEAREST ? Filter::Nearest : Filter::Linear;
      switch (s.minFilter) {
        case TINYGLTF_TEXTURE_FILTER_NEAREST:
          r.sampler.min = Filter::Nearest, r.sampler.mipmaps = false;
          break;
        case TINYGLTF_TEXTURE_FILTER_LINEAR:
          r.sampler.min = Filter::Linear, r.sampler.mipmaps = false;
          break;
        case TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_NEAREST:
        case TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_LINEAR:
          r.sampler.min = Filter::Nearest;
          break;
        default:
          r.sampler.min = Filter::Linear;
          break;  // LINEAR_MIPMAP_* or unset
      }
    }
    return r;
  }

  void importMaterial(int i) {
    const tinygltf::Material& g = m_.materials[size_t(i)];
    const std::string el = "materials[" + std::to_string(i) + "]";
    Material m;
    m.name = g.name.empty() ? el : g.name;
    const auto& pbr = g.pbrMetallicRoughness;
    if (pbr.baseColorFactor.size() == 4) {
      m.base_color =
          glm::vec3(pbr.baseColorFactor[0], pbr.baseColorFactor[1], pbr.baseColorFactor[2]);
      m.base_alpha = float(pbr.baseColorFactor[3]);
    }
    m.metallic = float(pbr.metallicFactor);
    m.roughness = float(pbr.roughnessFactor);
    m.base_color_tex = texture(pbr.baseColorTexture.index, pbr.baseColorTexture.texCoord,
                               el + ".baseColorTexture");
    m.metallic_roughness_tex =
        texture(pbr.metallicRoughnessTexture.index, pbr.metallicRoughnessTexture.texCoord,
                el + ".metallicRoughnessTexture");
    m.normal_tex = texture(g.normalTexture.index, g.normalTexture.texCoord, el + ".normalTexture");
    m.normal_tex.scale = float(g.normalTexture.scale);
    m.occlusion_tex =
        texture(g.occlusionTexture.index, g.occlusionTexture.texCoord, el + ".occlusionTexture");
    m.occlusion_tex.scale = float(g.occlusionTexture.strength);
    m.emissive_tex =
        texture(g.emissiveTexture.index, g.emissiveTexture.texCoord, el + ".emissiveTexture");
    if (g.emissiveFactor.size() == 3) {
      m.emissive = glm::vec3(g.emissiveFactor[0], g.emissiveFactor[1], g.emissiveFactor[2]);
    }
    m.double_sided = g.doubleSided;
    if (g.alphaMode == "MASK") {
      m.alpha_mode = AlphaMode::Mask;
      m.alpha_cutoff = float(g.alphaCutoff);
    } else if (g.alphaMode == "BLEND") {
      m.alpha_mode = AlphaMode::Opaque;
      warn(el + " \"" + m.name + "\": alphaMode BLEND is not supported; rendered opaque");
    } else if (g.alphaMode != "OPAQUE" && !g.alphaMode.empty()) {
      fail(el + ".alphaMode", "unknown value \"" + g.alphaMode + "\"");
    }
    auto sg = g.extensions.find("KHR_materials_pbrSpecularGlossiness");
    if (sg != g.extensions.end() && sg->second.IsObject()) {
      // Approximation: diffuse as base colour of a dielectric, roughness = 1 - glossiness; the
      // specular colour and specularGlossinessTexture are not representable and dropped.
      const tinygltf::Value& v = sg->second;
      m.metallic = 0.0f;
      m.metallic_roughness_tex = {};
      m.base_color = glm::vec3(1.0f);
      m.base_alpha = 1.0f;
      m.base_color_tex = {};
      if (v.Has("diffuseFactor") && v.Get("diffuseFactor").ArrayLen() == 4) {
        const auto& f = v.Get("diffuseFactor");
        m.base_color = glm::vec3(f.Get(0).GetNumberAsDouble(), f.Get(1).GetNumberAsDouble(),
                                 f.Get(2).GetNumberAsDouble());
        m.base_alpha = float(f.Get(3).GetNumberAsDouble());
      }
      m.roughness =
          1.0f -
          (v.Has("glossinessFactor") ? float(v.Get("glossinessFactor").GetNumberAsDouble()) : 1.0f);
      if (v.Has("diffuseTexture")) {
        const auto& t = v.Get("diffuseTexture");
        const int index = t.Has("index") ? t.Get("index").GetNumberAsInt() : -1;
        const int tc = t.Has("texCoord") ? t.Get("texCoord").GetNumberAsInt() : 0;
        m.base_color_tex = texture(index, tc, el + ".diffuseTexture");
      }
      if (!warned_specgloss_) {
        warn(
            "KHR_materials_pbrSpecularGlossiness approximated as metal/rough (specular colour "
            "dropped)");
        warned_specgloss_ = true;
      }
    }
    m.base_color = glm::clamp(m.base_color, 0.0f, 1.0f);
    m.metallic = glm::clamp(m.metallic, 0.0f, 1.0f);
    m.roughness = glm::clamp(m.roughness, 0.0f, 1.0f);
    materials.push_back(m);
  }

  int defaultMaterial() {
    if (opt_.material_override >= 0) return opt_.material_override;
    if (default_material_ < 0) {
      Material m;
      m.name = "gltf default";
      materials.push_back(m);
      default_material_ = int(materials.size()) - 1;
    }
    return material_base_ + default_material_;
  }

  // ---- meshes --------------------------------------------------------------------------------
  void importMesh(int mi) {
    const tinygltf::Mesh& gm = m_.meshes[size_t(mi)];
    for (size_t pi = 0; pi < gm.primitives.size(); ++pi) {
      const std::string el =
          "meshes[" + std::to_string(mi) + "].primitives[" + std::to_string(pi) + "]";
      std::optional<Mesh> mesh = importPrimitive(gm.primitives[pi], el);
      if (!mesh) continue;
      mesh->name =
          (gm.name.empty() ? "mesh" + std::to_string(mi) : gm.name) + "/" + std::to_string(pi);
      meshes.push_back(std::move(*mesh));
      mesh_map_[size_t(mi)].push_back(mesh_base_ + int(meshes.size()) - 1);
    }
  }

  std::optional<Mesh> importPrimitive(const tinygltf::Primitive& p, const std::string& el) {
    auto attr = [&](const char* name) {
      auto it = p.attributes.find(name);
      return it == p.attributes.end() ? -1 : it->second;
    };
    const int pos_acc = attr("POSITION");
    if (pos_acc < 0) fail(el, "primitive has no POSITION attribute");
    using std::initializer_list;
    constexpr int kF = TINYGLTF_COMPONENT_TYPE_FLOAT, kUB = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,
                  kB = TINYGLTF_COMPONENT_TYPE_BYTE, kUS = TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                  kS = TINYGLTF_COMPONENT_TYPE_SHORT;
    const std::vector<float> pos =
        readFloats(pos_acc, el + ".POSITION", {TINYGLTF_TYPE_VEC3}, {kF, kB, kUB, kS, kUS}, false);
    const size_t n = pos.size() / 3;
    for (float f : pos)
      if (!std::isfinite(f)) fail(el + ".POSITION", "non-finite value");
    std::vector<float> nrm, tan, uv[2];
    const bool has_normal = attr("NORMAL") >= 0;
    if (has_normal)
      nrm = readFloats(attr("NORMAL"), el + ".NORMAL", {TINYGLTF_TYPE_VEC3}, {kF, kB, kS}, true);
    if (has_normal && attr("TANGENT") >= 0) {
      tan = readFloats(attr("TANGENT"), el + ".TANGENT", {TINYGLTF_TYPE_VEC4}, {kF, kB, kS}, true);
    }
    for (int s = 0; s < 2; ++s) {
      const std::string name = "TEXCOORD_" + std::to_string(s);
      if (attr(name.c_str()) >= 0) {
        uv[s] = readFloats(attr(name.c_str()), el + "." + name, {TINYGLTF_TYPE_VEC2},
                           {kF, kUB, kUS, kB, kS}, true);
      }
    }
    auto sizeCheck = [&](const std::vector<float>& v, size_t comps, const char* what) {
      if (!v.empty() && v.size() != n * comps) {
        fail(el + "." + what, "count differs from POSITION count " + std::to_string(n));
      }
    };
    sizeCheck(nrm, 3, "NORMAL");
    sizeCheck(tan, 4, "TANGENT");
    sizeCheck(uv[0], 2, "TEXCOORD_0");
    sizeCheck(uv[1], 2, "TEXCOORD_1");

    std::vector<uint32_t> idx;
    if (p.indices >= 0) {
      idx = readIndices(p.indices, n, el);
    } else {
      idx.resize(n);
      for (size_t i = 0; i < n; ++i) idx[i] = uint32_t(i);
    }
    std::vector<uint32_t> tris;
    switch (p.mode) {
      case TINYGLTF_MODE_TRIANGLES:
        if (idx.size() % 3 != 0) fail(el, "TRIANGLES index count is not a multiple of 3");
        tris = idx;
        break;
      case TINYGLTF_MODE_TRIANGLE_STRIP:
        for (size_t i = 0; i + 2 < idx.size(); ++i) {  // glTF spec 3.7.2.1 ordering
          tris.insert(tris.end(), {idx[i], idx[i + 1 + i % 2], idx[i + 2 - i % 2]});
        }
        break;
      case TINYGLTF_MODE_TRIANGLE_FAN:
        for (size_t i = 1; i + 1 < idx.size(); ++i)
          tris.insert(tris.end(), {idx[i], idx[i + 1], idx[0]});
        break;
      case TINYGLTF_MODE_POINTS:
      case TINYGLTF_MODE_LINE:
      case TINYGLTF_MODE_LINE_LOOP:
      case TINYGLTF_MODE_LINE_STRIP:
        warn(el + ": mode " + std::to_string(p.mode) + " (points/lines) is not rendered; skipped");
        return std::nullopt;
      default:
        fail(el, "unknown mode " + std::to_string(p.mode));
    }

    int material;
    if (p.material >= 0) {
      if (p.material >= int(m_.materials.size())) fail(el, "material index out of range");
      material = opt_.material_override >= 0 ? opt_.material_override : material_base_ + p.material;
    } else {
      material = defaultMaterial();
    }
    int normal_set = 0;
    if (opt_.material_override < 0 && p.material >= 0) {
      normal_set = materials[size_t(p.material)].normal_tex.texcoord;
    }
    Mesh mesh;
    mesh.material = material;
    auto vertex = [&](size_t i) {
      Vertex v;
      v.position = glm::make_vec3(&pos[i * 3]);
      if (has_normal) {
        v.normal = glm::make_vec3(&nrm[i * 3]);
        const float l = glm::length(v.normal);
        v.normal = l > 1e-12f ? v.normal / l : glm::vec3(0, 1, 0);
      }
      if (!tan.empty()) {
        v.tangent = glm::make_vec4(&tan[i * 4]);
        v.tangent.w = v.tangent.w < 0.0f ? -1.0f : 1.0f;
      }
      if (!uv[0].empty()) v.uv0 = glm::make_vec2(&uv[0][i * 2]);
      if (!uv[1].empty()) v.uv1 = glm::make_vec2(&uv[1][i * 2]);
      return v;
    };
    if (has_normal) {
      mesh.vertices.reserve(n);
      for (size_t i = 0; i < n; ++i) mesh.vertices.push_back(vertex(i));
      mesh.indices = std::move(tris);
    } else {  // flat normals: every triangle gets its own three vertices
      for (size_t t = 0; t + 2 < tris.size(); t += 3) {
        Vertex v[3] = {vertex(tris[t]), vertex(tris[t + 1]), vertex(tris[t + 2])};
        glm::vec3 fn = glm::cross(v[1].position - v[0].position, v[2].position - v[0].position);
        const float l = glm::length(fn);
        fn = l > 0.0f ? fn / l : glm::vec3(0, 1, 0);
        for (Vertex& x : v) {
          x.normal = fn;
          mesh.indices.push_back(uint32_t(mesh.vertices.size()));
          mesh.vertices.push_back(x);
        }
      }
    }
    // Provided tangents are ignored when normals were missing (glTF 2.0, 3.7.2.1).
    if (tan.empty() || !has_normal) generateTangents(mesh, normal_set);
    return mesh;
  }

  // ---- nodes ---------------------------------------------------------------------------------
  void visit(int ni, const glm::mat4& parent, std::vector<bool>& on_path, const std::string& from) {
    if (ni < 0 || ni >= int(m_.nodes.size()))
      fail(from, "node index " + std::to_string(ni) + " out of range");
    const std::string el = "nodes[" + std::to_string(ni) + "]";
    if (on_path[size_t(ni)]) fail(el, "node hierarchy contains a cycle");
    on_path[size_t(ni)] = true;
    const tinygltf::Node& n = m_.nodes[size_t(ni)];
    glm::mat4 local(1.0f);
    if (n.matrix.size() == 16) {
      for (int k = 0; k < 16; ++k) glm::value_ptr(local)[k] = float(n.matrix[size_t(k)]);
    } else {
      glm::mat4 t(1.0f), r(1.0f), s(1.0f);
      if (n.translation.size() == 3) {
        t = glm::translate(glm::mat4(1.0f),
                           glm::vec3(n.translation[0], n.translation[1], n.translation[2]));
      }
      if (n.rotation.size() == 4) {
        r = glm::mat4_cast(glm::normalize(glm::quat(float(n.rotation[3]), float(n.rotation[0]),
                                                    float(n.rotation[1]), float(n.rotation[2]))));
      }
      if (n.scale.size() == 3)
        s = glm::scale(glm::mat4(1.0f), glm::vec3(n.scale[0], n.scale[1], n.scale[2]));
      local = t * r * s;
    }
    const glm::mat4 world = parent * local;
    if (n.mesh >= 0) {
      if (n.mesh >= int(m_.meshes.size())) fail(el, "mesh index out of range");
      if (!mesh_map_[size_t(n.mesh)].empty()) {
        Object o;
        o.name = (opt_.name_prefix.empty() ? fs::path(path_).stem().string() : opt_.name_prefix) +
                 "/" + (n.name.empty() ? el : n.name);
        o.transform = world;
        o.meshes = mesh_map_[size_t(n.mesh)];
        objects.push_back(std::move(o));
      }
    }
    if (n.camera >= 0 && n.camera < int(m_.cameras.size()))
      addCamera(m_.cameras[size_t(n.camera)], world);
    for (int c : n.children) visit(c, world, on_path, el + ".children");
    on_path[size_t(ni)] = false;
  }

  void addCamera(const tinygltf::Camera& c, const glm::mat4& world) {
    GltfCamera cam;
    cam.name = c.name;
    cam.world = world;
    cam.perspective = c.type != "orthographic";
    if (cam.perspective) {
      if (c.perspective.yfov > 0.0) cam.yfov_rad = float(c.perspective.yfov);
      if (c.perspective.znear > 0.0) cam.znear = float(c.perspective.znear);
      cam.zfar = float(std::max(c.perspective.zfar, 0.0));
    } else {
      cam.znear = float(std::max(c.orthographic.znear, 1e-4));
      cam.zfar = float(std::max(c.orthographic.zfar, 0.0));
    }
    cameras.push_back(cam);
  }

  std::string path_;
  const tinygltf::Model& m_;
  const GltfOptions& opt_;
  int image_base_ = 0, material_base_ = 0, mesh_base_ = 0;
  int default_material_ = -1;
  bool warned_specgloss_ = false;
  std::vector<std::vector<int>> mesh_map_;
};

}  // namespace

void loadGltf(const std::string& path, const glm::mat4& transform, Scene& scene,
              const GltfOptions& options) {
  if (!fs::is_regular_file(path)) throw SceneError(path + ": file not found");
  tinygltf::TinyGLTF loader;
  tinygltf::Model model;
  std::string err, warn;
  const std::string ext = fs::path(path).extension().string();
  if (options.material_override >= 0) {  // no glTF materials: their images are not decoded
    loader.SetImageLoader([](tinygltf::Image*, const int, std::string*, std::string*, int, int,
                             const unsigned char*, int, void*) { return true; },
                          nullptr);
  }
  bool ok;
  if (ext == ".glb" || ext == ".GLB") {
    ok = loader.LoadBinaryFromFile(&model, &err, &warn, path);
  } else {
    ok = loader.LoadASCIIFromFile(&model, &err, &warn, path);
  }
  if (!ok || !err.empty()) {
    while (!err.empty() && (err.back() == '\n' || err.back() == ' ')) err.pop_back();
    throw SceneError(path +
                     ": cannot load glTF: " + (err.empty() ? std::string("unknown error") : err));
  }
  Importer imp(path, model, scene, options);
  imp.run(transform);
  // Success: append everything at once (indices were computed against the final offsets).
  for (auto& x : imp.images) scene.images.push_back(std::move(x));
  for (auto& x : imp.materials) scene.materials.push_back(std::move(x));
  for (auto& x : imp.meshes) scene.meshes.push_back(std::move(x));
  for (auto& x : imp.objects) scene.objects.push_back(std::move(x));
  if (options.cameras) {
    for (auto& c : imp.cameras) options.cameras->push_back(std::move(c));
  }
}

}  // namespace hv
