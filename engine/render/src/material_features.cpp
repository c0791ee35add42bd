// The material features of the G-buffer programs (variant_key.hpp, MaterialFeatures): the
// feature table, and which features a material uses.
#include "halfvec/render/variant_key.hpp"

namespace hv::render {

const std::array<MaterialFeatureField, 13>& materialFeatureFields() {
  static const std::array<MaterialFeatureField, 13> fields = {{
      {"HV_MAT_BASE_COLOR_MAP", "base_color_map", &MaterialFeatures::base_color_map},
      {"HV_MAT_METAL_ROUGH_MAP", "metal_rough_map", &MaterialFeatures::metal_rough_map},
      {"HV_MAT_NORMAL_MAP", "normal_map", &MaterialFeatures::normal_map},
      {"HV_MAT_OCCLUSION_MAP", "occlusion_map", &MaterialFeatures::occlusion_map},
      {"HV_MAT_EMISSIVE", "emissive", &MaterialFeatures::emissive},
      {"HV_MAT_EMISSIVE_MAP", "emissive_map", &MaterialFeatures::emissive_map},
      {"HV_MAT_ALPHA_MASK", "alpha_mask", &MaterialFeatures::alpha_mask},
      {"HV_MAT_DOUBLE_SIDED", "double_sided", &MaterialFeatures::double_sided},
      {"HV_MAT_UV1", "uv1", &MaterialFeatures::uv1},
      {"HV_MAT_VERTEX_COLOR", "vertex_color", &MaterialFeatures::vertex_color},
      {"HV_MAT_TEX_TRANSFORM", "tex_transform", &MaterialFeatures::tex_transform},
      {"HV_MAT_CLEAR_COAT", "clear_coat", &MaterialFeatures::clear_coat},
      {"HV_MAT_CLEAR_COAT_MAPS", "clear_coat_maps", &MaterialFeatures::clear_coat_maps},
  }};
  return fields;
}

std::string MaterialFeatures::text() const {
  std::string t;
  for (const auto& f : materialFeatureFields()) {
    if (!(this->*f.member)) continue;
    if (!t.empty()) t += '+';
    t += f.name;
  }
  return t.empty() ? "none" : t;
}

MaterialFeatures materialFeatures(const Material& m, bool colored_mesh) {
  MaterialFeatures f;
  f.base_color_map = m.base_color_tex.valid();
  f.metal_rough_map = m.metallic_roughness_tex.valid();
  f.normal_map = m.normal_tex.valid();
  // cavity *= 1 + strength (ao - 1): strength 0 leaves it unchanged.
  f.occlusion_map = m.occlusion_tex.valid() && m.occlusion_tex.scale != 0.0f;
  f.emissive = m.emissive != glm::vec3(0.0f);
  // The map multiplies the constant: with a zero constant it changes nothing.
  f.emissive_map = f.emissive && m.emissive_tex.valid();
  f.alpha_mask = m.alpha_mode == AlphaMode::Mask;
  f.double_sided = m.double_sided;
  f.uv1 = (f.base_color_map && m.base_color_tex.texcoord == 1) ||
          (f.metal_rough_map && m.metallic_roughness_tex.texcoord == 1) ||
          (f.normal_map && m.normal_tex.texcoord == 1) ||
          (f.occlusion_map && m.occlusion_tex.texcoord == 1) ||
          (f.emissive_map && m.emissive_tex.texcoord == 1);
  f.vertex_color = colored_mesh && m.vertex_color;
  f.tex_transform = (f.base_color_map && m.base_color_tex.transformed()) ||
                    (f.metal_rough_map && m.metallic_roughness_tex.transformed()) ||
                    (f.normal_map && m.normal_tex.transformed()) ||
                    (f.occlusion_map && m.occlusion_tex.transformed()) ||
                    (f.emissive_map && m.emissive_tex.transformed());
  f.clear_coat = m.model == ShadingModel::ClearCoat;
  // The coat's textures count only on a coat (the G-buffer pass reads them there alone).
  const TextureRef* coat_maps[3] = {&m.clearcoat_tex, &m.clearcoat_roughness_tex,
                                    &m.clearcoat_normal_tex};
  for (const TextureRef* t : coat_maps) {
    if (!f.clear_coat || !t->valid()) continue;
    f.clear_coat_maps = true;
    f.uv1 |= t->texcoord == 1;
    f.tex_transform |= t->transformed();
  }
  return f;
}

MaterialFeatures allMaterialFeatures() {
  MaterialFeatures f;
  for (const auto& field : materialFeatureFields()) f.*field.member = true;
  return f;
}

}  // namespace hv::render
