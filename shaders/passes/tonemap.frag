#version 450 core
// Output transform: exposure, Reinhard (per channel c/(1+c), or on luminance), then gamma 2.2 or
// the exact sRGB curve, with optional triangular dither against 8-bit banding.
#include "../common/frame.glsl"
#include "../common/tonemap.glsl"

layout(binding = HV_UNIT_HDR) uniform sampler2D t_hdr;
layout(location = 0) in vec2 v_uv;
layout(location = 0) out vec4 o_color;

void main() {
  ivec2 px = ivec2(gl_FragCoord.xy);
  vec3 hdr = texelFetch(t_hdr, px, 0).rgb;
  vec3 c = outputTransform(hdr * u_output.x);
  c += (ditherNoise(vec2(px)) / 255.0) * u_output.y;
  o_color = vec4(clamp(c, 0.0, 1.0), 1.0);
}
