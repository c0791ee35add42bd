#version 450 core
// Shadow mask pass (`settings.shadow_resolution: half`; shadow_mask.glsl): the visibility of one
// shadowed light per dispatch layer (z) at one pixel per 2x2 block, its lower left, written to
// that light's layer of the mask (shadowMaskLayer); the first layer's dispatch also writes each
// texel's inverse view distance and G-buffer normal, which the resolve step's upsample weighs
// (shadow_resolve.comp). The
// lookup is the light pass's own (shadows.glsl, shadowVisibility and sunShadowVisibility), so
// at a texel's pixel the mask holds what the full-resolution pass computes there.
#define HV_SHADOW_MASK_PASS 1
#include "../common/frame.glsl"
#include "../common/gbuffer.glsl"
#include "../common/lights.glsl"
#include "../common/shadow_mask.glsl"

// An invocation computes HV_SHADOW_RECEIVERS texels of a column, as the light pass does pixels.
layout(local_size_x = 8, local_size_y = 8) in;

layout(r8, binding = HV_IMAGE_SHADOW_MASK) uniform writeonly image2DArray i_mask;
layout(rgba16f, binding = HV_IMAGE_SHADOW_MASK_GEOMETRY) uniform writeonly image2D i_geometry;

void main() {
  ivec2 size = imageSize(i_geometry);
  GpuLight l = lights[mask_lights[gl_WorkGroupID.z]];
  vec3 P[HV_SHADOW_RECEIVERS];
  vec3 N[HV_SHADOW_RECEIVERS];
  bvec4 use = bvec4(false);
  ivec2 q[HV_SHADOW_RECEIVERS];
  vec4 geometry[HV_SHADOW_RECEIVERS];
  for (int j = 0; j < HV_SHADOW_RECEIVERS; ++j) {
    q[j] = ivec2(gl_GlobalInvocationID.x, gl_GlobalInvocationID.y * HV_SHADOW_RECEIVERS + j);
    vec2 code;
    bool lit = shadowMaskSurface(min(q[j] * 2, ivec2(u_viewport.xy) - 1), P[j], N[j], code);
    use[j] = q[j].x < size.x && q[j].y < size.y && lit;
    float inv_dist = 1.0 / max(length(P[j] - u_camera_pos.xyz), 1e-30);
    geometry[j] = vec4(use[j] ? inv_dist : 0.0, code, 0.0);
  }
  vec4 vis = anyLightShadow(l, P, N, use);
  int layer = shadowMaskLayer(l);
  for (int j = 0; j < HV_SHADOW_RECEIVERS; ++j) {
    if (q[j].x >= size.x || q[j].y >= size.y) continue;
    imageStore(i_mask, ivec3(q[j], layer), vec4(vis[j]));
    if (gl_WorkGroupID.z == 0u) imageStore(i_geometry, q[j], geometry[j]);
  }
}
