#version 450 core
// Tiled light culling (Andersson 2011, "DirectX 11 Rendering in Battlefield 3"): one workgroup per
// 16x16 tile finds the tile's depth range, tests every light's bounding sphere against the tile's
// view-space frustum and its AABB, and appends the survivors to one global index list.
// Two passes over the lights (count, then write) so the list is exactly sized per tile; if the
// global list overflows, the renderer grows it and runs this pass again (no fixed per-tile cap).
#include "../common/frame.glsl"
#include "../common/lights.glsl"

layout(local_size_x = HV_TILE_SIZE, local_size_y = HV_TILE_SIZE) in;

layout(binding = 3) uniform sampler2D t_depth;

layout(std430, binding = HV_BINDING_LIGHTS) readonly buffer LightBlock { GpuLight lights[]; };
layout(std430, binding = HV_BINDING_TILE_RANGES) writeonly buffer TileRangeBlock { uvec2 tile_ranges[]; };
layout(std430, binding = HV_BINDING_TILE_INDICES) buffer TileIndexBlock {
  uint tile_index_count;  // total appended (may exceed capacity: the renderer then grows the list)
  uint pad0, pad1, pad2;
  uint tile_indices[];
};

shared uint s_min_depth;  // reversed-Z: min = farthest
shared uint s_max_depth;  // max = nearest
shared uint s_count;
shared uint s_offset;
shared uint s_slot;

// View-space distance along -z of reversed-Z infinite depth d (see frame_data.hpp).
float viewDistance(float d) { return u_near_params.x / max(d, 1e-30); }

void main() {
  uint tid = gl_LocalInvocationIndex;
  ivec2 px = ivec2(gl_GlobalInvocationID.xy);
  if (tid == 0u) {
    s_min_depth = floatBitsToUint(1.0);
    s_max_depth = 0u;
    s_count = 0u;
    s_slot = 0u;
  }
  barrier();
  if (px.x < int(u_viewport.x) && px.y < int(u_viewport.y)) {
    float d = texelFetch(t_depth, px, 0).r;
    if (d > 0.0) {  // 0 = nothing drawn (background needs no lights)
      atomicMin(s_min_depth, floatBitsToUint(d));  // positive floats order as their bits
      atomicMax(s_max_depth, floatBitsToUint(d));
    }
  }
  barrier();
  uint tile = gl_WorkGroupID.y * u_viewport.z + gl_WorkGroupID.x;
  bool empty = s_max_depth == 0u;
  float z_near = viewDistance(uintBitsToFloat(s_max_depth));
  float z_far = viewDistance(uintBitsToFloat(s_min_depth));

  // Tile side planes through the eye, in view space, from the projection's NDC bounds.
  vec2 ndc0 = vec2(gl_WorkGroupID.xy * HV_TILE_SIZE) / vec2(u_viewport.xy) * 2.0 - 1.0;
  vec2 ndc1 = vec2((gl_WorkGroupID.xy + 1u) * HV_TILE_SIZE) / vec2(u_viewport.xy) * 2.0 - 1.0;
  // A view-space point at distance 1 projects to ndc = (P00 x, P11 y); invert for the corners.
  vec2 inv_scale = vec2(1.0 / u_proj[0][0], 1.0 / u_proj[1][1]);
  vec3 c00 = vec3(ndc0 * inv_scale, -1.0);
  vec3 c11 = vec3(ndc1 * inv_scale, -1.0);
  vec3 c01 = vec3(ndc0.x * inv_scale.x, ndc1.y * inv_scale.y, -1.0);
  vec3 c10 = vec3(ndc1.x * inv_scale.x, ndc0.y * inv_scale.y, -1.0);
  vec3 planes[4];
  planes[0] = normalize(cross(c00, c01));  // left: (1, 0, x0), normals point into the tile
  planes[1] = normalize(cross(c11, c10));  // right: (-1, 0, -x1)
  planes[2] = normalize(cross(c10, c00));  // bottom: (0, 1, y0)
  planes[3] = normalize(cross(c01, c11));  // top: (0, -1, -y1)
  // AABB of the tile frustum between z_near and z_far (tightens the corners the planes miss).
  vec3 bmin = min(min(c00 * z_near, c11 * z_near), min(c00 * z_far, c11 * z_far));
  vec3 bmax = max(max(c00 * z_near, c11 * z_near), max(c00 * z_far, c11 * z_far));

  uint n = u_counts.x;
  for (int phase = 0; phase < 2; ++phase) {
    uint local = 0u;
    for (uint i = tid; i < n && !empty; i += HV_TILE_SIZE * HV_TILE_SIZE) {
      vec3 c = (u_view * vec4(lights[i].position_radius.xyz, 1.0)).xyz;
      float r = lightCullRadius(lights[i]);
      bool hit = -c.z + r >= z_near && -c.z - r <= z_far;
      for (int p = 0; p < 4; ++p) hit = hit && dot(planes[p], c) > -r;
      vec3 q = clamp(c, bmin, bmax);
      hit = hit && dot(q - c, q - c) <= r * r;
      if (hit) {
        if (phase == 0) {
          ++local;
        } else {
          uint slot = s_offset + atomicAdd(s_slot, 1u);
          if (slot < u_counts.y) tile_indices[slot] = i;
        }
      }
    }
    if (phase == 0) {
      if (local > 0u) atomicAdd(s_count, local);
      barrier();
      if (tid == 0u) {
        s_offset = atomicAdd(tile_index_count, s_count);
        tile_ranges[tile] = uvec2(s_offset, s_count);
      }
      barrier();
    }
  }
}
