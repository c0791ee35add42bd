#version 450 core
// The picked object's triangles, as the G-buffer pass places them (gbuffer.vert).
#include "../common/frame.glsl"

layout(location = 0) in vec3 a_position;
layout(location = 0) uniform mat4 u_model;

void main() { gl_Position = u_view_proj * (u_model * vec4(a_position, 1.0)); }
