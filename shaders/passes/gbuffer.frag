#version 450 core
// G-buffer pass: writes the material attributes (layout in common/gbuffer.glsl) and the emissive
// radiance straight into the HDR accumulation target.
#include "../common/frame.glsl"
#include "../common/gbuffer.glsl"
#include "../common/material.glsl"

layout(location = 2) uniform int u_material;

layout(binding = 0) uniform sampler2D t_base_color;  // sRGB texture: sampled linear
layout(binding = 1) uniform sampler2D t_metal_rough;
layout(binding = 2) uniform sampler2D t_normal;
layout(binding = 3) uniform sampler2D t_occlusion;
layout(binding = 4) uniform sampler2D t_emissive;

layout(location = 0) in vec3 v_normal;
layout(location = 1) in vec4 v_tangent;
layout(location = 2) in vec2 v_uv0;
layout(location = 3) in vec2 v_uv1;

layout(location = 0) out vec4 o_base_cavity;  // SRGB8_ALPHA8
layout(location = 1) out vec4 o_material;     // RGBA8
layout(location = 2) out vec2 o_normal;       // RG16_SNORM
layout(location = 3) out vec4 o_hdr;          // RGBA16F

vec2 uvSet(uint set) { return set == 0u ? v_uv0 : v_uv1; }

void main() {
  GpuMaterial m = materials[u_material];
  uint flags = m.flags.x;
  vec4 base = m.base_color;
  if ((flags & HV_MAT_BASE_COLOR_TEX) != 0u) base *= texture(t_base_color, uvSet(m.texcoords.x));
  if (m.flags.y == HV_ALPHA_MASK && base.a < m.params.w) discard;

  float metallic = m.params.x;
  float roughness = m.params.y;
  if ((flags & HV_MAT_METAL_ROUGH_TEX) != 0u) {
    vec4 mr = texture(t_metal_rough, uvSet(m.texcoords.y));
    metallic *= mr.b;   // glTF: B = metallic
    roughness *= mr.g;  //       G = roughness
  }
  float cavity = m.params.z;
  if ((flags & HV_MAT_OCCLUSION_TEX) != 0u) {
    float ao = texture(t_occlusion, uvSet(m.texcoords.w)).r;
    cavity *= 1.0 + m.extra.y * (ao - 1.0);  // glTF occlusion strength
  }

  vec3 n = normalize(v_normal);
  if (!gl_FrontFacing) n = -n;  // double-sided surfaces light their back face
  if ((flags & HV_MAT_NORMAL_TEX) != 0u) {
    vec3 t = v_tangent.xyz - n * dot(n, v_tangent.xyz);
    float tl = length(t);
    if (tl > 1e-8) {
      t /= tl;
      vec3 b = cross(n, t) * (v_tangent.w < 0.0 ? -1.0 : 1.0);
      vec3 tn = texture(t_normal, uvSet(m.texcoords.z)).xyz * 2.0 - 1.0;
      tn.xy *= m.extra.x;  // glTF normalTexture.scale
      vec3 mapped = t * tn.x + b * tn.y + n * tn.z;
      float ml = length(mapped);
      if (ml > 1e-8) n = mapped / ml;
    }
  }

  vec3 emissive = m.emissive.rgb;
  if ((flags & HV_MAT_EMISSIVE_TEX) != 0u) emissive *= texture(t_emissive, uvSet(m.extra.z > 0.5 ? 1u : 0u)).rgb;

  o_base_cavity = vec4(clamp(base.rgb, 0.0, 1.0), clamp(cavity, 0.0, 1.0));
  o_material = vec4(clamp(metallic, 0.0, 1.0), clamp(roughness, 0.0, 1.0), float(m.flags.z) / 255.0, 0.0);
  o_normal = octEncode(n);
  o_hdr = vec4(emissive, 0.0);
}
