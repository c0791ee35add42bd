// What a sphere or tube light looks like when the camera sees it: its emitting surface, a
// Lambertian emitter of uniform radiance (docs/lights.md, "Units and physical definitions").
#ifndef HV_EMITTER_GLSL
#define HV_EMITTER_GLSL

#include "math.glsl"

// Radiance of the surface of a light of radiant intensity `color_intensity` (color * I, W/sr per
// unit color): a sphere of radius r (len = 0) has L = I / (pi r^2); a capsule of radius r around a
// segment of length len has L = I / (pi r^2 + pi r len / 2) (its power, L pi times its area,
// equals 4 pi I). Zero for a zero radius (a point or line light has no surface to show).
vec3 emitterRadiance(vec3 color_intensity, float radius, float len) {
  if (radius <= 0.0f) return vec3(0.0f);
  return color_intensity / (PI * radius * radius + 0.5f * PI * radius * len);
}

#endif
