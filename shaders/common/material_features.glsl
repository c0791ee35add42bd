// Material feature switches of the G-buffer program (docs/variants.md), set per material variant
// by engine/render/src/variant_key.cpp. A feature at 0 compiles no code for it. The defaults (every
// feature in, flags read at run time) are the uber build.
//   HV_MAT_RUNTIME_FLAGS 1|0: 1 = test each material's flags at run time (uber); 0 = every
//     material drawn with the program has exactly the features switched on (no tests).
//   HV_MAT_BASE_COLOR_MAP, HV_MAT_METAL_ROUGH_MAP, HV_MAT_NORMAL_MAP, HV_MAT_OCCLUSION_MAP,
//   HV_MAT_EMISSIVE, HV_MAT_EMISSIVE_MAP, HV_MAT_ALPHA_MASK, HV_MAT_DOUBLE_SIDED, HV_MAT_UV1,
//   HV_MAT_VERTEX_COLOR (COLOR_0 multiplies base colour and alpha), HV_MAT_TEX_TRANSFORM
//   (KHR_texture_transform), HV_MAT_CLEAR_COAT (shading model clear_coat: the coat's weight,
//   roughness and normal, written to the G-buffer's coat target) 1|0.
#ifndef HV_MATERIAL_FEATURES_GLSL
#define HV_MATERIAL_FEATURES_GLSL

#ifndef HV_MAT_RUNTIME_FLAGS
#define HV_MAT_RUNTIME_FLAGS 1
#endif
#ifndef HV_MAT_BASE_COLOR_MAP
#define HV_MAT_BASE_COLOR_MAP 1
#endif
#ifndef HV_MAT_METAL_ROUGH_MAP
#define HV_MAT_METAL_ROUGH_MAP 1
#endif
#ifndef HV_MAT_NORMAL_MAP
#define HV_MAT_NORMAL_MAP 1
#endif
#ifndef HV_MAT_OCCLUSION_MAP
#define HV_MAT_OCCLUSION_MAP 1
#endif
#ifndef HV_MAT_EMISSIVE
#define HV_MAT_EMISSIVE 1
#endif
#ifndef HV_MAT_EMISSIVE_MAP
#define HV_MAT_EMISSIVE_MAP 1
#endif
#ifndef HV_MAT_ALPHA_MASK
#define HV_MAT_ALPHA_MASK 1
#endif
#ifndef HV_MAT_DOUBLE_SIDED
#define HV_MAT_DOUBLE_SIDED 1
#endif
#ifndef HV_MAT_UV1
#define HV_MAT_UV1 1
#endif
#ifndef HV_MAT_VERTEX_COLOR
#define HV_MAT_VERTEX_COLOR 1
#endif
#ifndef HV_MAT_TEX_TRANSFORM
#define HV_MAT_TEX_TRANSFORM 1
#endif
#ifndef HV_MAT_CLEAR_COAT
#define HV_MAT_CLEAR_COAT 1
#endif
#ifndef HV_MAT_CLEAR_COAT_MAPS
#define HV_MAT_CLEAR_COAT_MAPS 1
#endif

#endif
