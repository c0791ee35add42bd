#version 450 core
// G-buffer vertex stage. The tangent, the second UV set and the vertex colour are passed on only
// when the material variant reads them (common/material_features.glsl).
#include "../common/frame.glsl"
#include "../common/material_features.glsl"

layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec4 a_tangent;
layout(location = 3) in vec2 a_uv0;
layout(location = 4) in vec2 a_uv1;
layout(location = 5) in vec4 a_color;  // white where the mesh has no COLOR_0

layout(location = HV_LOC_MODEL) uniform mat4 u_model;
layout(location = HV_LOC_NORMAL_MATRIX) uniform mat4 u_normal_matrix;  // inverse transpose of u_model

layout(location = 0) out vec3 v_normal;
#if HV_MAT_NORMAL_MAP || HV_MAT_CLEAR_COAT_MAPS
layout(location = 1) out vec4 v_tangent;
#endif
layout(location = 2) out vec2 v_uv0;
#if HV_MAT_UV1
layout(location = 3) out vec2 v_uv1;
#endif
#if HV_MAT_VERTEX_COLOR
layout(location = 4) out vec4 v_color;
#endif
layout(location = 5) out vec3 v_to_camera;  // world: the fragment to the camera

void main() {
  vec4 world = u_model * vec4(a_position, 1.0);
  v_normal = mat3(u_normal_matrix) * a_normal;
  v_to_camera = u_camera_pos.xyz - world.xyz;
#if HV_MAT_NORMAL_MAP || HV_MAT_CLEAR_COAT_MAPS
  v_tangent = vec4(mat3(u_model) * a_tangent.xyz, a_tangent.w);
#endif
  v_uv0 = a_uv0;
#if HV_MAT_UV1
  v_uv1 = a_uv1;
#endif
#if HV_MAT_VERTEX_COLOR
  v_color = a_color;
#endif
  gl_Position = u_view_proj * world;
}
