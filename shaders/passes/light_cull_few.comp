#version 450 core
// Tiled culling of at most HV_CULL_FEW_MAX_LIGHTS lights in one dispatch (light_cull_common.glsl),
// in place of the bounds, binning and walk stages: each invocation of a group first computes one
// light's record (cullLightRecord, the binning stage's) into shared memory; then each invocation,
// one tile, tests the tile's surface AABB (tileBounds, the bounds stage's) against every light
// (lightTouchesTile, the walk's test), counts the hits per type, reserves with its group (reserve)
// and writes its list: points, then spheres, then tubes, each in light order. The staged path's
// group and block tests only skip lights that this test rejects, so both write the same lists;
// with a handful of lights there is nothing for those tests to save (docs/performance.md, "Culling
// a handful of lights"). The list's total must be 0 before the dispatch: the renderer clears it.
#include "light_cull_light.glsl"
#include "light_cull_tile_bounds.glsl"

#if HV_CULL_FEW_MAX_LIGHTS > HV_CULL_GROUP_SIZE || HV_CULL_FEW_MAX_LIGHTS > 64
#error "one light record per invocation of a group, the hits in two mask words"
#endif

layout(local_size_x = HV_CULL_GROUP_SIZE) in;

shared CullLight s_lights[HV_CULL_FEW_MAX_LIGHTS];

// Writes the lights of `hits` (bit k: light base + k), lowest first, each at its type's cursor.
void writeHits(uint hits, uint base, inout uvec3 cursor) {
  while (hits != 0u) {
    uint i = base + uint(findLSB(hits));
    hits &= hits - 1u;
    uint type = s_lights[i].rect.z;
    uint slot = type == 0u ? cursor.x : (type == 1u ? cursor.y : cursor.z);
    if (slot < u_tile_capacity) tile_indices[slot] = i;
    cursor += uvec3(type == 0u, type == 1u, type == 2u);
  }
}

void main() {
  uint t = gl_LocalInvocationIndex;
  uint count = u_batch.end;  // one batch: lights [0, end)
  if (t == 0u) s_group_total = 0u;
  if (t < count) s_lights[t] = cullLightRecord(t);
  barrier();
  uvec2 tile = thisTile();
  vec3 lo = vec3(3.0e38), hi = vec3(-3.0e38);
  if (inGrid(tile)) tileBounds(tile, lo, hi);
  bool has_surface = lo.x <= hi.x;
  // Every light against the tile, once: the hits kept as bits for the write below. The loop's
  // count is the same for every invocation (no divergence).
  uvec3 n = uvec3(0u);
  uint hits_lo = 0u, hits_hi = 0u;
  for (uint i = 0u; i < count; ++i) {
    bool hit = has_surface && lightTouchesTile(s_lights[i].sphere, s_lights[i].rect.xy,
                                               s_lights[i].cone_apex, s_lights[i].cone_axis,
                                               tile, lo, hi);
    uint type = s_lights[i].rect.z;
    n += uvec3(type == 0u, type == 1u, type == 2u) * uint(hit);
    uint bit = hit ? 1u << (i % 32u) : 0u;
    hits_lo |= i < 32u ? bit : 0u;
    hits_hi |= i < 32u ? 0u : bit;
  }
  uvec3 cursor = reserve(tile, n);
  writeHits(hits_lo, 0u, cursor);
  writeHits(hits_hi, 32u, cursor);
}
