#version 450 core
// Tiled culling, second stage (light_cull_common.glsl): one invocation per light of the batch and
// band of HV_CULL_BIN_GROUP_ROWS group rows (so that a light covering the screen is binned by
// several invocations, not by one): the light's culling record (cullLightRecord: its view sphere,
// tile rectangle and spot cone); then, for every group of the
// band that the rectangle overlaps and the sphere touches (sphere-box distance to the group's
// AABB), the light's bit in the group's light mask (atomicOr: the same masks whatever the order).
#include "light_cull_light.glsl"

layout(local_size_x = HV_CULL_BIN_LIGHTS) in;

void main() {
  uint i = u_batch.first + gl_GlobalInvocationID.x;
  if (i >= u_batch.end) return;
  CullLight l = cullLightRecord(i);
  if (gl_GlobalInvocationID.y == 0u) cull_lights[i] = l;
  bool visible = l.rect.x != HV_CULL_RECT_EMPTY;
  uvec4 rect = unpackRect(l.rect.xy);
  vec4 sphere = l.sphere;
  if (!visible) return;
  uvec4 g = rect / uint(HV_CULL_GROUP_TILES);  // the rectangle's groups
  uint band0 = gl_GlobalInvocationID.y * uint(HV_CULL_BIN_GROUP_ROWS);
  uint y0 = max(g.y, band0), y1 = min(g.w, band0 + uint(HV_CULL_BIN_GROUP_ROWS) - 1u);
  uint bit = 1u << ((i - u_batch.first) % 32u), w = (i - u_batch.first) / 32u;
  for (uint y = y0; y <= y1; ++y) {
    for (uint x = g.x; x <= g.z; ++x) {
      uint group = groupIndex(uvec2(x, y));
      vec4 lo = cull_bounds[groupBoundsAt(group)];
      if (lo.w != 0.0 && sphereTouchesBox(sphere, lo.xyz, cull_bounds[groupBoundsAt(group) + 1u].xyz)) {
        // The summary bit is set by the light that finds the word empty.
        uint at = groupMasksAt(group);
        if (atomicOr(cull_masks[at + u_batch.summary_words + w], bit) == 0u) {
          atomicOr(cull_masks[at + w / 32u], 1u << (w % 32u));
        }
      }
    }
  }
}
