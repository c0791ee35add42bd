#version 450 core
// Post-process anti-aliasing of the tone-mapped image: FXAA as in Lottes 2009, "FXAA" (NVIDIA
// whitepaper), in the form of its 3.11 "console" variant (Lottes 2011): the luma of the four
// diagonal neighbors gives the local edge direction; two and four taps along that direction are
// averaged, and the four-tap average is kept unless its luma leaves the neighborhood's range.
// Pixels whose neighborhood has a luma range below the edge threshold are copied unchanged, so a
// flat image (and the +-1/255 dither) passes through bit for bit. Constants: common/fxaa.glsl.
#include "../common/fxaa.glsl"

layout(binding = 0) uniform sampler2D t_ldr;  // display-encoded RGBA8, bilinear, clamped
layout(location = 0) out vec4 o_color;

// Luma of the texel at `px` + `offset`, clamped to the image (north = +y).
float lumaAt(ivec2 px, ivec2 offset) {
  ivec2 p = clamp(px + offset, ivec2(0), textureSize(t_ldr, 0) - 1);
  return fxaaLuma(texelFetch(t_ldr, p, 0).rgb);
}

void main() {
  ivec2 px = ivec2(gl_FragCoord.xy);
  vec2 texel = 1.0 / vec2(textureSize(t_ldr, 0));
  vec2 uv = gl_FragCoord.xy * texel;
  vec3 m = texelFetch(t_ldr, px, 0).rgb;
  float l_nw = lumaAt(px, ivec2(-1, 1)), l_ne = lumaAt(px, ivec2(1, 1));
  float l_sw = lumaAt(px, ivec2(-1, -1)), l_se = lumaAt(px, ivec2(1, -1));
  float l_m = fxaaLuma(m);
  float l_min = min(l_m, min(min(l_nw, l_ne), min(l_sw, l_se)));
  float l_max = max(l_m, max(max(l_nw, l_ne), max(l_sw, l_se)));
  if (!fxaaIsEdge(l_min, l_max)) {
    o_color = vec4(m, 1.0);
    return;
  }
  vec2 dir = fxaaDirection(l_nw, l_ne, l_sw, l_se) * texel;
  vec3 a = 0.5 * (texture(t_ldr, uv + dir * (1.0 / 3.0 - 0.5)).rgb +
                  texture(t_ldr, uv + dir * (2.0 / 3.0 - 0.5)).rgb);
  vec3 b = 0.5 * a + 0.25 * (texture(t_ldr, uv - dir * 0.5).rgb + texture(t_ldr, uv + dir * 0.5).rgb);
  float l_b = fxaaLuma(b);
  o_color = vec4((l_b < l_min || l_b > l_max) ? a : b, 1.0);
}
