// The scene's GPU resources: one vertex/index buffer for all meshes, the materials in one uniform
// buffer (a range per material, bound per draw), the lights in a storage buffer, textures with
// their samplers. Rebuilt when the scene changes; materials and
// lights can be updated in place (the viewer's panels do).
#pragma once

#include <array>
#include <map>
#include <vector>

#include "halfvec/gl/objects.hpp"
#include "halfvec/shaders/common/bindings.glsl"
#include "halfvec/scene/scene.hpp"

namespace hv::render {

struct DrawItem {
  uint32_t first_index = 0;
  uint32_t index_count = 0;
  int32_t base_vertex = 0;
  int material = 0;
  int object = 0;
  bool double_sided = false;
  // The mesh's object-space bounding box: blended draws sort by its centre and list the lights
  // whose bounds it meets.
  glm::vec3 center{0.0f};
  glm::vec3 half_extent{0.0f};
};

struct BoundTexture {
  GLuint texture = 0;
  GLuint sampler = 0;
};

class GpuScene {
 public:
  explicit GpuScene(const Scene& scene);
  void updateMaterials(const Scene& scene);
  void updateLights(const Scene& scene);

  GLuint vertexArray() const { return vao_.id(); }
  // One GpuMaterial per material, material i at byte i * materialStride(): the G-buffer pass
  // binds that range as the draw's MaterialBlock (material.glsl), so the shader reads the
  // material as uniforms instead of gathering it from a storage buffer per pixel.
  GLuint materialBuffer() const { return materials_.id(); }
  // sizeof(GpuMaterial) rounded up to GL_UNIFORM_BUFFER_OFFSET_ALIGNMENT (256 on some drivers).
  size_t materialStride() const { return material_stride_; }
  GLuint lightBuffer() const { return lights_.id(); }
  size_t lightCount() const { return lights_cpu_.size(); }
  // The lights the buffer holds, in its order: renderedLights(scene) at the last updateLights
  // (the environment's sun last, where it is a light), so that the passes of every frame see the
  // list the GPU has without looking for the sun again.
  const std::vector<Light>& lights() const { return lights_cpu_; }
  // What the GPU buffer holds, per light: world-space bounding sphere of the culling (xyz center,
  // w lightCullRadius), for sizing the tile lists on the CPU (Renderer::cullLightsPass).
  const std::vector<glm::vec4>& lightCullSpheres() const { return cull_spheres_; }
  // FrameBlock::directional_lights: the directional lights' indices + 1, 0 after the last (the
  // loader allows at most kMaxDirectionalLights; further ones, from a scene built in code, are
  // not shaded).
  glm::uvec4 directionalLights() const { return directional_; }
  size_t triangleCount() const { return triangles_; }
  const std::vector<DrawItem>& draws() const { return draws_; }
  // Texture units 0..4 for a material: base color, metal-rough, normal, occlusion, emissive.
  std::array<BoundTexture, HV_MATERIAL_TEXTURE_COUNT> materialTextures(int material) const;

 private:
  GLuint textureFor(int image, bool srgb);
  GLuint samplerFor(const Sampler& s);

  const Scene* scene_ = nullptr;
  gl::Buffer vertices_, indices_, materials_, lights_;
  gl::VertexArray vao_;
  std::vector<DrawItem> draws_;
  size_t material_stride_ = 0;
  std::vector<Light> lights_cpu_;
  std::vector<glm::vec4> cull_spheres_;
  glm::uvec4 directional_{0u};
  size_t light_capacity_ = 0;
  size_t triangles_ = 0;
  std::map<std::pair<int, bool>, gl::Texture> textures_;
  std::map<uint32_t, gl::Sampler> samplers_;
  std::vector<std::array<BoundTexture, HV_MATERIAL_TEXTURE_COUNT>> material_textures_;
  gl::Texture white_;
  gl::Sampler default_sampler_;
};

}  // namespace hv::render
