// Tiled culling: a tile's view-space surface AABB from the depth buffer, for the stages that
// compute it (light_cull_bounds.comp; light_cull_few.comp).
#ifndef HV_LIGHT_CULL_TILE_BOUNDS_GLSL
#define HV_LIGHT_CULL_TILE_BOUNDS_GLSL

#include "light_cull_common.glsl"

layout(binding = HV_UNIT_DEPTH) uniform sampler2D t_depth;

// Adds the view-space point of depth d at NDC (ndc_x, ndc_y) to the AABB (lo, hi), unless d = 0
// (nothing drawn: background needs no lights). A point at view distance z on the ray of NDC
// (nx, ny) is (nx z / P00, ny z / P11, -z) (centered projection, frame_data.cpp). Branch-free (a
// SIMD implementation runs both sides of a branch).
void addPoint(float d, float ndc_x, float ndc_y, vec2 inv_scale, inout vec3 lo, inout vec3 hi) {
  float z = u_frame_params.x / d;  // reversed-Z infinite: view distance (frame_data.hpp)
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
// four (the footprint of linear filtering), a quarter of the fetches of texelFetch (its cost:
// docs/lights.md, "Tiled culling"). Past the viewport's edge the
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

#endif
