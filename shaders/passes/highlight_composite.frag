#version 450 core
// The picked object's highlight over the tone-mapped output (alpha blended): an orange tint over
// its visible pixels and a 2-pixel orange outline around them.
layout(binding = 0) uniform sampler2D t_mask;
layout(location = 0) out vec4 o_color;

const vec3 kHighlight = vec3(1.0, 0.55, 0.1);

void main() {
  ivec2 px = ivec2(gl_FragCoord.xy);
  ivec2 last = textureSize(t_mask, 0) - 1;
  if (texelFetch(t_mask, px, 0).r > 0.5) {
    o_color = vec4(kHighlight, 0.12);
    return;
  }
  // Outline: a masked pixel within 2 pixels (8 taps on a ring of radius 2, and the 4 direct
  // neighbors, so thin parts are caught too).
  const ivec2 taps[12] = ivec2[](ivec2(-2, 0), ivec2(2, 0), ivec2(0, -2), ivec2(0, 2), ivec2(-1, -1),
                                 ivec2(1, -1), ivec2(-1, 1), ivec2(1, 1), ivec2(-1, 0), ivec2(1, 0),
                                 ivec2(0, -1), ivec2(0, 1));
  float near = 0.0;
  for (int i = 0; i < 12; ++i) near = max(near, texelFetch(t_mask, clamp(px + taps[i], ivec2(0), last), 0).r);
  if (near < 0.5) discard;
  o_color = vec4(kHighlight, 1.0);
}
