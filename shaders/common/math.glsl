// Small math helpers shared by GLSL and C++ (see halfvec/shading/glsl.hpp for the rules).
#ifndef HV_MATH_GLSL
#define HV_MATH_GLSL

#ifndef HV_CPP
#define HV_OUT(T) out T
#define HV_INOUT(T) inout T
#endif

const float PI = 3.14159265358979f;
const float INV_PI = 0.318309886183791f;

float saturate(float x) { return clamp(x, 0.0f, 1.0f); }
vec3 saturate(vec3 x) { return clamp(x, vec3(0.0f), vec3(1.0f)); }
float sq(float x) { return x * x; }
float pow5(float x) {
  float x2 = x * x;
  return x2 * x2 * x;
}

// normalize() that returns (almost) 0 instead of NaN for a zero vector (e.g. the half vector of
// V = -L, or the direction to a light from its own center). 1e-30 is far below any squared length
// that reaches shading (a distance of 1e-6 squares to 1e-12) but above the fp32 denormal range.
vec3 safeNormalize(vec3 v) { return v * inversesqrt(max(dot(v, v), 1e-30f)); }

#endif
