#include "halfvec/render/frame_data.hpp"

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "halfvec/shading/shading.hpp"

namespace hv::render {

GpuMaterial packMaterial(const Material& m) {
  GpuMaterial g{};
  g.base_color = glm::vec4(m.base_color, m.base_alpha);
  g.params = glm::vec4(m.metallic, m.roughness, m.cavity, m.alpha_cutoff);
  g.emissive = glm::vec4(m.emissive, 0.0f);
  g.extra = glm::vec4(m.normal_tex.scale, m.occlusion_tex.scale, float(m.emissive_tex.texcoord), 0);
  g.texcoords = glm::uvec4(m.base_color_tex.texcoord, m.metallic_roughness_tex.texcoord,
                           m.normal_tex.texcoord, m.occlusion_tex.texcoord);
  uint32_t bits = 0;
  if (m.base_color_tex.valid()) bits |= kBaseColorTex;
  if (m.metallic_roughness_tex.valid()) bits |= kMetalRoughTex;
  if (m.normal_tex.valid()) bits |= kNormalTex;
  if (m.occlusion_tex.valid()) bits |= kOcclusionTex;
  if (m.emissive_tex.valid()) bits |= kEmissiveTex;
  if (m.vertex_color) bits |= kVertexColor;
  const TextureRef* refs[5] = {&m.base_color_tex, &m.metallic_roughness_tex, &m.normal_tex,
                               &m.occlusion_tex, &m.emissive_tex};
  for (int i = 0; i < 5; ++i) {
    g.uv_linear[i] = glsl::textureTransformLinear(refs[i]->uv_scale, refs[i]->uv_rotation);
    g.uv_offset[i] = glm::vec4(refs[i]->uv_offset, 0.0f, 0.0f);
    if (refs[i]->valid() && refs[i]->transformed()) bits |= kTexTransform;
  }
  g.flags = glm::uvec4(bits, m.alpha_mode == AlphaMode::Mask ? 1u : 0u,
                       static_cast<uint32_t>(m.model), 0u);
  return g;
}

glm::mat4 reversedInfinitePerspective(float fov_y_rad, float aspect, float near_plane) {
  const float f = 1.0f / std::tan(fov_y_rad * 0.5f);
  glm::mat4 p(0.0f);
  p[0][0] = f / aspect;
  p[1][1] = f;
  p[2][3] = -1.0f;       // w_clip = -z_view
  p[3][2] = near_plane;  // z_clip = near  => depth = near / -z_view
  return p;
}

FrameBlock makeFrameBlock(const Scene& scene, int width, int height) {
  FrameBlock f{};
  const Camera& c = scene.camera;
  f.view = glm::lookAt(c.position, c.target, c.up);
  f.proj = reversedInfinitePerspective(glm::radians(c.fov_y_deg), float(width) / float(height),
                                       c.near_plane);
  f.view_proj = f.proj * f.view;
  f.inv_view_proj = glm::inverse(f.view_proj);
  f.camera_pos = glm::vec4(c.position, 1.0f);
  const uint32_t tx = (width + kTileSize - 1) / kTileSize;
  const uint32_t ty = (height + kTileHeight - 1) / kTileHeight;
  f.viewport = glm::uvec4(width, height, tx, ty);
  f.counts = glm::uvec4(static_cast<uint32_t>(scene.lights.size()), 0, 0, 0);
  f.output = glm::vec4(scene.settings.exposure, scene.settings.dither ? 1.0f : 0.0f,
                       scene.environment.intensity, glm::radians(scene.environment.rotation_deg));
  f.near_params = glm::vec4(c.near_plane, 0, 0, 0);
  return f;
}

}  // namespace hv::render
