// Small math helpers shared by GLSL and C++ (see engine/shading/glsl.hpp for the rules).
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

#endif
