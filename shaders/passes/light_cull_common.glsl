// Tiled light culling, parallel over tiles and over lights (docs/lights.md, "Tiled culling"): the
// declarations its stages share. The screen's tiles (HV_TILE_SIZE x HV_TILE_HEIGHT pixels) are
// grouped in workgroups of HV_CULL_GROUP_TILES x HV_CULL_GROUP_TILES tiles (64 x 32 pixels), each
// split into 8 blocks of 2 x 4 tiles (16 x 16 pixels; shaders/common/cull_layout.glsl). The
// stages, one file each, in the order the renderer dispatches them
// (engine/render/src/light_cull_pass.cpp):
//
//  light_cull_bounds.comp   per tile, the view-space AABB of its visible surface points; their
//                           unions per block and per group
//  light_cull_bin.comp      per light and band of group rows, its view sphere and tile rectangle,
//                           and its bit in the light mask of every group its sphere touches
//  light_cull_tiles.comp    per group, its mask refined per block, then every tile's walk of its
//                           block's mask: count, reserve, write (light_cull_walk.glsl)
//  light_cull_count.comp, light_cull_reserve.comp, light_cull_fill.comp
//                           the same as light_cull_tiles in steps, for more than
//                           HV_CULL_FUSED_MAX_LIGHTS lights, binned and walked in batches of that
//                           many (a batch bounds the masks' memory and one invocation's loop
//                           iterations)
//
// Every test is a necessary condition for the sphere to touch a surface point of the tile, so no
// light that lights a pixel is dropped (tested: tiled == brute force). No per-tile cap: the list
// is sized by the renderer beforehand. A tile's list holds its lights in light order whatever the
// run, so the light pass sums them in the same order every frame: renders are reproducible bit for
// bit (only where a group's entries sit in the index list depends on the run). No stage runs on one
// workgroup or loops over a light's whole rectangle in one invocation. Plain GLSL 4.50: shared
// memory, barriers, atomics; no subgroup operations.
#ifndef HV_LIGHT_CULL_COMMON_GLSL
#define HV_LIGHT_CULL_COMMON_GLSL

#include "../common/frame.glsl"
#include "../common/lights.glsl"
#include "../common/cull.glsl"

#if HV_CULL_BLOCK_TILES != 8 || HV_CULL_GROUP_TILES != 8
#error "the blocks are 8 tiles of an 8 x 8 tile group (shaders/common/cull_layout.glsl)"
#endif

// Per light, from the binning stage (CullLight: cull_layout.glsl).
layout(std430, binding = HV_BINDING_CULL_LIGHTS) buffer CullLightBlock { CullLight cull_lights[]; };
// Surface AABBs (HV_CULL_BOX_VEC4S vec4s each): per tile, then per block, then per group.
layout(std430, binding = HV_BINDING_CULL_BOUNDS) buffer CullBoundsBlock { vec4 cull_bounds[]; };
// Per group: u_batch.summary_words summary words (bit w % 32 of word w / 32: mask word w is not
// 0), then u_batch.mask_words mask words (bit k of word w: light u_batch.first + 32 w + k). All 0
// between frames and batches: the group that reads a word clears it.
layout(std430, binding = HV_BINDING_CULL_MASKS) buffer CullMaskBlock { uint cull_masks[]; };
// Batched stages: per tile, its counts per type, then its write cursors per type.
layout(std430, binding = HV_BINDING_CULL_TILE_STATE) buffer TileStateBlock { uvec4 tile_state[]; };
layout(std430, binding = HV_BINDING_TILE_RANGES) buffer TileRangeBlock { uvec2 tile_ranges[]; };
layout(std430, binding = HV_BINDING_TILE_TYPES) buffer TileTypeBlock { uvec2 tile_types[]; };
layout(std430, binding = HV_BINDING_TILE_INDICES) buffer TileIndexBlock {
  uint tile_index_count;  // entries of every list: the groups reserve their ranges here
  uint pad0, pad1, pad2;  // HV_TILE_LIST_HEADER_UINTS
  uint tile_indices[];
};
// The lights of this dispatch and the masks' layout (CullBatch: cull_layout.glsl).
layout(std140, binding = HV_UBO_CULL_BATCH) uniform CullBatchBlock { CullBatch u_batch; };
uint groupMasksAt(uint group) { return group * (u_batch.summary_words + u_batch.mask_words); }

uint groupsX() { return (u_viewport.z + uint(HV_CULL_GROUP_TILES) - 1u) / uint(HV_CULL_GROUP_TILES); }
uint groupsY() { return (u_viewport.w + uint(HV_CULL_GROUP_TILES) - 1u) / uint(HV_CULL_GROUP_TILES); }
uint tileIndex(uvec2 tile) { return tile.y * u_viewport.z + tile.x; }
uint groupIndex(uvec2 group) { return group.y * groupsX() + group.x; }
// Indices into cull_bounds (of the min; the max follows).
uint tileBoundsAt(uvec2 tile) { return uint(HV_CULL_BOX_VEC4S) * tileIndex(tile); }
uint blockBoundsAt(uint group, uint block) {
  return uint(HV_CULL_BOX_VEC4S) * (u_viewport.z * u_viewport.w + group * uint(HV_CULL_BLOCKS) + block);
}
uint groupBoundsAt(uint group) {
  return uint(HV_CULL_BOX_VEC4S) *
         (u_viewport.z * u_viewport.w + groupsX() * groupsY() * uint(HV_CULL_BLOCKS) + group);
}

bool sphereTouchesBox(vec4 sphere, vec3 lo, vec3 hi) {
  vec3 q = clamp(sphere.xyz, lo, hi);
  return dot(q - sphere.xyz, q - sphere.xyz) <= sphere.w * sphere.w;
}
// A spot's cone (the record's cone_apex, cone_axis) against the box (lo, hi): false when the
// box's bounding sphere lies outside it (sphereOutsideCone); true for every other light, and no
// code without spots.
bool coneTouchesBox(vec4 apex, vec4 axis, vec3 lo, vec3 hi) {
#if !HV_HAS_SPOT_LIGHTS
  return true;
#endif
  vec3 c = 0.5 * (lo + hi);
  return apex.w == 0.0 ||
         !sphereOutsideCone(c, 0.5 * length(hi - lo), apex.xyz, axis.xyz, axis.w, apex.w);
}
uvec4 unpackRect(uvec2 r) {  // x0, y0, x1, y1
  return uvec4(r.x & HV_CULL_RECT_MASK, r.x >> HV_CULL_RECT_SHIFT, r.y & HV_CULL_RECT_MASK,
               r.y >> HV_CULL_RECT_SHIFT);
}

// Invocation t of a group: block t / 8 (blocks in rows of HV_CULL_BLOCKS_X), tile t % 8 of it.
uvec2 blockOrigin(uint block) {  // in tiles, within the group
  return uvec2(block % uint(HV_CULL_BLOCKS_X) * uint(HV_CULL_BLOCK_W),
               block / uint(HV_CULL_BLOCKS_X) * uint(HV_CULL_BLOCK_H));
}
uvec2 thisTile() {
  uint t = gl_LocalInvocationIndex;
  uvec2 in_block = uvec2(t % uint(HV_CULL_BLOCK_W), (t % 8u) / uint(HV_CULL_BLOCK_W));
  return gl_WorkGroupID.xy * uint(HV_CULL_GROUP_TILES) + blockOrigin(t / 8u) + in_block;
}
bool inGrid(uvec2 tile) { return tile.x < u_viewport.z && tile.y < u_viewport.w; }

// The last test of every path, the light (its record) against one tile with a surface, whose
// view-space AABB is (lo, hi): inside the light's tile rectangle, sphere-box distance, a spot's
// cone against the box's sphere.
bool lightTouchesTile(vec4 sphere, uvec2 packed_rect, vec4 cone_apex, vec4 cone_axis, uvec2 tile,
                      vec3 lo, vec3 hi) {
  uvec4 rect = unpackRect(packed_rect);
  return tile.x >= rect.x && tile.x <= rect.z && tile.y >= rect.y && tile.y <= rect.w &&
         sphereTouchesBox(sphere, lo, hi) && coneTouchesBox(cone_apex, cone_axis, lo, hi);
}

// The group's reservation (reserve): its entries' total, then its base in the index list.
shared uint s_group_total, s_group_base;

// Reserves the group's entries with one global atomic (within the group, each tile's place in any
// order) and writes the tile's range and split. Returns the tile's write cursors per type.
// Contains barriers: call from uniform control flow, with s_group_total 0 and a barrier before.
uvec3 reserve(uvec2 tile, uvec3 n) {
  uint total = n.x + n.y + n.z;
  uint local_offset = atomicAdd(s_group_total, total);
  barrier();
  if (gl_LocalInvocationIndex == 0u) s_group_base = atomicAdd(tile_index_count, s_group_total);
  barrier();
  uint offset = s_group_base + local_offset;
  if (inGrid(tile)) {
    tile_ranges[tileIndex(tile)] = uvec2(offset, total);
    tile_types[tileIndex(tile)] = n.xy;  // points, spheres; tubes follow
  }
  return uvec3(offset, offset + n.x, offset + n.x + n.y);
}

#endif
