// The shadow mask (`settings.shadow_resolution: half`; docs/lights.md, "Shadows", "Half
// resolution"), in two steps of the shadow mask pass (engine/render/src/shadow_mask_pass.cpp):
// passes/shadow_mask.comp computes each shadowed light's visibility (shadows.glsl, the same lookup
// as the light pass's at full resolution) once per 2x2 pixels, at the pixel at the block's lower
// left, one layer of a 2D array per light; passes/shadow_resolve.comp upsamples it to every pixel
// from the four nearest texels with bilinear weights times a depth and a normal weight, so that
// neither a silhouette nor a crease takes the visibility of the surface across it, into a
// full-resolution array that the light pass reads with one fetch per pixel and shadowed light.
// GLSL only (the reference has no mask).
#ifndef HV_SHADOW_MASK_GLSL
#define HV_SHADOW_MASK_GLSL

#include "bindings.glsl"
#include "frame.glsl"
#include "gbuffer.glsl"
#include "half_res.glsl"
#include "lights.glsl"

// The mask layer of light l (-1: no map): the directional lights' sun layers first, then the
// cubes (bindings.glsl, HV_SHADOW_MASK_SUN_LAYERS).
int shadowMaskLayer(GpuLight l) {
  int slot = int(l.shadow_cube) - 1;
  bool sun = lightType(l) == HV_LIGHT_DIRECTIONAL;
  return slot < 0 ? -1 : (sun ? slot : HV_SHADOW_MASK_SUN_LAYERS + slot);
}

// A texel's depth weight is half_res.glsl's (0 at 5% from the pixel's distance, as the AO
// upsample's); its normal weight, dot(N_pixel, N_texel)^32: 0.61 at 10 degrees, 0.14 at 20,
// 0.01 at 30; across a crease (a box's edge) the other face drops out.

#if !defined(HV_CPP) && HV_SHADOWS
// The resolve step (HV_SHADOW_MASK_PASS 2): the half-resolution mask and its texels' geometry.
// The light pass: the resolved, full-resolution mask.
layout(binding = HV_UNIT_SHADOW_MASK) uniform sampler2DArray t_shadow_mask;
#if defined(HV_SHADOW_MASK_PASS)
// The shadow mask pass's two steps (HV_SHADOW_MASK_PASS 1: the half-resolution visibility,
// shadow_mask.comp; 2: the resolve, shadow_resolve.comp) read the G-buffer, the lights and the
// shadowed lights (indices into `lights`: one per dispatch layer in step 1, all of them in
// step 2).
layout(binding = HV_UNIT_MATERIAL) uniform sampler2D t_material;
layout(binding = HV_UNIT_NORMAL) uniform sampler2D t_normal;
layout(binding = HV_UNIT_DEPTH) uniform sampler2D t_depth;
layout(std430, binding = HV_BINDING_LIGHTS) readonly buffer LightBlock { GpuLight lights[]; };
layout(std430, binding = HV_BINDING_SHADOW_MASK_LIGHTS) readonly buffer MaskLightBlock {
  uint mask_lights[];
};

// The G-buffer at pixel p (inside the viewport): whether its surface is lit, its world position
// P, its normal N and the normal's octahedral code.
bool shadowMaskSurface(ivec2 p, out vec3 P, out vec3 N, out vec2 code) {
  uint model = decodeShadingModel(texelFetch(t_material, p, 0).b);
  code = texelFetch(t_normal, p, 0).xy;
  N = octDecode(code);
  vec2 uv = (vec2(p) + 0.5) / vec2(u_viewport.xy);
  P = reconstructWorldPosition(uv, texelFetch(t_depth, p, 0).r, u_inv_view_proj);
  return isLitModel(model);
}
#endif

#if defined(HV_SHADOW_MASK_PASS) && HV_SHADOW_MASK_PASS == 2
layout(binding = HV_UNIT_SHADOW_MASK_GEOMETRY) uniform sampler2D t_shadow_mask_geometry;

// The upsample of pixel px (world position P, normal N, the camera at C): the texel coordinate
// `uv` at which one textureGather reads the four nearest texels, and their weights (sum 1).
// Texel q holds pixel 2q, so pixel px sits at px / 2 in texel units. Returns false, weights 0,
// where no texel is within the tolerances (a sliver of surface between two others, the far side
// of a thin object): no texel holds that pixel's surface, and the resolve step looks the maps up
// for it itself (passes/shadow_resolve.comp).
bool shadowMaskWeights(ivec2 px, vec3 P, vec3 N, vec3 C, out vec2 uv, out vec4 w) {
  float inv_dist = 1.0 / max(length(P - C), 1e-30);
  vec4 wb;
  halfResFootprint(px, textureSize(t_shadow_mask_geometry, 0), uv, wb);
  vec4 inv = textureGather(t_shadow_mask_geometry, uv, 0);
  vec4 nx = textureGather(t_shadow_mask_geometry, uv, 1);
  vec4 ny = textureGather(t_shadow_mask_geometry, uv, 2);
  // A texel of no lit surface (w 0) never counts.
  vec4 diff = halfResDistanceDiff(inv, inv_dist);
  vec4 cosn;
  for (int k = 0; k < 4; ++k) cosn[k] = dot(N, octDecode(vec2(nx[k], ny[k])));
  // cos^32 by five squarings: no exp2 and log2 per texel.
  vec4 wn = clamp(cosn, 0.0, 1.0);
  for (int k = 0; k < 5; ++k) wn *= wn;
  w = wb * halfResDepthWeight(diff) * wn;
  w *= step(vec4(1e-30), inv);
  float wsum = w.x + w.y + w.z + w.w;
  bool found = wsum > 1e-4;
  w = found ? w / wsum : vec4(0.0);
  return found;
}

#elif !defined(HV_SHADOW_MASK_PASS)
// Visibility of light l at the invocation's pixels px[j] from the resolved mask (1: no map): a
// loop of one pass or none (shadows.glsl says why), so a light without a map reads nothing.
vec4 shadowMaskVisibility(GpuLight l, ivec2 px[HV_SHADOW_RECEIVERS]) {
  vec4 vis = vec4(1.0);
  int layer = shadowMaskLayer(l);
  int reads = layer >= 0 ? 1 : 0;
  for (int k = 0; k < reads; ++k) {
    for (int j = 0; j < HV_SHADOW_RECEIVERS; ++j) {
      vis[j] = texelFetch(t_shadow_mask, ivec3(px[j], layer), 0).r;
    }
  }
  return vis;
}
#endif
#endif

#endif
