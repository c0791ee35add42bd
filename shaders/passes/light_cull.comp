#version 450 core
// Tiled light culling, parallel over tiles and over lights (docs/lights.md, "Tiled culling").
// The screen's tiles (HV_TILE_SIZE x HV_TILE_HEIGHT pixels) are grouped in workgroups of
// HV_CULL_GROUP_TILES x HV_CULL_GROUP_TILES tiles (64 x 32 pixels), each split into 8 blocks of
// 2 x 4 tiles (16 x 16 pixels); a block's 8 tiles are 8 consecutive invocations, one SIMD vector on
// an 8-wide implementation (llvmpipe). Stages, picked by HV_CULL_STAGE:
//
//  0 HV_CULL_BOUNDS  one invocation per tile: the view-space AABB of the tile's visible surface
//                    points, from its depth texels (Andersson 2011, "DirectX 11 Rendering in
//                    Battlefield 3", tightened in x and y: a slanted floor tile is a thin slab,
//                    not the whole frustum slice between its min and max depth), and the unions
//                    over each block and each group. Sets the list's total to 0.
//  1 HV_CULL_BIN     one invocation per light and band of group rows: the light's bounding sphere
//                    (lightCullRadius) in view space and its exact rectangle of tiles
//                    (sphereTileRect: tangent planes through the eye; none when the sphere lies
//                    entirely nearer than the near plane or off screen); then, for every group of
//                    the band that the rectangle overlaps and the sphere touches (sphere-box
//                    distance to the group's AABB), the light's bit in the group's light mask
//                    (atomicOr: the same masks whatever the order).
//  2 HV_CULL_TILES   one workgroup per group: (a) its mask refined per block (rectangle and
//                    sphere-box tests against each block) into shared memory, the group's mask
//                    cleared for the next frame; (b) every tile walks its block's mask in light
//                    order, tests each light against itself (inside the light's rectangle,
//                    sphere-box distance to the tile's AABB) and counts the hits per light type;
//                    (c) the group reserves its tiles' entries with one atomicAdd on the list's
//                    total; (d) the walk again, writing each tile's list: points, then spheres,
//                    then tubes, each in light order.
//  3, 4, 5           the same as 2 in steps, for more than HV_CULL_FUSED_MAX_LIGHTS lights, binned
//                    and walked in batches of that many (a batch bounds the masks' memory and one
//                    invocation's loop iterations): HV_CULL_COUNT (a and b for a batch, the counts
//                    kept per tile), HV_CULL_RESERVE (c), HV_CULL_FILL (a and d for a batch at
//                    cursors kept per tile).
//
// Every test is a necessary condition for the sphere to touch a surface point of the tile, so no
// light that lights a pixel is dropped (tested: tiled == brute force). No per-tile cap: the list
// is sized by the renderer beforehand (engine/render/src/light_cull_pass.cpp). A tile's list holds
// its lights in light order whatever the run, so the light pass sums them in the same order every
// frame: renders are reproducible bit for bit (only where a group's entries sit in the index list
// depends on the run). No stage runs on one workgroup or loops over a light's whole rectangle in
// one invocation. Plain GLSL 4.50: shared memory, barriers, atomics; no subgroup operations.
#include "../common/frame.glsl"
#include "../common/lights.glsl"
#include "../common/cull.glsl"

#define HV_CULL_BOUNDS 0
#define HV_CULL_BIN 1
#define HV_CULL_TILES 2
#define HV_CULL_COUNT 3
#define HV_CULL_RESERVE 4
#define HV_CULL_FILL 5
#ifndef HV_CULL_STAGE
#define HV_CULL_STAGE HV_CULL_BOUNDS
#endif

#define HV_CULL_GROUP_SIZE (HV_CULL_GROUP_TILES * HV_CULL_GROUP_TILES)  // tiles = invocations
#define HV_CULL_BLOCK_W 2                                              // tiles
#define HV_CULL_BLOCK_H 4
#define HV_CULL_BLOCKS_X (HV_CULL_GROUP_TILES / HV_CULL_BLOCK_W)
#define HV_CULL_BLOCKS (HV_CULL_GROUP_SIZE / (HV_CULL_BLOCK_W * HV_CULL_BLOCK_H))
#if HV_CULL_BLOCK_W * HV_CULL_BLOCK_H != 8 || HV_CULL_GROUP_TILES != 8
#error "the blocks are 8 tiles of an 8 x 8 tile group (engine/render/src/light_cull_pass.cpp)"
#endif

// Per light, from HV_CULL_BIN: the view-space sphere (center xyz, culling radius w) and its tile
// rectangle x0 | y0 << 16, x1 | y1 << 16 | type << 30 (an empty rectangle, x0 > x1, for a light
// that touches no tile). Tile coordinates < 2^14 (viewport <= 16384).
struct CullLight {
  vec4 sphere;
  uvec4 rect;  // x, y as above; z, w unused
};
layout(std430, binding = HV_BINDING_CULL_LIGHTS) buffer CullLightBlock { CullLight cull_lights[]; };
// Surface AABBs as (min xyz, 1 if any surface) and (max xyz, 0): per tile, then per block, then
// per group.
layout(std430, binding = HV_BINDING_CULL_BOUNDS) buffer CullBoundsBlock { vec4 cull_bounds[]; };
// Per group: u_cull_batch.w summary words (bit w % 32 of word w / 32: mask word w is not 0), then
// u_cull_batch.z mask words (bit k of word w: light batch start + 32 w + k). All 0 between frames
// and batches: the group that reads a word clears it.
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
// The lights [x, y) of this dispatch (a batch), mask words per group z, summary words per group w.
layout(location = HV_LOC_CULL_BATCH) uniform uvec4 u_cull_batch;
uint groupMasksAt(uint group) { return group * (u_cull_batch.w + u_cull_batch.z); }

uint groupsX() { return (u_viewport.z + uint(HV_CULL_GROUP_TILES) - 1u) / uint(HV_CULL_GROUP_TILES); }
uint groupsY() { return (u_viewport.w + uint(HV_CULL_GROUP_TILES) - 1u) / uint(HV_CULL_GROUP_TILES); }
uint tileIndex(uvec2 tile) { return tile.y * u_viewport.z + tile.x; }
uint groupIndex(uvec2 group) { return group.y * groupsX() + group.x; }
// Indices into cull_bounds (of the min; the max follows).
uint tileBoundsAt(uvec2 tile) { return 2u * tileIndex(tile); }
uint blockBoundsAt(uint group, uint block) {
  return 2u * (u_viewport.z * u_viewport.w + group * uint(HV_CULL_BLOCKS) + block);
}
uint groupBoundsAt(uint group) {
  return 2u * (u_viewport.z * u_viewport.w + groupsX() * groupsY() * uint(HV_CULL_BLOCKS) + group);
}

bool sphereTouchesBox(vec4 sphere, vec3 lo, vec3 hi) {
  vec3 q = clamp(sphere.xyz, lo, hi);
  return dot(q - sphere.xyz, q - sphere.xyz) <= sphere.w * sphere.w;
}
uvec4 unpackRect(uvec2 r) {  // x0, y0, x1, y1
  return uvec4(r.x & 0xFFFFu, r.x >> 16, r.y & 0xFFFFu, (r.y >> 16) & 0x3FFFu);
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

// Float -> uint with the same order (negative floats flipped), so atomicMin/Max work on signs.
uint orderedBits(float f) {
  uint u = floatBitsToUint(f);
  return (u & 0x80000000u) != 0u ? ~u : u | 0x80000000u;
}
float fromOrderedBits(uint u) {
  return uintBitsToFloat((u & 0x80000000u) != 0u ? u & 0x7FFFFFFFu : ~u);
}

// ---------------------------------------------------------------------------------------------
#if HV_CULL_STAGE == HV_CULL_BOUNDS
layout(local_size_x = HV_CULL_GROUP_SIZE) in;
layout(binding = HV_UNIT_DEPTH) uniform sampler2D t_depth;

shared uint s_bounds[(HV_CULL_BLOCKS + 1) * 6];  // per block, then the group: min xyz, max xyz

// Adds the view-space point of depth d at NDC (ndc_x, ndc_y) to the AABB (lo, hi), unless d = 0
// (nothing drawn: background needs no lights). A point at view distance z on the ray of NDC
// (nx, ny) is (nx z / P00, ny z / P11, -z) (centered projection, frame_data.cpp). Branch-free (a
// SIMD implementation runs both sides of a branch).
void addPoint(float d, float ndc_x, float ndc_y, vec2 inv_scale, inout vec3 lo, inout vec3 hi) {
  float z = u_near_params.x / d;  // reversed-Z infinite: view distance (frame_data.hpp)
  vec3 p = vec3(ndc_x * inv_scale.x * z, ndc_y * inv_scale.y * z, -z);
  bool surface = d > 0.0;
  lo = surface ? min(lo, p) : lo;
  hi = surface ? max(hi, p) : hi;
}

float pixelNdc(int p, float size) { return (float(p) + 0.5) / size * 2.0 - 1.0; }

#if (HV_TILE_SIZE % 2) != 0 || (HV_TILE_HEIGHT % 2) != 0
#error "tileBounds gathers 2 x 2 texels: the tile's sides must be even"
#endif
// The tile's view-space surface AABB (lo > hi: no surface), from its depth texels four at a
// time: textureGather at the corner shared by pixels (x, y) .. (x + 1, y + 1) returns exactly those
// four (the footprint of linear filtering), a quarter of the fetches of texelFetch (measured on
// llvmpipe: the bounds 0.54 -> 0.31 floor passes, default scene). Past the viewport's edge the
// clamp-to-edge sampler returns the last row or column again, which leaves the bounds as they are.
void tileBounds(uvec2 tile, out vec3 lo, out vec3 hi) {
  lo = vec3(3.0e38);
  hi = vec3(-3.0e38);
  vec2 inv_scale = vec2(1.0 / u_proj[0][0], 1.0 / u_proj[1][1]);
  vec2 size = vec2(u_viewport.xy);
  ivec2 last = ivec2(u_viewport.xy) - 1;
  ivec2 origin = ivec2(tile) * ivec2(HV_TILE_SIZE, HV_TILE_HEIGHT);
  for (int i = 0; i < HV_TILE_SIZE; i += 2) {
    int x = origin.x + i;
    float nx0 = pixelNdc(min(x, last.x), size.x), nx1 = pixelNdc(min(x + 1, last.x), size.x);
    for (int j = 0; j < HV_TILE_HEIGHT; j += 2) {
      int y = origin.y + j;
      float ny0 = pixelNdc(min(y, last.y), size.y), ny1 = pixelNdc(min(y + 1, last.y), size.y);
      // Components: x (x, y + 1), y (x + 1, y + 1), z (x + 1, y), w (x, y).
      vec4 d = textureGather(t_depth, vec2(x + 1, y + 1) / size);
      addPoint(d.w, nx0, ny0, inv_scale, lo, hi);
      addPoint(d.z, nx1, ny0, inv_scale, lo, hi);
      addPoint(d.x, nx0, ny1, inv_scale, lo, hi);
      addPoint(d.y, nx1, ny1, inv_scale, lo, hi);
    }
  }
  if (lo.x <= hi.x) {
    // Widen by 1e-5 of the distance: the light pass reconstructs positions through
    // inv_view_proj, which may round differently from the view-space formula above.
    vec3 pad = vec3(1e-5 * max(-lo.z, 1.0));
    lo -= pad;
    hi += pad;
  }
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

// ---------------------------------------------------------------------------------------------
#elif HV_CULL_STAGE == HV_CULL_BIN
// x: 64 lights of the batch; y: bands of HV_CULL_BIN_GROUP_ROWS group rows, so that a light
// covering the screen is binned by several invocations, not by one.
layout(local_size_x = 64) in;
layout(std430, binding = HV_BINDING_LIGHTS) readonly buffer LightBlock { GpuLight lights[]; };

void main() {
  uint i = u_cull_batch.x + gl_GlobalInvocationID.x;
  if (i >= u_cull_batch.y) return;
  vec3 c = (u_view * vec4(lights[i].position_radius.xyz, 1.0)).xyz;
  float r = lightCullRadius(lights[i]);
  uint type = uint(lights[i].params.y + 0.5);  // HV_LIGHT_POINT/SPHERE/TUBE = 0/1/2
  ivec4 rect;
  bool visible = type <= 2u && sphereTileRect(c, r, vec2(u_proj[0][0], u_proj[1][1]),
                                              u_near_params.x, vec2(u_viewport.xy),
                                              ivec2(u_viewport.zw),
                                              vec2(HV_TILE_SIZE, HV_TILE_HEIGHT), rect);
  vec4 sphere = vec4(c, r);
  if (gl_GlobalInvocationID.y == 0u) {
    cull_lights[i].sphere = sphere;
    cull_lights[i].rect = visible ? uvec4(uint(rect.x) | (uint(rect.y) << 16),
                                          uint(rect.z) | (uint(rect.w) << 16) | (type << 30), 0u, 0u)
                                  : uvec4(0xFFFFu, 0u, 0u, 0u);
  }
  if (!visible) return;
  uvec4 g = uvec4(rect) / uint(HV_CULL_GROUP_TILES);  // the rectangle's groups
  uint band0 = gl_GlobalInvocationID.y * uint(HV_CULL_BIN_GROUP_ROWS);
  uint y0 = max(g.y, band0), y1 = min(g.w, band0 + uint(HV_CULL_BIN_GROUP_ROWS) - 1u);
  uint bit = 1u << ((i - u_cull_batch.x) % 32u), w = (i - u_cull_batch.x) / 32u;
  for (uint y = y0; y <= y1; ++y) {
    for (uint x = g.x; x <= g.z; ++x) {
      uint group = groupIndex(uvec2(x, y));
      vec4 lo = cull_bounds[groupBoundsAt(group)];
      if (lo.w != 0.0 && sphereTouchesBox(sphere, lo.xyz, cull_bounds[groupBoundsAt(group) + 1u].xyz)) {
        // The summary bit is set by the light that finds the word empty.
        uint at = groupMasksAt(group);
        if (atomicOr(cull_masks[at + u_cull_batch.w + w], bit) == 0u) {
          atomicOr(cull_masks[at + w / 32u], 1u << (w % 32u));
        }
      }
    }
  }
}

// ---------------------------------------------------------------------------------------------
#else  // the per-group stages
layout(local_size_x = HV_CULL_GROUP_SIZE) in;

// Per block: the group's mask refined to the lights that can touch a tile of the block.
shared uint s_mask[HV_CULL_BLOCKS * (HV_CULL_FUSED_MAX_LIGHTS / 32)];
// Per block, which of its mask words are not 0 (bit w % 32 of word w / 32): the walk visits only
// those (and no other word of s_mask is written).
shared uint s_words[HV_CULL_BLOCKS * (HV_CULL_FUSED_MAX_LIGHTS / 1024)];
shared vec4 s_block_bounds[HV_CULL_BLOCKS * 2];
shared uint s_group_total, s_group_base;

uint blockWords() { return u_cull_batch.z; }
uint blockSummaryWords() { return u_cull_batch.w; }

// (a) The group's mask words, refined per block into s_mask and s_words (which must be 0):
// invocation t takes the words of summary word t (few invocations work, but the loops run over
// marked words only: on llvmpipe every loop iteration costs, and most of a group's words are 0).
// The group's words are cleared as they are read. A barrier must follow before the walks.
void refine() {
  uint t = gl_LocalInvocationIndex;
  uvec2 group_tile = gl_WorkGroupID.xy * uint(HV_CULL_GROUP_TILES);
  uint at = groupMasksAt(groupIndex(gl_WorkGroupID.xy));
  if (t >= u_cull_batch.w) return;
  uint words = cull_masks[at + t];
  if (words != 0u) cull_masks[at + t] = 0u;
  while (words != 0u) {
    uint w = 32u * t + uint(findLSB(words));
    words &= words - 1u;
    uint m = cull_masks[at + u_cull_batch.w + w];
    cull_masks[at + u_cull_batch.w + w] = 0u;
    uint bits[HV_CULL_BLOCKS];
    for (int b = 0; b < HV_CULL_BLOCKS; ++b) bits[b] = 0u;
    do {
      uint k = uint(findLSB(m));
      m &= m - 1u;
      // A stale bit past the batch (masks left by a failed frame) is ignored.
      uint i = min(u_cull_batch.x + 32u * w + k, u_cull_batch.y - 1u);
      bool valid = u_cull_batch.x + 32u * w + k < u_cull_batch.y;
      uvec4 rect = unpackRect(cull_lights[i].rect.xy);
      vec4 sphere = cull_lights[i].sphere;
      for (int b = 0; b < HV_CULL_BLOCKS; ++b) {
        uvec2 lo = group_tile + blockOrigin(uint(b));
        uvec2 hi = lo + uvec2(HV_CULL_BLOCK_W - 1, HV_CULL_BLOCK_H - 1);
        vec4 box_lo = s_block_bounds[2 * b];
        bool touch = valid && rect.x <= hi.x && rect.z >= lo.x && rect.y <= hi.y && rect.w >= lo.y &&
                     box_lo.w != 0.0 &&
                     sphereTouchesBox(sphere, box_lo.xyz, s_block_bounds[2 * b + 1].xyz);
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
      uint first = u_cull_batch.x + 32u * w;
      do {  // m != 0: the summary marks the word
        uint i = first + uint(findLSB(m));
        m &= m - 1u;
        uvec4 rect = unpackRect(cull_lights[i].rect.xy);
        uint type = cull_lights[i].rect.y >> 30;
        bool hit = has_surface && tile.x >= rect.x && tile.x <= rect.z && tile.y >= rect.y &&
                   tile.y <= rect.w && sphereTouchesBox(cull_lights[i].sphere, lo.xyz, hi);
        // Per type without indexing a vector by a variable (which a SIMD implementation may turn
        // into per-lane memory accesses): selects.
        uvec3 add = uvec3(type == 0u, type == 1u, type == 2u) * uint(hit);
        uint slot = type == 0u ? cursor.x : (type == 1u ? cursor.y : cursor.z);
        if (fill && hit && slot < u_counts.y) tile_indices[slot] = i;
        cursor += add;
        n += add;
      } while (m != 0u);
    }
  }
}

// (c) Reserves the group's entries with one global atomic (within the group, each tile's place in
// any order) and writes the tile's range and split. Returns the tile's write cursors per type.
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

void main() {
  uvec2 tile = thisTile();
  uvec3 n = uvec3(0u), cursor = uvec3(0u);
  init();
#if HV_CULL_STAGE == HV_CULL_TILES
  refine();
  barrier();
  walk(tile, false, n, cursor);
  cursor = reserve(tile, n);
  walk(tile, true, n, cursor);
#elif HV_CULL_STAGE == HV_CULL_COUNT
  if (inGrid(tile) && u_cull_batch.x > 0u) n = tile_state[tileIndex(tile)].xyz;
  refine();
  barrier();
  walk(tile, false, n, cursor);
  if (inGrid(tile)) tile_state[tileIndex(tile)] = uvec4(n, 0u);
#elif HV_CULL_STAGE == HV_CULL_RESERVE
  if (inGrid(tile)) n = tile_state[tileIndex(tile)].xyz;
  cursor = reserve(tile, n);
  if (inGrid(tile)) tile_state[tileIndex(tile)] = uvec4(cursor, 0u);
#else  // HV_CULL_FILL
  if (inGrid(tile)) cursor = tile_state[tileIndex(tile)].xyz;
  refine();
  barrier();
  walk(tile, true, n, cursor);
  if (inGrid(tile)) tile_state[tileIndex(tile)] = uvec4(cursor, 0u);
#endif
}
#endif
