#version 450 core
// Shadow-map pass (engine/render/src/shadow_pass.cpp): one cube face of a shadowed light.
// HV_SHADOW_ALPHA_MASK 1: the variant for alpha-masked materials (glTF alphaMode MASK), which
// passes on what the fragment stage needs to compute the base colour's alpha (shadow.frag).
#include "../common/bindings.glsl"

#ifndef HV_SHADOW_ALPHA_MASK
#define HV_SHADOW_ALPHA_MASK 0
#endif

layout(location = 0) in vec3 a_position;
#if HV_SHADOW_ALPHA_MASK
layout(location = 3) in vec2 a_uv0;
layout(location = 4) in vec2 a_uv1;
layout(location = 5) in vec4 a_color;  // white where the mesh has no COLOR_0
#endif

layout(location = HV_LOC_MODEL) uniform mat4 u_model;
layout(location = HV_LOC_SHADOW_VIEW_PROJ) uniform mat4 u_face_view_proj;

layout(location = 0) out vec3 v_world;
#if HV_SHADOW_ALPHA_MASK
layout(location = 1) out vec2 v_uv0;
layout(location = 2) out vec2 v_uv1;
layout(location = 3) out float v_alpha;
#endif

void main() {
  vec4 world = u_model * vec4(a_position, 1.0);
  v_world = world.xyz;
#if HV_SHADOW_ALPHA_MASK
  v_uv0 = a_uv0;
  v_uv1 = a_uv1;
  v_alpha = a_color.a;
#endif
  gl_Position = u_face_view_proj * world;
}
