// The material of the fragment being drawn: its textures, its varyings (gbuffer.vert) and the
// evaluation of base colour, alpha, metallic, roughness, cavity, shading normal and emissive.
// Included by the two fragment stages that draw scene geometry, so that a surface shades from the
// same values whether the G-buffer stores them (gbuffer.frag) or the forward pass of blended
// surfaces lights them at once (forward.frag). Compiled per material variant: a feature switched
// off in common/material_features.glsl has no code here (docs/variants.md).
#ifndef HV_SURFACE_MATERIAL_GLSL
#define HV_SURFACE_MATERIAL_GLSL

#include "../common/gbuffer.glsl"
#include "../common/material.glsl"
#include "../common/texture_transform.glsl"

layout(binding = HV_UNIT_MATERIAL_TEXTURES + 0) uniform sampler2D t_base_color;  // sRGB texture: sampled linear
layout(binding = HV_UNIT_MATERIAL_TEXTURES + 1) uniform sampler2D t_metal_rough;
layout(binding = HV_UNIT_MATERIAL_TEXTURES + 2) uniform sampler2D t_normal;
layout(binding = HV_UNIT_MATERIAL_TEXTURES + 3) uniform sampler2D t_occlusion;
layout(binding = HV_UNIT_MATERIAL_TEXTURES + 4) uniform sampler2D t_emissive;
#if HV_MAT_CLEAR_COAT_MAPS
layout(binding = HV_UNIT_MATERIAL_TEXTURES + 5) uniform sampler2D t_clearcoat;
layout(binding = HV_UNIT_MATERIAL_TEXTURES + 6) uniform sampler2D t_clearcoat_roughness;
layout(binding = HV_UNIT_MATERIAL_TEXTURES + 7) uniform sampler2D t_clearcoat_normal;
#endif

layout(location = 0) in vec3 v_normal;
#if HV_MAT_NORMAL_MAP || HV_MAT_CLEAR_COAT_MAPS
layout(location = 1) in vec4 v_tangent;
#endif
layout(location = 2) in vec2 v_uv0;
#if HV_MAT_UV1
layout(location = 3) in vec2 v_uv1;
#endif
#if HV_MAT_VERTEX_COLOR
layout(location = 4) in vec4 v_color;
#endif
layout(location = 5) in vec3 v_to_camera;

#if HV_MAT_UV1
vec2 uvSet(uint set) { return set == 0u ? v_uv0 : v_uv1; }
#else
vec2 uvSet(uint set) { return v_uv0; }
#endif

// Uber build: a compiled-in feature still tests the material's flag. Specialized: every material
// of the variant has the feature, so there is nothing to test.
#if HV_MAT_RUNTIME_FLAGS
#define HV_MAT_USES(bit) ((m.texture_bits & (bit)) != 0u)
#define HV_MAT_MASKED (m.alpha_mode == HV_ALPHA_MASK)
#else
#define HV_MAT_USES(bit) true
#define HV_MAT_MASKED true
#endif

// The UV of texture `slot` (0 base color .. 4 emissive, GpuMaterial's order) from set `set`,
// through its KHR_texture_transform when the material has one.
vec2 texUv(uint slot, uint set) {
  vec2 uv = uvSet(set);
#if HV_MAT_TEX_TRANSFORM
  GpuMaterial m = u_material;
  if (HV_MAT_USES(HV_MAT_TEX_TRANSFORM_BIT)) {
    uv = applyTextureTransform(uv, m.uv_linear[slot], m.uv_offset[slot].xy);
  }
#endif
  return uv;
}

#if HV_MAT_NORMAL_MAP || HV_MAT_CLEAR_COAT_MAPS
// A tangent-space normal map's normal (glTF 2.0 normalTexture: tn = 2 texel - 1, its xy times
// `scale`) about the interpolated normal n and the vertex tangent; n where the frame or the
// result degenerates.
vec3 mappedNormal(vec3 n, vec3 texel, float scale) {
  vec3 t = v_tangent.xyz - n * dot(n, v_tangent.xyz);
  float tl = length(t);
  if (tl > 1e-8) {
    t /= tl;
    vec3 b = cross(n, t) * (v_tangent.w < 0.0 ? -1.0 : 1.0);
    vec3 tn = texel * 2.0 - 1.0;
    tn.xy *= scale;
    vec3 mapped = t * tn.x + b * tn.y + n * tn.z;
    float ml = length(mapped);
    if (ml > 1e-8) n = mapped / ml;
  }
  return n;
}
#endif

struct SurfaceMaterial {
  vec4 base;  // linear base colour, alpha (coverage)
  float metallic;
  float roughness;  // perceptual
  float cavity;
  vec3 n;  // shading normal (world space, unit)
  vec3 emissive;
  bool masked_out;  // alpha-masked out (glTF alphaCutoff)
  // Clear coat (clear_coat.glsl): weight (0 off clear_coat materials), perceptual roughness and
  // the coat's normal: the interpolated vertex normal, which the base's normal map does not
  // perturb (a varnish over a bumpy surface is smooth: Filament section 4.9, KHR_materials_
  // clearcoat's default clearcoatNormal).
  float coat;
  float coat_roughness;
  vec3 coat_n;
};

SurfaceMaterial surfaceMaterial() {
  GpuMaterial m = u_material;
  SurfaceMaterial sm;
  vec4 base = m.base_color;
#if HV_MAT_BASE_COLOR_MAP
  if (HV_MAT_USES(HV_MAT_BASE_COLOR_TEX)) {
    base *= texture(t_base_color, texUv(HV_MAT_SLOT_BASE_COLOR, m.texcoord_base_color));
  }
#endif
#if HV_MAT_VERTEX_COLOR
  if (HV_MAT_USES(HV_MAT_VERTEX_COLOR_BIT)) base *= v_color;  // glTF 2.0 3.9.2: COLOR_0 multiplies
#endif
  sm.base = base;
  sm.masked_out = false;
#if HV_MAT_ALPHA_MASK
  sm.masked_out = HV_MAT_MASKED && base.a < m.alpha_cutoff;
#endif

  float metallic = m.metallic;
  float roughness = m.roughness;
#if HV_MAT_METAL_ROUGH_MAP
  if (HV_MAT_USES(HV_MAT_METAL_ROUGH_TEX)) {
    vec4 mr = texture(t_metal_rough, texUv(HV_MAT_SLOT_METAL_ROUGH, m.texcoord_metal_rough));
    metallic *= mr.b;   // glTF: B = metallic
    roughness *= mr.g;  //       G = roughness
  }
#endif
  sm.metallic = metallic;
  sm.roughness = roughness;
  float cavity = m.cavity;
#if HV_MAT_OCCLUSION_MAP
  if (HV_MAT_USES(HV_MAT_OCCLUSION_TEX)) {
    float ao = texture(t_occlusion, texUv(HV_MAT_SLOT_OCCLUSION, m.texcoord_occlusion)).r;
    cavity *= 1.0 + m.occlusion_strength * (ao - 1.0);  // glTF occlusion strength
  }
#endif
  sm.cavity = cavity;

  vec3 n = normalize(v_normal);
#if HV_MAT_DOUBLE_SIDED
  if (!gl_FrontFacing) n = -n;  // double-sided surfaces light their back face
#endif
  sm.coat_n = n;
#if HV_MAT_CLEAR_COAT
  sm.coat = m.shading_model == HV_MODEL_CLEAR_COAT ? m.clearcoat : 0.0;
  sm.coat_roughness = m.clearcoat_roughness;
#if HV_MAT_CLEAR_COAT_MAPS
  // KHR_materials_clearcoat's textures, each tested at run time even when specialized (one
  // feature covers the three: a missing normal map must not be read as white).
  uint coat_sets = m.texcoord_coat;
  if ((m.texture_bits & HV_MAT_CLEARCOAT_TEX) != 0u) {
    sm.coat *= texture(t_clearcoat, texUv(HV_MAT_SLOT_CLEARCOAT, coat_sets & 1u)).r;
  }
  if ((m.texture_bits & HV_MAT_CLEARCOAT_ROUGHNESS_TEX) != 0u) {
    sm.coat_roughness *=
        texture(t_clearcoat_roughness, texUv(HV_MAT_SLOT_CLEARCOAT_ROUGHNESS, (coat_sets >> 1u) & 1u)).g;
  }
  if ((m.texture_bits & HV_MAT_CLEARCOAT_NORMAL_TEX) != 0u) {
    vec3 texel = texture(t_clearcoat_normal, texUv(HV_MAT_SLOT_CLEARCOAT_NORMAL, (coat_sets >> 2u) & 1u)).xyz;
    sm.coat_n = mappedNormal(sm.coat_n, texel, m.clearcoat_normal_scale);
  }
#endif
#else
  sm.coat = 0.0;
  sm.coat_roughness = 0.0;
#endif
#if HV_MAT_NORMAL_MAP
  if (HV_MAT_USES(HV_MAT_NORMAL_TEX)) {
    n = mappedNormal(n, texture(t_normal, texUv(HV_MAT_SLOT_NORMAL, m.texcoord_normal)).xyz,
                     m.normal_scale);  // glTF normalTexture.scale
  }
#endif
  // Lit as facing the viewer wherever the normal map or the interpolation turned it away
  // (viewFacingNormal, gbuffer.glsl), the coat's normal too.
  vec3 V = normalize(v_to_camera);
  sm.n = viewFacingNormal(n, V);
  sm.coat_n = viewFacingNormal(sm.coat_n, V);

#if HV_MAT_EMISSIVE
  vec3 emissive = m.emissive;
#if HV_MAT_EMISSIVE_MAP
  if (HV_MAT_USES(HV_MAT_EMISSIVE_TEX)) {
    emissive *= texture(t_emissive, texUv(HV_MAT_SLOT_EMISSIVE, m.texcoord_emissive)).rgb;
  }
#endif
#else
  vec3 emissive = vec3(0.0);
#endif
  sm.emissive = emissive;
  return sm;
}

#endif
