// Spot lights' cone, shared by GLSL and C++ (halfvec/shading/glsl.hpp rules): the angular
// attenuation the light pass and the CPU reference multiply a point or sphere light by, its
// packing into the light record, and the cone's bounding sphere for tiled culling. Definitions
// and units: docs/lights.md, "Spot lights".
#ifndef HV_SPOT_GLSL
#define HV_SPOT_GLSL

#include "math.glsl"

// KHR_lights_punctual, "Inner and Outer Cone Angles" (and its implementation note): with cd the
// cosine between the spot's direction and the direction from the light to the shading point,
//   t = saturate((cd - cos_outer) / (cos_inner - cos_outer)),  attenuation = t^2,
// written as t = saturate(cd * scale + offset), scale = 1 / max(cos_inner - cos_outer, 1e-3),
// offset = -cos_outer * scale, so that the pass does one dot product and one multiply-add. The
// record holds cone = (direction * scale, offset) (spotCone); L: unit, from the shading point
// toward the light. 1 inside the inner cone, exactly 0 outside the outer one.
float spotAttenuation(vec3 L, vec4 cone) {
  float t = saturate(-dot(L, vec3(cone.x, cone.y, cone.z)) + cone.w);
  return t * t;
}

// The cone as spotAttenuation reads it, from the unit direction and the angles' cosines. The
// 1e-3 floor is the specification's own guard against inner = outer.
vec4 spotCone(vec3 direction, float cos_inner, float cos_outer) {
  float scale = 1.0f / max(cos_inner - cos_outer, 1e-3f);
  return vec4(direction * scale, -cos_outer * scale);
}

// The smallest sphere holding the spherical sector that a spot at `apex` of range R lights (the
// cone of half-angle theta_outer, recovered from `cone`, capped by the range sphere), for
// culling; returns (center, radius). For theta <= pi/4 it is the sphere through the apex and the
// cap's rim, radius R / (2 cos theta), centered on the axis; for a wider cone the sphere around
// the rim, radius R sin theta, centered at R cos theta (the apex is then inside it). Both hold
// the whole cap: a cap point at angle phi <= theta lies within the radius because cos phi >=
// cos theta. The sector
// is convex (theta <= pi/2), so holding the apex and the cap holds all of it. The radius is
// widened by 1e-4 R against the rounding of cos theta recovered from the scaled cone.
vec4 spotBoundingSphere(vec3 apex, vec4 cone, float range) {
  vec3 d = vec3(cone.x, cone.y, cone.z);
  float scale = length(d);
  d = d / scale;
  float cos_outer = clamp(-cone.w / scale, 0.0f, 1.0f);
  float sin_outer = sqrt(max(1.0f - cos_outer * cos_outer, 0.0f));
  bool narrow = cos_outer > 0.70710678f;
  float offset = narrow ? range / (2.0f * cos_outer) : range * cos_outer;
  float radius = narrow ? offset : range * sin_outer;
  return vec4(apex + d * offset, radius + 1e-4f * range);
}

#endif
