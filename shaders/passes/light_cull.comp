#version 450 core
// Tiled light culling whose cost follows the (tile, light) pairs that touch, not tiles x lights
// (docs/lights.md, "Tiled culling"). Three stages, picked by HV_CULL_STAGE, dispatched in order:
//
//  0 HV_CULL_BOUNDS  one workgroup per tile (HV_TILE_SIZE x HV_TILE_HEIGHT pixels): the view-space
//                    AABB of its visible surface points (from depth; background pixels excluded):
//                    the depth range of Andersson 2011 ("DirectX 11 Rendering in Battlefield 3")
//                    tightened in x and y as well: a slanted floor tile is a thin slab, not the
//                    whole frustum slice between its min and max depth.
//  1 HV_CULL_LIGHTS  one invocation per light: the light's bounding sphere (lightCullRadius) is
//                    projected to its exact rectangle of tiles (tangent planes through the eye);
//                    for every tile of it the sphere is tested against the tile's AABB (exact
//                    sphere-box distance). u_cull_phase 0 counts hits per (tile, light type);
//                    phase 1 writes the light index into the slot the scan reserved. Both phases
//                    run the same program on the same data, so they find the same pairs.
//  2 HV_CULL_SCAN    one workgroup: exclusive prefix sum over the (tile, type) counts, giving each
//                    tile an exactly sized range [offset, offset + count) of the global index list,
//                    sorted by light type (points, spheres, tubes) so the light pass runs one
//                    branch-free loop per type.
//
// Every test is a necessary condition for the sphere to touch a surface point of the tile, so no
// light that lights a pixel is ever dropped (tested: tiled == brute force, 4,096 lights). No
// per-tile cap: the renderer reads the total back after the scan and grows the list before the
// fill (engine/render/src/light_pass.cpp). Plain GLSL 4.50 (shared memory atomics and barriers only;
// no subgroup operations).
#include "../common/frame.glsl"
#include "../common/lights.glsl"
#include "../common/cull.glsl"

#define HV_CULL_BOUNDS 0
#define HV_CULL_LIGHTS 1
#define HV_CULL_SCAN 2
#ifndef HV_CULL_STAGE
#define HV_CULL_STAGE HV_CULL_BOUNDS
#endif

// Per tile: view-space AABB of its surface points; min.w = 1 when the tile has any (else 0).
layout(std430, binding = HV_BINDING_TILE_BOUNDS) buffer TileBoundsBlock { vec4 tile_bounds[]; };
// Per (tile, type): hit count (stage 1 phase 0), then the next free slot (scan, stage 1 phase 1).
layout(std430, binding = HV_BINDING_TILE_COUNTERS) buffer TileCounterBlock { uint tile_counters[]; };

// ---------------------------------------------------------------------------------------------
#if HV_CULL_STAGE == HV_CULL_BOUNDS
layout(binding = HV_UNIT_DEPTH) uniform sampler2D t_depth;
// One invocation per pixel column of the tile: its HV_TILE_HEIGHT fetches reduced in registers,
// then one shared atomic per bound (instead of one per pixel).
layout(local_size_x = HV_TILE_SIZE) in;

shared uint s_bounds[6];  // min xyz, max xyz as order-preserving uints

// Float -> uint with the same order (negative floats flipped), so atomicMin/Max work on signs.
uint orderedBits(float f) {
  uint u = floatBitsToUint(f);
  return (u & 0x80000000u) != 0u ? ~u : u | 0x80000000u;
}
float fromOrderedBits(uint u) {
  return uintBitsToFloat((u & 0x80000000u) != 0u ? u & 0x7FFFFFFFu : ~u);
}

void main() {
  uint x = gl_LocalInvocationID.x;
  if (x < 3u) {
    s_bounds[x] = 0xFFFFFFFFu;
    s_bounds[x + 3u] = 0u;
  }
  barrier();
  vec3 lo = vec3(3.0e38), hi = vec3(-3.0e38);
  int px = int(gl_WorkGroupID.x * HV_TILE_SIZE + x);
  // A view-space point at view distance z on the ray of NDC (nx, ny) is
  // (nx z / P00, ny z / P11, -z)
  // (centered projection, frame_data.cpp).
  vec2 inv_scale = vec2(1.0 / u_proj[0][0], 1.0 / u_proj[1][1]);
  float ndc_x = (float(px) + 0.5) / float(u_viewport.x) * 2.0 - 1.0;
  if (px < int(u_viewport.x)) {
    for (int j = 0; j < HV_TILE_HEIGHT; ++j) {
      int py = int(gl_WorkGroupID.y * HV_TILE_HEIGHT) + j;
      if (py >= int(u_viewport.y)) break;
      float d = texelFetch(t_depth, ivec2(px, py), 0).r;
      if (d > 0.0) {  // 0 = nothing drawn (background needs no lights)
        float z = u_near_params.x / d;  // reversed-Z infinite: view distance (frame_data.hpp)
        float ndc_y = (float(py) + 0.5) / float(u_viewport.y) * 2.0 - 1.0;
        vec3 p = vec3(ndc_x * inv_scale.x * z, ndc_y * inv_scale.y * z, -z);
        lo = min(lo, p);
        hi = max(hi, p);
      }
    }
  }
  if (lo.x <= hi.x) {
    atomicMin(s_bounds[0], orderedBits(lo.x));
    atomicMin(s_bounds[1], orderedBits(lo.y));
    atomicMin(s_bounds[2], orderedBits(lo.z));
    atomicMax(s_bounds[3], orderedBits(hi.x));
    atomicMax(s_bounds[4], orderedBits(hi.y));
    atomicMax(s_bounds[5], orderedBits(hi.z));
  }
  barrier();
  if (x == 0u) {
    uint tile = gl_WorkGroupID.y * u_viewport.z + gl_WorkGroupID.x;
    bool has_surface = s_bounds[3] != 0u;
    vec3 bmin = vec3(fromOrderedBits(s_bounds[0]), fromOrderedBits(s_bounds[1]),
                     fromOrderedBits(s_bounds[2]));
    vec3 bmax = vec3(fromOrderedBits(s_bounds[3]), fromOrderedBits(s_bounds[4]),
                     fromOrderedBits(s_bounds[5]));
    // Widen by 1e-5 of the distance: the light pass reconstructs positions through
    // inv_view_proj, which may round differently from the view-space formula above.
    vec3 pad = vec3(1e-5 * max(-bmin.z, 1.0));
    tile_bounds[tile * 2u] = vec4(bmin - pad, has_surface ? 1.0 : 0.0);
    tile_bounds[tile * 2u + 1u] = vec4(bmax + pad, 0.0);
  }
}

// ---------------------------------------------------------------------------------------------
#elif HV_CULL_STAGE == HV_CULL_LIGHTS
layout(local_size_x = 64) in;

layout(std430, binding = HV_BINDING_LIGHTS) readonly buffer LightBlock { GpuLight lights[]; };
layout(std430, binding = HV_BINDING_TILE_INDICES) buffer TileIndexBlock {
  uint tile_index_count;
  uint pad0, pad1, pad2;
  uint tile_indices[];
};
layout(location = HV_LOC_CULL_PHASE) uniform uint u_cull_phase;  // 0 = count, 1 = fill

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= u_counts.x) return;
  vec3 c = (u_view * vec4(lights[i].position_radius.xyz, 1.0)).xyz;
  float r = lightCullRadius(lights[i]);
  uint type = uint(lights[i].params.y + 0.5);  // HV_LIGHT_POINT/SPHERE/TUBE = 0/1/2
  if (type > 2u) return;
  ivec4 rect;
  if (!sphereTileRect(c, r, vec2(u_proj[0][0], u_proj[1][1]), u_near_params.x, vec2(u_viewport.xy),
                      ivec2(u_viewport.zw), vec2(HV_TILE_SIZE, HV_TILE_HEIGHT), rect)) {
    return;
  }
  ivec2 t0 = rect.xy, t1 = rect.zw;

  // The rectangle's tiles against the tile surface boxes (exact sphere-box distance). do-while:
  // the exit test at the end of the body, which a SIMD CPU implementation (llvmpipe) would
  // otherwise pay as one more, fully masked iteration per loop entry (t0 <= t1 after the clamps).
  float r2 = r * r;
  int ty = t0.y;
  do {
    int tx = t0.x;
    do {
      uint tile = uint(ty) * u_viewport.z + uint(tx);
      vec4 bmin = tile_bounds[tile * 2u];
      vec3 q = clamp(c, bmin.xyz, tile_bounds[tile * 2u + 1u].xyz);
      // bmin.w = 0: no surface in this tile.
      if (bmin.w != 0.0 && dot(q - c, q - c) <= r2) {
        uint slot = atomicAdd(tile_counters[tile * 3u + type], 1u);
        if (u_cull_phase == 1u && slot < u_counts.y) tile_indices[slot] = i;
      }
    } while (++tx <= t1.x);
  } while (++ty <= t1.y);
}

// ---------------------------------------------------------------------------------------------
#else  // HV_CULL_STAGE == HV_CULL_SCAN
#define HV_SCAN_THREADS 256
layout(local_size_x = HV_SCAN_THREADS) in;

layout(std430, binding = HV_BINDING_TILE_RANGES) writeonly buffer TileRangeBlock { uvec2 tile_ranges[]; };
layout(std430, binding = HV_BINDING_TILE_TYPES) writeonly buffer TileTypeBlock { uvec2 tile_types[]; };
layout(std430, binding = HV_BINDING_TILE_INDICES) buffer TileIndexBlock {
  uint tile_index_count;
  uint pad0, pad1, pad2;
  uint tile_indices[];
};

shared uint s_sums[HV_SCAN_THREADS];

// Each invocation owns a contiguous chunk of tiles: serial sum, a Hillis-Steele scan of the 256
// chunk sums in shared memory, then a serial pass writing the offsets.
void main() {
  uint tid = gl_LocalInvocationID.x;
  uint tiles = u_viewport.z * u_viewport.w;
  uint chunk = (tiles + HV_SCAN_THREADS - 1u) / HV_SCAN_THREADS;
  uint first = min(tid * chunk, tiles), last = min(first + chunk, tiles);
  uint sum = 0u;
  for (uint t = first; t < last; ++t) {
    sum += tile_counters[t * 3u] + tile_counters[t * 3u + 1u] + tile_counters[t * 3u + 2u];
  }
  s_sums[tid] = sum;
  barrier();
  for (uint step = 1u; step < HV_SCAN_THREADS; step <<= 1) {
    uint v = tid >= step ? s_sums[tid - step] : 0u;
    barrier();
    s_sums[tid] += v;
    barrier();
  }
  uint offset = s_sums[tid] - sum;  // exclusive
  for (uint t = first; t < last; ++t) {
    uint n0 = tile_counters[t * 3u], n1 = tile_counters[t * 3u + 1u];
    uint n2 = tile_counters[t * 3u + 2u];
    tile_ranges[t] = uvec2(offset, n0 + n1 + n2);
    tile_types[t] = uvec2(n0, n1);
    tile_counters[t * 3u] = offset;
    tile_counters[t * 3u + 1u] = offset + n0;
    tile_counters[t * 3u + 2u] = offset + n0 + n1;
    offset += n0 + n1 + n2;
  }
  if (tid == HV_SCAN_THREADS - 1u) tile_index_count = s_sums[tid];
}
#endif
