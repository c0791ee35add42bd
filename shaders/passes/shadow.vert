#version 450 core
// Shadow-map pass (engine/render/src/shadow_pass.cpp): one cube face of a shadowed light.
#include "../common/bindings.glsl"

layout(location = 0) in vec3 a_position;

layout(location = HV_LOC_MODEL) uniform mat4 u_model;
layout(location = HV_LOC_SHADOW_VIEW_PROJ) uniform mat4 u_face_view_proj;

layout(location = 0) out vec3 v_world;

void main() {
  vec4 world = u_model * vec4(a_position, 1.0);
  v_world = world.xyz;
  gl_Position = u_face_view_proj * world;
}
