#version 450 core
// Shadow-map pass: stores the distance from the light's center over its far distance (the
// culling radius), linear, so that every face and every filter compares distances (shadows.glsl).
#include "../common/bindings.glsl"

layout(location = HV_LOC_SHADOW_LIGHT) uniform vec4 u_light;  // xyz light center, w 1 / far

layout(location = 0) in vec3 v_world;

void main() {
  gl_FragDepth = length(v_world - u_light.xyz) * u_light.w;
}
