// Screen-space extent of a light's bounding sphere for tiled culling, shared by the GPU culling
// (shaders/passes/light_cull_bin.comp) and the renderer, which sizes the tile index list from the
// same rectangles on the CPU (engine/render/src/light_cull_pass.cpp) instead of reading the GPU's count
// back mid-frame. Compiled as C++ too (halfvec/shading/glsl.hpp rules).
#ifndef HV_CULL_GLSL
#define HV_CULL_GLSL

#include "math.glsl"
#include "cull_layout.glsl"

// Range of k = x / (-z) (x or y) over a view-space sphere of center (cx, -d) and radius r,
// d > r (entirely in front of the eye): the slopes of the two planes through the eye tangent to
// it, roots of (cx + k cz)^2 = r^2 (1 + k^2) (distance from the center to the plane x = k (-z)
// equal to r; as in Mara & McGuire 2013, "2D Polyhedral Bounds of a Clipped, Perspective-
// Projected 3D Sphere"). A tile column whose planes x = k0 (-z), x = k1 (-z) bound a k interval
// missing this range holds no point of the sphere: exact, not just conservative, in x and y.
vec2 tangentSlopes(float cx, float d, float r) {
  float den = d * d - r * r;
  float root = r * sqrt(max(cx * cx + den, 0.0f));
  return vec2(cx * d - root, cx * d + root) / den;
}

// Tiles (x0, y0, x1, y1), inclusive, of a tiles.x x tiles.y grid of tile_px-pixel tiles over a
// viewport_px frame, that a view-space sphere (center c, radius r) can touch, for a centered
// projection with scale (P00, P11) and near plane `near`. False when it touches none: entirely
// nearer than the near plane or off screen. NDC rectangle exact from the tangent planes
// (tangentSlopes: x = k (-z) maps to ndc_x = k P00) when the sphere lies in front of the eye
// (1e-3 r of margin against rounding in the division); otherwise, the sphere containing or
// touching the eye plane, the whole screen. Widened by 1e-5 in NDC (0.004 px at 720 p) so rounding
// never drops a tile at its border.
bool sphereTileRect(vec3 c, float r, vec2 scale, float near, vec2 viewport_px, ivec2 tiles,
                    vec2 tile_px, HV_OUT(ivec4) rect) {
  float near_z = -c.z - r, far_z = -c.z + r;  // view-distance interval of the sphere
  if (far_z < near) return false;            // every visible point is beyond the near plane
  vec2 ndc_lo = vec2(-1.0f), ndc_hi = vec2(1.0f);
  if (near_z > 1e-3f * r) {
    vec2 kx = tangentSlopes(c.x, -c.z, r), ky = tangentSlopes(c.y, -c.z, r);
    ndc_lo = max(vec2(kx.x, ky.x) * scale - vec2(1e-5f), vec2(-1.0f));
    ndc_hi = min(vec2(kx.y, ky.y) * scale + vec2(1e-5f), vec2(1.0f));
    if (ndc_lo.x > 1.0f || ndc_lo.y > 1.0f || ndc_hi.x < -1.0f || ndc_hi.y < -1.0f) return false;
  }
  ivec2 tmax = tiles - ivec2(1);
  ivec2 t0 = clamp(ivec2(floor((ndc_lo * 0.5f + vec2(0.5f)) * viewport_px / tile_px)), ivec2(0),
                   tmax);
  ivec2 t1 = clamp(ivec2(floor((ndc_hi * 0.5f + vec2(0.5f)) * viewport_px / tile_px)), ivec2(0),
                   tmax);
  rect = ivec4(t0.x, t0.y, t1.x, t1.y);
  return true;
}

// Whether a sphere (center c, radius r) lies entirely outside a spot's lit cone: apex, unit axis,
// outer half-angle theta <= pi/2 (cos_t, sin_t) capped at distance `range` along the axis
// (Wronski 2017, "Cull that cone!"). In the plane of the axis and c, c's signed distance to the
// cone's side line is cos_t |v x axis| - (v . axis) sin_t, v = c - apex; the cone's nearest point
// to c lies on that line's ray or at the apex, so beyond r from the line is beyond r from the
// cone. Past the cap plane (v . axis > r + range) or behind the apex (v . axis < -r, a cone of at
// most a hemisphere lies in front of it) likewise. Conservative: it never culls a sphere that
// meets the cone.
bool sphereOutsideCone(vec3 c, float r, vec3 apex, vec3 axis, float cos_t, float range) {
  vec3 v = c - apex;
  float along = dot(v, axis);
  float across = sqrt(max(dot(v, v) - along * along, 0.0f));
  float sin_t = sqrt(max(1.0f - cos_t * cos_t, 0.0f));
  return cos_t * across - along * sin_t > r || along > r + range || along < -r;
}

#endif
