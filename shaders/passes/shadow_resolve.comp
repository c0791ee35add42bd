#version 450 core
// Shadow mask pass, second step (`settings.shadow_resolution: half`; shadow_mask.glsl): every
// pixel's visibility of each shadowed light, upsampled from the half-resolution mask
// (shadow_mask.comp) by the weights of shadowMaskWeights, computed once per pixel for every light,
// into that light's layer of a full-resolution array the light pass reads. A pixel none of whose
// four texels is of its own surface looks the maps up itself (the light pass's full-resolution
// lookup, shadows.glsl), in a dispatch of its own (HV_SHADOW_RESOLVE_FALLBACK 1): the resolve
// lists the workgroups that have such a pixel, and an indirect dispatch over that list runs the
// lookup there alone. Inside the resolve, even in a loop that no invocation entered, the
// lookup's code cost every SIMD row (docs/lights.md, "Half resolution"). Doing this here rather
// than in the light pass keeps the weights out of the light loops, where they stayed live across
// every light.
#define HV_SHADOW_MASK_PASS 2
#include "../common/frame.glsl"
#include "../common/gbuffer.glsl"
#include "../common/lights.glsl"
#include "../common/shadow_mask.glsl"

// An invocation resolves HV_SHADOW_RECEIVERS pixels of a column (shadowVisibility's receivers).
layout(local_size_x = 8, local_size_y = 8) in;

// The shadowed lights to resolve: the first u_mask_lights of mask_lights (shadow_mask.glsl).
layout(location = HV_LOC_SHADOW_MASK_LIGHTS) uniform uint u_mask_lights;
layout(r8, binding = HV_IMAGE_SHADOW_MASK) uniform writeonly image2DArray i_resolved;

#ifndef HV_SHADOW_RESOLVE_FALLBACK
#define HV_SHADOW_RESOLVE_FALLBACK 0
#endif
// The workgroups with a pixel that no texel holds: the indirect dispatch's (x, y, 1), which the
// resolve grows as it lists them (at most HV_SHADOW_FALLBACK_ROW workgroups a row, under GL's
// least maximum of 65535 per dimension), their count, then the groups' IDs (x + y << 16), one per
// workgroup of the fallback.
#ifndef HV_SHADOW_FALLBACK_ROW
#define HV_SHADOW_FALLBACK_ROW 65535u
#endif
layout(std430, binding = HV_BINDING_SHADOW_FALLBACK) buffer FallbackBlock {
  uint fallback_dispatch[3];
  uint fallback_count;
  uint fallback_groups[];
};

#if !HV_SHADOW_RESOLVE_FALLBACK
shared uint group_missed;  // 1 when some pixel of the workgroup missed
#endif

void main() {
#if HV_SHADOW_RESOLVE_FALLBACK
  uint slot = gl_WorkGroupID.y * HV_SHADOW_FALLBACK_ROW + gl_WorkGroupID.x;
  if (slot >= fallback_count) return;  // the last row's rest (the whole workgroup)
  uint listed = fallback_groups[slot];
  uvec2 group = uvec2(listed & 0xffffu, listed >> 16);
#else
  uvec2 group = gl_WorkGroupID.xy;
  if (gl_LocalInvocationIndex == 0u) group_missed = 0u;
  barrier();
#endif
  uvec2 id = group * gl_WorkGroupSize.xy + gl_LocalInvocationID.xy;
  ivec2 px[HV_SHADOW_RECEIVERS];
  vec3 P[HV_SHADOW_RECEIVERS];
  vec3 N[HV_SHADOW_RECEIVERS];
  vec2 uv[HV_SHADOW_RECEIVERS];
  vec4 w[HV_SHADOW_RECEIVERS];
  bvec4 use = bvec4(false);
  bvec4 miss = bvec4(false);
  for (int j = 0; j < HV_SHADOW_RECEIVERS; ++j) {
    px[j] = ivec2(id.x, id.y * HV_SHADOW_RECEIVERS + j);
    ivec2 p = min(px[j], ivec2(u_viewport.xy) - 1);
    vec2 code;
    bool lit = shadowMaskSurface(p, P[j], N[j], code);
    use[j] = px[j].x < int(u_viewport.x) && px[j].y < int(u_viewport.y) && lit;
    bool own = shadowMaskWeights(p, P[j], N[j], u_camera_pos.xyz, uv[j], w[j]);
    miss[j] = use[j] && !own;
  }
#if HV_SHADOW_RESOLVE_FALLBACK
  // The maps' lookup for this group's missed pixels (their invocations' loop count is 0
  // elsewhere), stored where the resolve stored nothing.
  uint lookups = any(miss) ? u_mask_lights : 0u;
  for (uint i = 0u; i < lookups; ++i) {
    GpuLight l = lights[mask_lights[i]];
    int layer = shadowMaskLayer(l);
    vec4 direct = anyLightShadow(l, P, N, miss);
    for (int j = 0; j < HV_SHADOW_RECEIVERS; ++j) {
      if (miss[j]) imageStore(i_resolved, ivec3(px[j], layer), vec4(direct[j]));
    }
  }
#else
  for (uint i = 0u; i < u_mask_lights; ++i) {
    int layer = shadowMaskLayer(lights[mask_lights[i]]);
    for (int j = 0; j < HV_SHADOW_RECEIVERS; ++j) {
      float vis = dot(textureGather(t_shadow_mask, vec3(uv[j], float(layer)), 0), w[j]);
      if (px[j].x < int(u_viewport.x) && px[j].y < int(u_viewport.y) && !miss[j]) {
        imageStore(i_resolved, ivec3(px[j], layer), vec4(vis));
      }
    }
  }
  // The group's first invocation lists the group when some pixel of it missed.
  if (any(miss)) group_missed = 1u;
  barrier();
  if (gl_LocalInvocationIndex == 0u && group_missed != 0u) {
    uint k = atomicAdd(fallback_count, 1u);
    fallback_groups[k] = group.x | (group.y << 16);
    atomicMax(fallback_dispatch[0], min(k + 1u, HV_SHADOW_FALLBACK_ROW));
    atomicMax(fallback_dispatch[1], k / HV_SHADOW_FALLBACK_ROW + 1u);
  }
#endif
}
