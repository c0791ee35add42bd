#version 450 core
// Tiled culling, third stage, up to HV_CULL_FUSED_MAX_LIGHTS lights (light_cull_common.glsl):
// one workgroup per group of tiles refines the group's mask per block, then every tile walks its
// block's mask twice, counting, then (after one reservation per group) writing its list
// (light_cull_walk.glsl).
#include "light_cull_walk.glsl"

void main() {
  uvec2 tile = thisTile();
  uvec3 n = uvec3(0u), cursor = uvec3(0u);
  init();
  refine();
  barrier();
  walk(tile, false, n, cursor);
  cursor = reserve(tile, n);
  walk(tile, true, n, cursor);
}
