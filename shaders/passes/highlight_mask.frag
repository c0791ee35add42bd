#version 450 core
// 1 where the picked object is what the G-buffer shows: its depth matches the stored one (reversed
// Z: larger is nearer). The tolerance, 0.1% of the depth (of the distance), absorbs the rounding of
// two programs transforming the same vertices; only a surface within 0.1% of the distance behind
// the object could be marked with it.
layout(binding = 0) uniform sampler2D t_depth;
layout(location = 0) out float o_mask;

void main() {
  float stored = texelFetch(t_depth, ivec2(gl_FragCoord.xy), 0).r;
  if (gl_FragCoord.z < stored * 0.999) discard;
  o_mask = 1.0;
}
