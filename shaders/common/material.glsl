// Material records as the G-buffer pass reads them (binding HV_BINDING_MATERIALS).
// C++ mirror: halfvec/render/frame_data.hpp (GpuMaterial).
#ifndef HV_MATERIAL_GLSL
#define HV_MATERIAL_GLSL

#include "material_features.glsl"

#define HV_MAT_BASE_COLOR_TEX 1u
#define HV_MAT_METAL_ROUGH_TEX 2u
#define HV_MAT_NORMAL_TEX 4u
#define HV_MAT_OCCLUSION_TEX 8u
#define HV_MAT_EMISSIVE_TEX 16u
#define HV_ALPHA_OPAQUE 0u
#define HV_ALPHA_MASK 1u

struct GpuMaterial {
  vec4 base_color;  // linear rgb, alpha
  vec4 params;      // metallic, roughness, cavity, alpha cutoff
  vec4 emissive;    // linear rgb radiance, unused
  vec4 extra;       // normal scale, occlusion strength, emissive texcoord set, unused
  uvec4 texcoords;  // texcoord set of base color, metal-rough, normal, occlusion
  uvec4 flags;      // texture bits, alpha mode, shading-model ID, unused
};

layout(std430, binding = HV_BINDING_MATERIALS) readonly buffer MaterialBlock {
  GpuMaterial materials[];
};

#endif
