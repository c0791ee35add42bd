// Tiled culling, the per-group stages' steps (light_cull_tiles.comp; batched:
// light_cull_count.comp, light_cull_reserve.comp, light_cull_fill.comp): (a) refine, the group's
// mask refined per block (rectangle and sphere-box tests against each block) into shared memory,
// the group's mask cleared for the next frame or batch; (b) walk, every tile walks its block's mask
// in light order, tests each light against itself (lightTouchesTile) and counts the hits per light
// type; (c) reserve (light_cull_common.glsl), the group reserves its tiles' entries with one
// atomicAdd on the list's total; (d) walk again, writing each tile's list: points, then spheres,
// then tubes, each in light order.
#ifndef HV_LIGHT_CULL_WALK_GLSL
#define HV_LIGHT_CULL_WALK_GLSL

#include "light_cull_common.glsl"

layout(local_size_x = HV_CULL_GROUP_SIZE) in;

// Per block: the group's mask refined to the lights that can touch a tile of the block.
shared uint s_mask[HV_CULL_BLOCKS * (HV_CULL_FUSED_MAX_LIGHTS / 32)];
// Per block, which of its mask words are not 0 (bit w % 32 of word w / 32): the walk visits only
// those (and no other word of s_mask is written).
shared uint s_words[HV_CULL_BLOCKS * (HV_CULL_FUSED_MAX_LIGHTS / 1024)];
shared vec4 s_block_bounds[HV_CULL_BLOCKS * 2];

uint blockWords() { return u_batch.mask_words; }
uint blockSummaryWords() { return u_batch.summary_words; }

// (a) The group's mask words, refined per block into s_mask and s_words (which must be 0):
// invocation t takes the words of summary word t (few invocations work, but the loops run over
// marked words only: on llvmpipe every loop iteration costs, and most of a group's words are 0).
// The group's words are cleared as they are read. A barrier must follow before the walks.
void refine() {
  uint t = gl_LocalInvocationIndex;
  uvec2 group_tile = gl_WorkGroupID.xy * uint(HV_CULL_GROUP_TILES);
  uint at = groupMasksAt(groupIndex(gl_WorkGroupID.xy));
  if (t >= u_batch.summary_words) return;
  uint words = cull_masks[at + t];
  if (words != 0u) cull_masks[at + t] = 0u;
  while (words != 0u) {
    uint w = 32u * t + uint(findLSB(words));
    words &= words - 1u;
    uint m = cull_masks[at + u_batch.summary_words + w];
    cull_masks[at + u_batch.summary_words + w] = 0u;
    uint bits[HV_CULL_BLOCKS];
    for (int b = 0; b < HV_CULL_BLOCKS; ++b) bits[b] = 0u;
    do {
      uint k = uint(findLSB(m));
      m &= m - 1u;
      // A stale bit past the batch (masks left by a failed frame) is ignored.
      uint i = min(u_batch.first + 32u * w + k, u_batch.end - 1u);
      bool valid = u_batch.first + 32u * w + k < u_batch.end;
      uvec4 rect = unpackRect(cull_lights[i].rect.xy);
      vec4 sphere = cull_lights[i].sphere;
      for (int b = 0; b < HV_CULL_BLOCKS; ++b) {
        uvec2 lo = group_tile + blockOrigin(uint(b));
        uvec2 hi = lo + uvec2(HV_CULL_BLOCK_W - 1, HV_CULL_BLOCK_H - 1);
        vec4 box_lo = s_block_bounds[2 * b];
        bool touch = valid && rect.x <= hi.x && rect.z >= lo.x && rect.y <= hi.y && rect.w >= lo.y &&
                     box_lo.w != 0.0 &&
                     sphereTouchesBox(sphere, box_lo.xyz, s_block_bounds[2 * b + 1].xyz) &&
                     coneTouchesBox(cull_lights[i].cone_apex, cull_lights[i].cone_axis, box_lo.xyz,
                                    s_block_bounds[2 * b + 1].xyz);
        bits[b] |= touch ? 1u << k : 0u;
      }
    } while (m != 0u);
    for (int b = 0; b < HV_CULL_BLOCKS; ++b) {
      s_mask[uint(b) * blockWords() + w] = bits[b];
      if (bits[b] != 0u) atomicOr(s_words[uint(b) * blockSummaryWords() + w / 32u], 1u << (w % 32u));
    }
  }
}

// (b, d) The tile's block mask against the tile, in light order: counts hits per type into n;
// with `fill`, also writes each hit at cursor[type] (then advanced). The loops run over the
// block's marked words and lights only, the same for every tile of the block: they do not
// diverge on an implementation that runs a block as one SIMD vector (8 wide: llvmpipe).
void walk(uvec2 tile, bool fill, inout uvec3 n, inout uvec3 cursor) {
  uint block = gl_LocalInvocationIndex / 8u;
  bool in_grid = inGrid(tile);
  vec4 lo = in_grid ? cull_bounds[tileBoundsAt(tile)] : vec4(0.0);
  vec3 hi = in_grid ? cull_bounds[tileBoundsAt(tile) + 1u].xyz : vec3(0.0);
  bool has_surface = in_grid && lo.w != 0.0;
  for (uint h = 0u; h < blockSummaryWords(); ++h) {
    uint words = s_words[block * blockSummaryWords() + h];
    while (words != 0u) {
      uint w = 32u * h + uint(findLSB(words));
      words &= words - 1u;
      uint m = s_mask[block * blockWords() + w];
      uint first = u_batch.first + 32u * w;
      do {  // m != 0: the summary marks the word
        uint i = first + uint(findLSB(m));
        m &= m - 1u;
        uint type = cull_lights[i].rect.z;
        bool hit = has_surface &&
                   lightTouchesTile(cull_lights[i].sphere, cull_lights[i].rect.xy,
                                    cull_lights[i].cone_apex, cull_lights[i].cone_axis, tile,
                                    lo.xyz, hi);
        // Per type without indexing a vector by a variable (which a SIMD implementation may turn
        // into per-lane memory accesses): selects.
        uvec3 add = uvec3(type == 0u, type == 1u, type == 2u) * uint(hit);
        uint slot = type == 0u ? cursor.x : (type == 1u ? cursor.y : cursor.z);
        if (fill && hit && slot < u_tile_capacity) tile_indices[slot] = i;
        cursor += add;
        n += add;
      } while (m != 0u);
    }
  }
}

// Shared state to 0, the blocks' bounds into shared memory; a barrier follows.
void init() {
  uint t = gl_LocalInvocationIndex;
  if (t == 0u) s_group_total = 0u;
  for (uint h = t; h < uint(HV_CULL_BLOCKS) * blockSummaryWords(); h += uint(HV_CULL_GROUP_SIZE)) {
    s_words[h] = 0u;
  }
  if (t < uint(2 * HV_CULL_BLOCKS)) {
    s_block_bounds[t] = cull_bounds[blockBoundsAt(groupIndex(gl_WorkGroupID.xy), t / 2u) + t % 2u];
  }
  barrier();
}


#endif
