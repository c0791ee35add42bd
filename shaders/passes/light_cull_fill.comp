#version 450 core
// Tiled culling in batches (light_cull_common.glsl), once per batch after its binning again: the
// group's mask refined per block, each tile's hits of the batch written at its cursors, which
// advance.
#include "light_cull_walk.glsl"

void main() {
  uvec2 tile = thisTile();
  uvec3 n = uvec3(0u), cursor = uvec3(0u);
  init();
  if (inGrid(tile)) cursor = tile_state[tileIndex(tile)].xyz;
  refine();
  barrier();
  walk(tile, true, n, cursor);
  if (inGrid(tile)) tile_state[tileIndex(tile)] = uvec4(cursor, 0u);
}
