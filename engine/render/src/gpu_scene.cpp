#include "halfvec/render/gpu_scene.hpp"

#include <algorithm>
#include <cstddef>
#include <cstring>

#include "halfvec/render/frame_data.hpp"
#include "halfvec/ibl/sky_sun.hpp"
#include "halfvec/shading/light_gpu.hpp"

namespace hv::render {

namespace {
// The draw's object-space bounding box, as centre and half extents (blended draws sort by the
// centre and cull their lights by the box: forward_pass.cpp).
void setBounds(DrawItem& d, const Mesh& m) {
  if (m.vertices.empty()) return;
  glm::vec3 lo = m.vertices[0].position, hi = lo;
  for (const Vertex& v : m.vertices) {
    lo = glm::min(lo, v.position);
    hi = glm::max(hi, v.position);
  }
  d.center = 0.5f * (lo + hi);
  d.half_extent = 0.5f * (hi - lo);
}
}  // namespace

GpuScene::GpuScene(const Scene& scene) : scene_(&scene) {
  std::vector<Vertex> verts;
  std::vector<uint32_t> idx;
  std::vector<std::pair<uint32_t, int32_t>> mesh_ranges;  // first index, base vertex
  for (const Mesh& m : scene.meshes) {
    mesh_ranges.emplace_back(static_cast<uint32_t>(idx.size()), static_cast<int32_t>(verts.size()));
    verts.insert(verts.end(), m.vertices.begin(), m.vertices.end());
    idx.insert(idx.end(), m.indices.begin(), m.indices.end());
    triangles_ += m.indices.size() / 3;
  }
  for (size_t o = 0; o < scene.objects.size(); ++o) {
    for (int mi : scene.objects[o].meshes) {
      const Mesh& m = scene.meshes[mi];
      DrawItem d;
      d.first_index = mesh_ranges[mi].first;
      d.index_count = static_cast<uint32_t>(m.indices.size());
      d.base_vertex = mesh_ranges[mi].second;
      d.material = m.material;
      d.object = static_cast<int>(o);
      d.double_sided = scene.materials[m.material].double_sided;
      setBounds(d, m);
      draws_.push_back(d);
    }
  }
  vertices_ = gl::createBuffer("scene vertices", verts.size() * sizeof(Vertex), verts.data(), 0);
  indices_ = gl::createBuffer("scene indices", idx.size() * sizeof(uint32_t), idx.data(), 0);
  vao_ = gl::createVertexArray("scene vertex layout");
  const GLuint vao = vao_.id();
  glVertexArrayVertexBuffer(vao, 0, vertices_.id(), 0, sizeof(Vertex));
  glVertexArrayElementBuffer(vao, indices_.id());
  struct Attr {
    GLuint loc;
    GLint size;
    size_t offset;
  };
  for (Attr a : {Attr{0, 3, offsetof(Vertex, position)}, Attr{1, 3, offsetof(Vertex, normal)},
                 Attr{2, 4, offsetof(Vertex, tangent)}, Attr{3, 2, offsetof(Vertex, uv0)},
                 Attr{4, 2, offsetof(Vertex, uv1)}, Attr{5, 4, offsetof(Vertex, color)}}) {
    glEnableVertexArrayAttrib(vao, a.loc);
    glVertexArrayAttribFormat(vao, a.loc, a.size, GL_FLOAT, GL_FALSE,
                              static_cast<GLuint>(a.offset));
    glVertexArrayAttribBinding(vao, a.loc, 0);
  }

  const uint8_t white_px[4] = {255, 255, 255, 255};
  white_ = gl::createTexture2D("white 1x1", GL_RGBA8, 1, 1);
  glTextureSubImage2D(white_.id(), 0, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, white_px);
  default_sampler_ = gl::createSampler("default sampler");

  GLint align = 0;
  glGetIntegerv(GL_UNIFORM_BUFFER_OFFSET_ALIGNMENT, &align);
  const size_t a = size_t(std::max(align, 1));
  material_stride_ = (sizeof(GpuMaterial) + a - 1) / a * a;
  materials_ =
      gl::createBuffer("materials", std::max<size_t>(1, scene.materials.size()) * material_stride_);
  updateMaterials(scene);
  updateLights(scene);

  for (size_t i = 0; i < scene.materials.size(); ++i) {
    const Material& m = scene.materials[i];
    std::array<BoundTexture, HV_MATERIAL_TEXTURE_COUNT> t;
    static_assert(HV_MATERIAL_TEXTURE_COUNT == HV_MAT_SLOTS, "one texture unit per slot");
    const auto refs = materialTextureSlots(m);
    const bool srgb[HV_MATERIAL_TEXTURE_COUNT] = {true, false, false, false,
                                                  true, false, false, false};
    for (int s = 0; s < HV_MATERIAL_TEXTURE_COUNT; ++s) {
      if (refs[s]->valid()) {
        t[s] = {textureFor(refs[s]->image, srgb[s]), samplerFor(refs[s]->sampler)};
      } else {
        t[s] = {white_.id(), default_sampler_.id()};
      }
    }
    material_textures_.push_back(t);
  }
}

void GpuScene::updateMaterials(const Scene& scene) {
  std::vector<std::byte> bytes(scene.materials.size() * material_stride_);
  for (size_t i = 0; i < scene.materials.size(); ++i) {
    const GpuMaterial g = packMaterial(scene.materials[i]);
    std::memcpy(bytes.data() + i * material_stride_, &g, sizeof g);
  }
  if (!bytes.empty())
    glNamedBufferSubData(materials_.id(), 0, GLsizeiptr(bytes.size()), bytes.data());
}

void GpuScene::updateLights(const Scene& scene) {
  lights_cpu_ = renderedLights(scene);
  const std::vector<Light>& lights = lights_cpu_;
  std::vector<GpuLight> packed;
  packed.reserve(lights.size());
  cull_spheres_.clear();
  directional_ = glm::uvec4(0u);
  int directional = 0;
  for (const Light& l : lights) {
    if (l.type == LightType::Directional && directional < int(kMaxDirectionalLights)) {
      directional_[directional++] = uint32_t(packed.size() + 1);
    }
    packed.push_back(packLight(l));
    cull_spheres_.push_back(glsl::lightCullSphere(toGlsl(packed.back())));
  }
  if (!lights_ || light_capacity_ < packed.size()) {
    light_capacity_ = std::max<size_t>(packed.size(), 1);
    lights_ = gl::createBuffer("lights", light_capacity_ * sizeof(GpuLight));
  }
  if (!packed.empty()) {
    glNamedBufferSubData(lights_.id(), 0, packed.size() * sizeof(GpuLight), packed.data());
  }
}

std::array<BoundTexture, HV_MATERIAL_TEXTURE_COUNT> GpuScene::materialTextures(int material) const {
  return material_textures_.at(material);
}

GLuint GpuScene::textureFor(int image, bool srgb) {
  auto key = std::make_pair(image, srgb);
  if (auto it = textures_.find(key); it != textures_.end()) return it->second.id();
  const ImageData& img = scene_->images.at(image);
  const int levels = gl::mipLevelsFor(img.width, img.height);
  gl::Texture t =
      gl::createTexture2D(img.name.empty() ? "image" : img.name, srgb ? GL_SRGB8_ALPHA8 : GL_RGBA8,
                          img.width, img.height, levels);
  glTextureSubImage2D(t.id(), 0, 0, 0, img.width, img.height, GL_RGBA, GL_UNSIGNED_BYTE,
                      img.rgba.data());
  glGenerateTextureMipmap(t.id());
  const GLuint id = t.id();
  textures_.emplace(key, std::move(t));
  return id;
}

GLuint GpuScene::samplerFor(const Sampler& s) {
  const uint32_t key = uint32_t(s.wrap_s) | uint32_t(s.wrap_t) << 4 | uint32_t(s.mag) << 8 |
                       uint32_t(s.min) << 12 | uint32_t(s.mipmaps) << 16;
  if (auto it = samplers_.find(key); it != samplers_.end()) return it->second.id();
  auto wrap = [](Wrap w) {
    switch (w) {
      case Wrap::ClampToEdge:
        return GL_CLAMP_TO_EDGE;
      case Wrap::MirroredRepeat:
        return GL_MIRRORED_REPEAT;
      default:
        return GL_REPEAT;
    }
  };
  gl::Sampler smp = gl::createSampler("material sampler");
  glSamplerParameteri(smp.id(), GL_TEXTURE_WRAP_S, wrap(s.wrap_s));
  glSamplerParameteri(smp.id(), GL_TEXTURE_WRAP_T, wrap(s.wrap_t));
  glSamplerParameteri(smp.id(), GL_TEXTURE_MAG_FILTER,
                      s.mag == Filter::Nearest ? GL_NEAREST : GL_LINEAR);
  GLenum min_filter;
  if (s.mipmaps) {
    min_filter = s.min == Filter::Nearest ? GL_NEAREST_MIPMAP_LINEAR : GL_LINEAR_MIPMAP_LINEAR;
  } else {
    min_filter = s.min == Filter::Nearest ? GL_NEAREST : GL_LINEAR;
  }
  glSamplerParameteri(smp.id(), GL_TEXTURE_MIN_FILTER, min_filter);
  const GLuint id = smp.id();
  samplers_.emplace(key, std::move(smp));
  return id;
}

}  // namespace hv::render
