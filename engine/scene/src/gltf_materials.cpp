// Materials: metal/rough factors and textures, emission (KHR_materials_emissive_strength), alpha
// modes, clear coat (KHR_materials_clearcoat's factors), KHR_materials_pbrSpecularGlossiness
// approximated, and the glTF default material.
#include "gltf_import.hpp"

#include <cmath>

namespace hv::gltf {

void Importer::importMaterial(int i) {
  const tinygltf::Material& g = m_.materials[size_t(i)];
  const std::string el = "materials[" + std::to_string(i) + "]";
  Material m;
  m.name = g.name.empty() ? el : g.name;
  metalRoughFactors(g, el, m);
  for (const auto& [name, value] : g.extensions) {
    if (name != "KHR_materials_pbrSpecularGlossiness") noteExtension(name, el + ".extensions");
  }
  noteExtensions(g.pbrMetallicRoughness.extensions, el + ".pbrMetallicRoughness");
  materialTextures(g, el, m);
  emission(g, el, m);
  m.double_sided = g.doubleSided;
  alphaMode(g, el, m);
  clearCoat(g, el, m);
  auto sg = g.extensions.find("KHR_materials_pbrSpecularGlossiness");
  if (sg != g.extensions.end() && sg->second.IsObject()) {
    specularGlossiness(sg->second, el, m);
  }
  m.base_color = glm::clamp(m.base_color, 0.0f, 1.0f);
  m.metallic = glm::clamp(m.metallic, 0.0f, 1.0f);
  m.roughness = glm::clamp(m.roughness, 0.0f, 1.0f);
  materials.push_back(m);
}

// baseColorFactor, metallicFactor and roughnessFactor (clamped by importMaterial).
void Importer::metalRoughFactors(const tinygltf::Material& g, const std::string& el,
                                 Material& m) const {
  const auto& pbr = g.pbrMetallicRoughness;
  if (pbr.baseColorFactor.size() == 4) {
    const std::string f = el + ".pbrMetallicRoughness.baseColorFactor";
    m.base_color = glm::vec3(finite(pbr.baseColorFactor[0], f), finite(pbr.baseColorFactor[1], f),
                             finite(pbr.baseColorFactor[2], f));
    m.base_alpha = finite(pbr.baseColorFactor[3], f);
  }
  m.metallic = finite(pbr.metallicFactor, el + ".pbrMetallicRoughness.metallicFactor");
  m.roughness = finite(pbr.roughnessFactor, el + ".pbrMetallicRoughness.roughnessFactor");
}

// The five textures of a metal/rough material, with the normal scale and occlusion strength.
void Importer::materialTextures(const tinygltf::Material& g, const std::string& el, Material& m) {
  const auto& pbr = g.pbrMetallicRoughness;
  m.base_color_tex = texture(pbr.baseColorTexture.index, pbr.baseColorTexture.texCoord,
                             pbr.baseColorTexture.extensions, el + ".baseColorTexture");
  m.metallic_roughness_tex =
      texture(pbr.metallicRoughnessTexture.index, pbr.metallicRoughnessTexture.texCoord,
              pbr.metallicRoughnessTexture.extensions, el + ".metallicRoughnessTexture");
  m.normal_tex = texture(g.normalTexture.index, g.normalTexture.texCoord,
                         g.normalTexture.extensions, el + ".normalTexture");
  m.normal_tex.scale = finite(g.normalTexture.scale, el + ".normalTexture.scale");
  m.occlusion_tex = texture(g.occlusionTexture.index, g.occlusionTexture.texCoord,
                            g.occlusionTexture.extensions, el + ".occlusionTexture");
  m.occlusion_tex.scale = finite(g.occlusionTexture.strength, el + ".occlusionTexture.strength");
  m.emissive_tex = texture(g.emissiveTexture.index, g.emissiveTexture.texCoord,
                           g.emissiveTexture.extensions, el + ".emissiveTexture");
}

// emissiveFactor, scaled by KHR_materials_emissive_strength's emissiveStrength.
void Importer::emission(const tinygltf::Material& g, const std::string& el, Material& m) const {
  if (g.emissiveFactor.size() == 3) {
    const std::string f = el + ".emissiveFactor";
    // glTF 2.0: each in [0, 1]; KHR_materials_emissive_strength scales it past 1.
    m.emissive =
        glm::clamp(glm::vec3(finite(g.emissiveFactor[0], f), finite(g.emissiveFactor[1], f),
                             finite(g.emissiveFactor[2], f)),
                   0.0f, 1.0f);
  }
  if (auto es = g.extensions.find("KHR_materials_emissive_strength"); es != g.extensions.end()) {
    const std::string xel = el + ".extensions.KHR_materials_emissive_strength";
    if (!es->second.IsObject()) fail(xel, "expected an object");
    if (es->second.Has("emissiveStrength")) {
      const float k = extNumber(es->second, "emissiveStrength", xel);
      if (k < 0.0f) fail(xel + ".emissiveStrength", "expected >= 0, got " + fmtFloat(k));
      m.emissive *= k;
      // The product stays a radiance the HDR target holds (frame.glsl clamps at HV_HDR_MAX).
      if (!std::isfinite(m.emissive.x + m.emissive.y + m.emissive.z)) {
        fail(xel + ".emissiveStrength", "emissive radiance overflows");
      }
    }
  }
}

// alphaMode MASK with its cutoff; BLEND: drawn by the forward pass of blended surfaces.
void Importer::alphaMode(const tinygltf::Material& g, const std::string& el, Material& m) const {
  if (g.alphaMode == "MASK") {
    m.alpha_mode = AlphaMode::Mask;
    m.alpha_cutoff = finite(g.alphaCutoff, el + ".alphaCutoff");
  } else if (g.alphaMode == "BLEND") {
    m.alpha_mode = AlphaMode::Blend;
  } else if (g.alphaMode != "OPAQUE" && !g.alphaMode.empty()) {
    fail(el + ".alphaMode", "unknown value \"" + g.alphaMode + "\"");
  }
}

// KHR_materials_pbrSpecularGlossiness, approximated: diffuse as base colour of a dielectric,
// roughness = 1 - glossiness; the specular colour and specularGlossinessTexture are not
// representable and dropped.
void Importer::specularGlossiness(const tinygltf::Value& v, const std::string& el, Material& m) {
  m.metallic = 0.0f;
  m.metallic_roughness_tex = {};
  m.base_color = glm::vec3(1.0f);
  m.base_alpha = 1.0f;
  m.base_color_tex = {};
  if (v.Has("diffuseFactor") && v.Get("diffuseFactor").ArrayLen() == 4) {
    const auto& f = v.Get("diffuseFactor");
    const std::string fe = el + ".diffuseFactor";
    m.base_color = glm::vec3(finite(f.Get(0).GetNumberAsDouble(), fe),
                             finite(f.Get(1).GetNumberAsDouble(), fe),
                             finite(f.Get(2).GetNumberAsDouble(), fe));
    m.base_alpha = finite(f.Get(3).GetNumberAsDouble(), fe);
  }
  m.roughness =
      1.0f - (v.Has("glossinessFactor")
                  ? finite(v.Get("glossinessFactor").GetNumberAsDouble(), el + ".glossinessFactor")
                  : 1.0f);
  if (v.Has("diffuseTexture")) {
    m.base_color_tex = textureInfo(v.Get("diffuseTexture"), el + ".diffuseTexture");
  }
  if (!warned_specgloss_) {
    warn(
        "KHR_materials_pbrSpecularGlossiness approximated as metal/rough (specular colour "
        "dropped)");
    warned_specgloss_ = true;
  }
}

// KHR_materials_clearcoat: clearcoatFactor and clearcoatRoughnessFactor (each 0..1, default 0),
// clearcoatTexture (R multiplies the weight), clearcoatRoughnessTexture (G multiplies the
// roughness) and clearcoatNormalTexture (the coat's normal map, with its scale); a factor above 0
// makes the material clear_coat (clear_coat.glsl). A blended material takes the factors alone.
void Importer::clearCoat(const tinygltf::Material& g, const std::string& el, Material& m) {
  auto cc = g.extensions.find("KHR_materials_clearcoat");
  if (cc == g.extensions.end()) return;
  const tinygltf::Value& v = cc->second;
  const std::string xel = el + ".extensions.KHR_materials_clearcoat";
  if (!v.IsObject()) fail(xel, "expected an object");
  auto factor = [&](const char* key) {
    if (!v.Has(key)) return 0.0f;
    const float f = extNumber(v, key, xel);
    if (f < 0.0f || f > 1.0f) fail(xel + "." + key, "expected 0..1, got " + fmtFloat(f));
    return f;
  };
  m.clearcoat = factor("clearcoatFactor");
  m.clearcoat_roughness = factor("clearcoatRoughnessFactor");
  auto info = [&](const char* key) {
    return v.Has(key) ? textureInfo(v.Get(key), xel + "." + key) : TextureRef{};
  };
  m.clearcoat_tex = info("clearcoatTexture");
  m.clearcoat_roughness_tex = info("clearcoatRoughnessTexture");
  m.clearcoat_normal_tex = info("clearcoatNormalTexture");
  const bool maps = m.clearcoat_tex.valid() || m.clearcoat_roughness_tex.valid() ||
                    m.clearcoat_normal_tex.valid();
  if (maps && g.alphaMode == "BLEND") {
    warnOnce("clearcoat blend", xel +
                                    ": the coat's textures are not applied on a blended "
                                    "surface (alphaMode BLEND); its factors are");
  }
  if (m.clearcoat > 0.0f && m.model == ShadingModel::DefaultLit) m.model = ShadingModel::ClearCoat;
}

int Importer::defaultMaterial() {
  if (opt_.material_override >= 0) return opt_.material_override;
  if (default_material_ < 0) {
    // glTF 2.0, 3.9.6: a primitive without a material uses every default of a material:
    // baseColorFactor 1, metallicFactor 1, roughnessFactor 1.
    Material m;
    m.name = "gltf default";
    m.base_color = glm::vec3(1.0f);
    m.metallic = 1.0f;
    m.roughness = 1.0f;
    materials.push_back(m);
    default_material_ = int(materials.size()) - 1;
  }
  return material_base_ + default_material_;
}

}  // namespace hv::gltf
