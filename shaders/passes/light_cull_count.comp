#version 450 core
// Tiled culling in batches (more than HV_CULL_FUSED_MAX_LIGHTS lights; light_cull_common.glsl),
// once per batch after its binning: the group's mask refined per block, each tile's hits of the
// batch counted per type on top of the previous batches' counts, kept per tile.
#include "light_cull_walk.glsl"

void main() {
  uvec2 tile = thisTile();
  uvec3 n = uvec3(0u), cursor = uvec3(0u);
  init();
  if (inGrid(tile) && u_batch.first > 0u) n = tile_state[tileIndex(tile)].xyz;
  refine();
  barrier();
  walk(tile, false, n, cursor);
  if (inGrid(tile)) tile_state[tileIndex(tile)] = uvec4(n, 0u);
}
