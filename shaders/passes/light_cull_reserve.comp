#version 450 core
// Tiled culling in batches (light_cull_common.glsl), once after every batch is counted: each
// group reserves its tiles' entries with one atomicAdd and keeps each tile's write cursors per
// type.
#include "light_cull_walk.glsl"

void main() {
  uvec2 tile = thisTile();
  uvec3 n = uvec3(0u), cursor = uvec3(0u);
  init();
  if (inGrid(tile)) n = tile_state[tileIndex(tile)].xyz;
  cursor = reserve(tile, n);
  if (inGrid(tile)) tile_state[tileIndex(tile)] = uvec4(cursor, 0u);
}
