#version 450 core
// Tiled culling, first stage (light_cull_common.glsl): one invocation per tile, the view-space
// AABB of the tile's visible surface points, from its depth texels (Andersson 2011, "DirectX 11
// Rendering in Battlefield 3", tightened in x and y: a slanted floor tile is a thin slab, not the
// whole frustum slice between its min and max depth), and the unions over each block and each
// group. Sets the list's total to 0.
#include "light_cull_tile_bounds.glsl"

layout(local_size_x = HV_CULL_GROUP_SIZE) in;

shared uint s_bounds[(HV_CULL_BLOCKS + 1) * 6];  // per block, then the group: min xyz, max xyz

// Float -> uint with the same order (negative floats flipped), so atomicMin/Max work on signs.
uint orderedBits(float f) {
  uint u = floatBitsToUint(f);
  return (u & 0x80000000u) != 0u ? ~u : u | 0x80000000u;
}
float fromOrderedBits(uint u) {
  return uintBitsToFloat((u & 0x80000000u) != 0u ? u & 0x7FFFFFFFu : ~u);
}

void addToBox(uint box, vec3 lo, vec3 hi) {
  atomicMin(s_bounds[box * 6u + 0u], orderedBits(lo.x));
  atomicMin(s_bounds[box * 6u + 1u], orderedBits(lo.y));
  atomicMin(s_bounds[box * 6u + 2u], orderedBits(lo.z));
  atomicMax(s_bounds[box * 6u + 3u], orderedBits(hi.x));
  atomicMax(s_bounds[box * 6u + 4u], orderedBits(hi.y));
  atomicMax(s_bounds[box * 6u + 5u], orderedBits(hi.z));
}

void storeBox(uint box, uint at) {
  bool any = s_bounds[box * 6u + 3u] != 0u;
  cull_bounds[at] = vec4(fromOrderedBits(s_bounds[box * 6u]), fromOrderedBits(s_bounds[box * 6u + 1u]),
                         fromOrderedBits(s_bounds[box * 6u + 2u]), any ? 1.0 : 0.0);
  cull_bounds[at + 1u] = vec4(fromOrderedBits(s_bounds[box * 6u + 3u]),
                              fromOrderedBits(s_bounds[box * 6u + 4u]),
                              fromOrderedBits(s_bounds[box * 6u + 5u]), 0.0);
}

void main() {
  uint t = gl_LocalInvocationIndex;
  if (gl_WorkGroupID.xy == uvec2(0u) && t == 0u) tile_index_count = 0u;  // for the reservations
  if (t < uint((HV_CULL_BLOCKS + 1) * 6)) s_bounds[t] = t % 6u < 3u ? 0xFFFFFFFFu : 0u;
  barrier();
  uvec2 tile = thisTile();
  vec3 lo = vec3(3.0e38), hi = vec3(-3.0e38);
  if (inGrid(tile)) {
    tileBounds(tile, lo, hi);
    cull_bounds[tileBoundsAt(tile)] = vec4(lo, lo.x <= hi.x ? 1.0 : 0.0);
    cull_bounds[tileBoundsAt(tile) + 1u] = vec4(hi, 0.0);
  }
  if (lo.x <= hi.x) {
    addToBox(t / 8u, lo, hi);
    addToBox(uint(HV_CULL_BLOCKS), lo, hi);
  }
  barrier();
  uint group = groupIndex(gl_WorkGroupID.xy);
  if (t < uint(HV_CULL_BLOCKS)) storeBox(t, blockBoundsAt(group, t));
  if (t == uint(HV_CULL_BLOCKS)) storeBox(t, groupBoundsAt(group));
}
