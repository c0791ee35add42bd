#include "halfvec/render/frame_data.hpp"

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "halfvec/shading/shading.hpp"

namespace hv::render {

static_assert(uint32_t(ShadingModel::Background) == glsl::HV_MODEL_BACKGROUND &&
                  uint32_t(ShadingModel::Unlit) == glsl::HV_MODEL_UNLIT &&
                  uint32_t(ShadingModel::DefaultLit) == glsl::HV_MODEL_DEFAULT_LIT &&
                  uint32_t(ShadingModel::ClearCoat) == glsl::HV_MODEL_CLEAR_COAT,
              "GpuMaterial::shading_model holds hv::ShadingModel (gbuffer.glsl's HV_MODEL_*)");

std::array<const TextureRef*, HV_MAT_SLOTS> materialTextureSlots(const Material& m) {
  return {&m.base_color_tex,          &m.metallic_roughness_tex, &m.normal_tex,
          &m.occlusion_tex,           &m.emissive_tex,           &m.clearcoat_tex,
          &m.clearcoat_roughness_tex, &m.clearcoat_normal_tex};
}

GpuMaterial packMaterial(const Material& m) {
  GpuMaterial g{};
  g.base_color = glm::vec4(m.base_color, m.base_alpha);
  g.metallic = m.metallic;
  g.roughness = m.roughness;
  g.cavity = m.cavity;
  g.alpha_cutoff = m.alpha_cutoff;
  g.emissive = m.emissive;
  g.normal_scale = m.normal_tex.scale;
  g.occlusion_strength = m.occlusion_tex.scale;
  g.alpha_mode = m.alpha_mode == AlphaMode::Mask    ? HV_ALPHA_MASK
                 : m.alpha_mode == AlphaMode::Blend ? HV_ALPHA_BLEND
                                                    : HV_ALPHA_OPAQUE;
  g.shading_model = static_cast<uint32_t>(m.model);
  g.clearcoat = m.model == ShadingModel::ClearCoat ? m.clearcoat : 0.0f;
  g.clearcoat_roughness = m.clearcoat_roughness;
  g.texcoord_base_color = static_cast<uint32_t>(m.base_color_tex.texcoord);
  g.texcoord_metal_rough = static_cast<uint32_t>(m.metallic_roughness_tex.texcoord);
  g.texcoord_normal = static_cast<uint32_t>(m.normal_tex.texcoord);
  g.texcoord_occlusion = static_cast<uint32_t>(m.occlusion_tex.texcoord);
  g.texcoord_emissive = static_cast<uint32_t>(m.emissive_tex.texcoord);
  const auto refs = materialTextureSlots(m);
  const uint32_t tex_bits[HV_MAT_SLOTS] = {
      HV_MAT_BASE_COLOR_TEX,          HV_MAT_METAL_ROUGH_TEX,     HV_MAT_NORMAL_TEX,
      HV_MAT_OCCLUSION_TEX,           HV_MAT_EMISSIVE_TEX,        HV_MAT_CLEARCOAT_TEX,
      HV_MAT_CLEARCOAT_ROUGHNESS_TEX, HV_MAT_CLEARCOAT_NORMAL_TEX};
  uint32_t bits = m.vertex_color ? HV_MAT_VERTEX_COLOR_BIT : 0u;
  for (uint32_t k = 0; k < 3; ++k) {
    if (refs[HV_MAT_SLOT_CLEARCOAT + k]->texcoord == 1) g.texcoord_coat |= 1u << k;
  }
  g.clearcoat_normal_scale = m.clearcoat_normal_tex.scale;
  for (int i = 0; i < HV_MAT_SLOTS; ++i) {
    if (refs[i]->valid()) bits |= tex_bits[i];
    g.uv_linear[i] = glsl::textureTransformLinear(refs[i]->uv_scale, refs[i]->uv_rotation);
    g.uv_offset[i] = glm::vec4(refs[i]->uv_offset, 0.0f, 0.0f);
    if (refs[i]->valid() && refs[i]->transformed()) bits |= HV_MAT_TEX_TRANSFORM_BIT;
  }
  g.texture_bits = bits;
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
  // The scene's lights; the renderer sets the count of the lights it uploaded
  // (GpuScene::lightCount: the environment's sun last, where it is a light).
  f.light_count = static_cast<uint32_t>(scene.lights.size());
  f.output = glm::vec4(scene.settings.exposure, scene.settings.dither ? 1.0f : 0.0f,
                       scene.environment.intensity, glm::radians(scene.environment.rotation_deg));
  f.frame_params = glm::vec4(c.near_plane, scene.settings.max_error, scene.settings.ao_radius, 0);
  return f;
}

}  // namespace hv::render
