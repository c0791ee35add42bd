// The records the C++ uploads and the shaders read, declared once for both languages
// (zeux/niagara's src/shaders/mesh.h does the same): GLSL includes this file, C++ includes it via
// halfvec/shading/gpu_records.hpp, which checks every size and offset with static_asserts. Rules
// of a shared header: halfvec/shading/glsl.hpp. Plain structs only (no functions), so the C++ side
// can hold them outside the shading headers' anonymous namespace: hv::GpuLight, hv::GpuMaterial.
//
// Layout rules: every member is placed so that std140 and std430 give the same offsets as a C++
// struct of glm types (a vec4 or a uvec4 on a 16-byte boundary; a vec3 on a 16-byte boundary with a
// 4-byte scalar after it in the same 16 bytes; scalars on 4 bytes; arrays of vec4 only, whose
// stride is 16 in both rules). Each struct's size is a multiple of 16, so an array of it has the
// same stride in C++, std140 and std430.
#ifndef HV_GPU_RECORDS_GLSL
#define HV_GPU_RECORDS_GLSL

// ---- Lights -------------------------------------------------------------------------------------
// Light type codes stored in GpuLight.type; = hv::LightType for the first three.
#define HV_LIGHT_POINT 0
#define HV_LIGHT_SPHERE 1
#define HV_LIGHT_TUBE 2
// hv::LightType::Directional. Not culled per tile (the culling bins types 0-2 only): the light
// pass and the forward pass loop over the frame's directional lights (frame_block.glsl,
// directional_lights) at every pixel. position_radius holds the unit direction toward the light
// and the sine of the disk's angular radius; color_inv_range the color times the illuminance E,
// w 0 (no range).
#define HV_LIGHT_DIRECTIONAL 3
// A spot (hv::LightType::Spot) is a point or sphere light times its cone: its type is
// HV_LIGHT_POINT or HV_LIGHT_SPHERE with this bit set (so that the culling sorts it with its shape
// and the light pass shades it in that shape's loop), and axis_length holds its cone (spotCone,
// spot.glsl) instead of an axis and a length.
#define HV_LIGHT_SPOT_FLAG 4u
#define HV_LIGHT_TYPE_MASK 3u

// One light as the GPU reads it: std430 storage buffer HV_BINDING_LIGHTS, or 4 RGBA32UI texels of
// a buffer texture (light_shade.comp, HV_LIGHTS_TEXTURE, which reinterprets the float fields with
// uintBitsToFloat), 64 bytes. Points and spheres read only the first two vec4 in the light pass,
// tubes and spots three, which is why the first fields are vec4 texels. Offsets in bytes on the
// right.
struct GpuLight {
  vec4 position_radius;  //  0 x,y,z world position (tube: segment center), w sphere/capsule
                         //    radius (m)
  vec4 color_inv_range;  // 16 rgb linear color premultiplied by intensity I (W/sr), w 1/R (Karis
                         //    eq. 9 window)
  vec4 axis_length;      // 32 x,y,z unit tube axis, w tube segment length (m); 0 for point and
                         //    sphere; a spot's cone (spotCone, spot.glsl)
  float range;           // 48 range R (Karis eq. 9 window)
  uint type;             // 52 HV_LIGHT_* (| HV_LIGHT_SPOT_FLAG); read through lightType
                         //    (lights.glsl)
  float cull_radius;     // 56 culling radius; read through lightCullRadius (lights.glsl)
  uint shadow_cube;      // 60 the light's cube in the shadow atlas + 1 (0: no shadow map), written
                         //    by the shadow pass (engine/render/src/shadow_pass.cpp)
};

// One directional light's shadow map as the lookup reads it (shadows.glsl, sunShadowVisibility):
// an orthographic map along the light's travel direction over the casters' bounds, layer
// shadow_cube - 1 of the sun map array (engine/render/src/shadow_pass.cpp). A point P maps to
// uv = (dot(P - origin, right), dot(P - origin, up)) / extent + 0.5 and depth dot(P - origin,
// forward) / range; std140 uniform block HV_UBO_SUN_SHADOWS, kMaxDirectionalLights of them, 64
// bytes each. Offsets in bytes on the right.
struct GpuSunShadow {
  vec4 origin_inv_range;  //  0 xyz the map's center on its near plane, w 1 / range (m)
  vec4 right_inv_extent;  // 16 xyz unit across the light, w 1 / extent (the square's side, m)
  vec4 up_texel;          // 32 xyz unit across the light, w one texel's side (m)
  vec4 forward_tan;       // 48 xyz unit, the light's travel direction, w tan(angular radius)
};

// ---- Materials ----------------------------------------------------------------------------------
// GpuMaterial::texture_bits
#define HV_MAT_BASE_COLOR_TEX 1u
#define HV_MAT_METAL_ROUGH_TEX 2u
#define HV_MAT_NORMAL_TEX 4u
#define HV_MAT_OCCLUSION_TEX 8u
#define HV_MAT_EMISSIVE_TEX 16u
#define HV_MAT_VERTEX_COLOR_BIT 32u   // multiply base colour and alpha by the vertex colour
#define HV_MAT_TEX_TRANSFORM_BIT 64u  // some texture has a KHR_texture_transform
#define HV_MAT_CLEARCOAT_TEX 128u            // KHR_materials_clearcoat's textures
#define HV_MAT_CLEARCOAT_ROUGHNESS_TEX 256u
#define HV_MAT_CLEARCOAT_NORMAL_TEX 512u
// GpuMaterial::alpha_mode
#define HV_ALPHA_OPAQUE 0u
#define HV_ALPHA_MASK 1u
#define HV_ALPHA_BLEND 2u  // drawn by the forward pass (forward.frag), not into the G-buffer
// Texture slots: the index of uv_linear / uv_offset and of the texture unit after
// HV_UNIT_MATERIAL_TEXTURES (bindings.glsl).
#define HV_MAT_SLOT_BASE_COLOR 0u
#define HV_MAT_SLOT_METAL_ROUGH 1u
#define HV_MAT_SLOT_NORMAL 2u
#define HV_MAT_SLOT_OCCLUSION 3u
#define HV_MAT_SLOT_EMISSIVE 4u
#define HV_MAT_SLOT_CLEARCOAT 5u
#define HV_MAT_SLOT_CLEARCOAT_ROUGHNESS 6u
#define HV_MAT_SLOT_CLEARCOAT_NORMAL 7u
#define HV_MAT_SLOTS 8

// One material as the G-buffer pass reads it: std140 uniform block HV_UBO_MATERIAL
// (material.glsl), 368 bytes; GpuScene keeps every material in one buffer, one per
// GL_UNIFORM_BUFFER_OFFSET_ALIGNMENT stride. Offsets in bytes on the right.
struct GpuMaterial {
  vec4 base_color;             //   0 linear rgb, alpha
  float metallic;              //  16
  float roughness;             //  20 perceptual
  float cavity;                //  24
  float alpha_cutoff;          //  28 glTF alphaCutoff (alpha_mode HV_ALPHA_MASK)
  vec3 emissive;               //  32 linear rgb radiance
  float normal_scale;          //  44 glTF normalTexture.scale
  float occlusion_strength;    //  48 glTF occlusionTexture.strength
  uint texture_bits;           //  52 HV_MAT_* bits
  uint alpha_mode;             //  56 HV_ALPHA_*
  uint shading_model;          //  60 HV_MODEL_* (gbuffer.glsl) = hv::ShadingModel
  uint texcoord_base_color;    //  64 the UV set each texture reads (0 or 1)
  uint texcoord_metal_rough;   //  68
  uint texcoord_normal;        //  72
  uint texcoord_occlusion;     //  76
  uint texcoord_emissive;      //  80
  float clearcoat;             //  84 KHR_materials_clearcoat layer weight (shading_model 3)
  float clearcoat_roughness;   //  88 the coat's perceptual roughness
  uint texcoord_coat;          //  92 bit k: slot HV_MAT_SLOT_CLEARCOAT + k reads UV set 1
  // KHR_texture_transform per slot (HV_MAT_SLOT_*): uv_linear[i] = textureTransformLinear
  // (texture_transform.glsl), uv_offset[i].xy the offset.
  vec4 uv_linear[HV_MAT_SLOTS];  //  96
  vec4 uv_offset[HV_MAT_SLOTS];  // 224
  float clearcoat_normal_scale;  // 352 clearcoatNormalTexture.scale
  float unused3;                 // 356
  float unused4;                 // 360
  float unused5;                 // 364
};

#endif
