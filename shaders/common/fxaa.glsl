// FXAA's per-pixel decisions (Lottes 2009, "FXAA", NVIDIA whitepaper; 3.11 console variant, 2011),
// shared with C++ so tests check them: luma, edge test, edge direction.
#ifndef HV_FXAA_GLSL
#define HV_FXAA_GLSL

#include "math.glsl"

// Smallest luma range treated as an edge, absolute (dark areas) and relative to the local
// maximum: Lottes's "edge threshold min" 1/32 and "edge threshold" 1/8 (the quality presets'
// middle values). 1/32 is 8 codes of an 8-bit image: the dither (+-1 code) never triggers it.
#define HV_FXAA_EDGE_MIN 0.03125f
#define HV_FXAA_EDGE_REL 0.125f
// Direction normalization: the smaller component is scaled to about 1 texel (FXAA_REDUCE_MIN 1/128
// keeps it finite on faint edges, FXAA_REDUCE_MUL 1/8 damps it on bright ones) and the taps reach at
// most HV_FXAA_SPAN_MAX texels along the edge.
#define HV_FXAA_REDUCE_MIN (1.0f / 128.0f)
#define HV_FXAA_REDUCE_MUL (1.0f / 8.0f)
#define HV_FXAA_SPAN_MAX 8.0f

// Luma of a display-encoded color (Rec. 601 weights, as FXAA computes it on gamma-space values).
float fxaaLuma(vec3 c) { return dot(c, vec3(0.299f, 0.587f, 0.114f)); }

bool fxaaIsEdge(float l_min, float l_max) {
  return l_max - l_min >= max(HV_FXAA_EDGE_MIN, l_max * HV_FXAA_EDGE_REL);
}

// Direction along the edge, in texels, from the lumas of the diagonal neighbors, north = +y (up in
// GL window coordinates): perpendicular to the luma gradient (E - W, N - S), i.e. (N - S, W - E).
vec2 fxaaDirection(float l_nw, float l_ne, float l_sw, float l_se) {
  vec2 dir = vec2((l_nw + l_ne) - (l_sw + l_se), (l_nw + l_sw) - (l_ne + l_se));
  float reduce = max((l_nw + l_ne + l_sw + l_se) * (0.25f * HV_FXAA_REDUCE_MUL), HV_FXAA_REDUCE_MIN);
  float scale = 1.0f / (min(abs(dir.x), abs(dir.y)) + reduce);
  return clamp(dir * scale, vec2(-HV_FXAA_SPAN_MAX), vec2(HV_FXAA_SPAN_MAX));
}

#endif
