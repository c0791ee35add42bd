#version 450 core
// G-buffer pass: writes the material attributes (layout in common/gbuffer.glsl) and the emissive
// radiance straight into the HDR accumulation target. Compiled per material variant: a feature
// switched off in common/material_features.glsl has no code here (docs/variants.md).
#include "../common/frame.glsl"
#include "../common/gbuffer.glsl"
#include "surface_material.glsl"

layout(location = 0) out vec4 o_base_cavity;  // SRGB8_ALPHA8
layout(location = 1) out vec4 o_material;     // RGBA8: metallic, roughness high, model, roughness low
layout(location = 2) out vec2 o_normal;       // RG16_SNORM
layout(location = 3) out vec4 o_hdr;          // RGBA16F
#if HV_MAT_CLEAR_COAT
layout(location = 4) out vec4 o_coat;  // RGBA16_SNORM (scenes with clear coat): encodeCoat
#endif

void main() {
  SurfaceMaterial sm = surfaceMaterial();
#if HV_MAT_ALPHA_MASK
  if (sm.masked_out) discard;  // only masked materials have a discard (docs/variants.md)
#endif
  o_base_cavity = vec4(clamp(sm.base.rgb, 0.0, 1.0), clamp(sm.cavity, 0.0, 1.0));
  vec2 roughness16 = encodeRoughness16(sm.roughness);
  o_material = vec4(clamp(sm.metallic, 0.0, 1.0), roughness16.x,
                    encodeShadingModel(u_material.shading_model), roughness16.y);
  o_normal = octEncode(sm.n);
#if HV_MAT_CLEAR_COAT
  o_coat = encodeCoat(sm.coat_n, sm.coat, sm.coat_roughness);
#endif
  // Clamped as every pass that writes the HDR target clamps (frame.glsl HV_HDR_MAX): without an
  // environment no ambient pass follows to clamp unlit pixels.
  o_hdr = vec4(min(sm.emissive, vec3(HV_HDR_MAX)), 0.0);
}
