// The material record the G-buffer pass reads (uniform block HV_UBO_MATERIAL).
// C++ mirror: halfvec/render/frame_data.hpp (GpuMaterial).
#ifndef HV_MATERIAL_GLSL
#define HV_MATERIAL_GLSL

#include "material_features.glsl"

#define HV_MAT_BASE_COLOR_TEX 1u
#define HV_MAT_METAL_ROUGH_TEX 2u
#define HV_MAT_NORMAL_TEX 4u
#define HV_MAT_OCCLUSION_TEX 8u
#define HV_MAT_EMISSIVE_TEX 16u
#define HV_MAT_VERTEX_COLOR_BIT 32u  // multiply base colour and alpha by the vertex colour
#define HV_MAT_TEX_TRANSFORM_BIT 64u  // some texture has a KHR_texture_transform
#define HV_ALPHA_OPAQUE 0u
#define HV_ALPHA_MASK 1u

struct GpuMaterial {
  vec4 base_color;  // linear rgb, alpha
  vec4 params;      // metallic, roughness, cavity, alpha cutoff
  vec4 emissive;    // linear rgb radiance, unused
  vec4 extra;       // normal scale, occlusion strength, emissive texcoord set, unused
  uvec4 texcoords;  // texcoord set of base color, metal-rough, normal, occlusion
  uvec4 flags;      // texture bits, alpha mode, shading-model ID, unused
  // KHR_texture_transform per texture (base color, metal-rough, normal, occlusion, emissive):
  // uv_linear[i] = textureTransformLinear (common/texture_transform.glsl), uv_offset[i].xy.
  vec4 uv_linear[5];
  vec4 uv_offset[5];
};

// The draw's material: GpuScene keeps every material in one buffer and the G-buffer pass binds the
// draw's range (glBindBufferRange), so the values are uniform across the draw. A storage buffer
// indexed by a material uniform was gathered per pixel on llvmpipe (docs/performance.md "The
// material as uniforms").
layout(std140, binding = HV_UBO_MATERIAL) uniform MaterialBlock {
  GpuMaterial u_material;
};

#endif
