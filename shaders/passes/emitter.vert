#version 450 core
// Sphere and tube lights as their emitting surfaces: a capsule template (unit-sphere direction
// with the axis along +Y; w = +1 upper half, -1 lower half) scaled by the radius, turned onto the
// light's axis and split by its half length. Radiance from common/emitter.glsl.
#include "../common/frame.glsl"
#include "../common/emitter.glsl"

layout(location = 0) in vec4 a_template;
layout(location = 1) in vec4 i_center_radius;
layout(location = 2) in vec4 i_axis_half_length;
layout(location = 3) in vec4 i_color_intensity;

layout(location = 0) flat out vec3 v_radiance;

void main() {
  vec3 axis = i_axis_half_length.xyz;
  vec3 t = abs(axis.y) < 0.999 ? normalize(cross(axis, vec3(0.0, 1.0, 0.0))) : vec3(1.0, 0.0, 0.0);
  vec3 b = cross(t, axis);  // (t, axis, b) is a rotation: the template's winding is kept
  vec3 d = a_template.xyz;
  vec3 p = i_center_radius.xyz + i_center_radius.w * (t * d.x + axis * d.y + b * d.z) +
           axis * (a_template.w * i_axis_half_length.w);
  vec3 radiance = emitterRadiance(i_color_intensity.rgb, i_center_radius.w, 2.0 * i_axis_half_length.w);
  v_radiance = min(radiance, vec3(HV_HDR_MAX));  // the RGBA16F target's largest finite value
  gl_Position = u_view_proj * vec4(p, 1.0);
}
