#version 450 core
// Shadow-map pass: stores the distance from the light's center over its far distance (the
// culling radius), linear, so that every face and every filter compares distances (shadows.glsl).
// HV_SHADOW_ALPHA_MASK 1 (alpha-masked materials only): the texels whose base colour alpha is
// below the material's cutoff are discarded, as the G-buffer pass discards them (glTF 2.0
// 3.9.4, alphaMode MASK), so the caster's holes let the light through.
#include "../common/bindings.glsl"

#ifndef HV_SHADOW_ALPHA_MASK
#define HV_SHADOW_ALPHA_MASK 0
#endif

layout(location = HV_LOC_SHADOW_LIGHT) uniform vec4 u_light;  // xyz light center, w 1 / far

layout(location = 0) in vec3 v_world;

#if HV_SHADOW_ALPHA_MASK
#include "../common/material.glsl"
#include "../common/texture_transform.glsl"

layout(binding = HV_UNIT_MATERIAL_TEXTURES + 0) uniform sampler2D t_base_color;

layout(location = 1) in vec2 v_uv0;
layout(location = 2) in vec2 v_uv1;
layout(location = 3) in float v_alpha;  // the vertex colour's alpha

// The base colour's alpha as gbuffer.frag computes it: the factor, times the base colour
// texture's alpha (its UV set and KHR_texture_transform), times the vertex colour's.
float baseAlpha() {
  GpuMaterial m = u_material;
  float a = m.base_color.a;
  if ((m.texture_bits & HV_MAT_BASE_COLOR_TEX) != 0u) {
    vec2 uv = m.texcoord_base_color == 0u ? v_uv0 : v_uv1;
    if ((m.texture_bits & HV_MAT_TEX_TRANSFORM_BIT) != 0u) {
      uv = applyTextureTransform(uv, m.uv_linear[HV_MAT_SLOT_BASE_COLOR], m.uv_offset[HV_MAT_SLOT_BASE_COLOR].xy);
    }
    a *= texture(t_base_color, uv).a;
  }
  if ((m.texture_bits & HV_MAT_VERTEX_COLOR_BIT) != 0u) a *= v_alpha;
  return a;
}
#endif

void main() {
#if HV_SHADOW_ALPHA_MASK
  if (baseAlpha() < u_material.alpha_cutoff) discard;
#endif
#ifndef HV_SHADOW_ORTHO
  // A cube face: the distance from the light's center over far (a perspective depth would not
  // match across faces).
  gl_FragDepth = length(v_world - u_light.xyz) * u_light.w;
#endif
  // HV_SHADOW_ORTHO (a directional light's map): the rasterized depth, linear along the light.
}
