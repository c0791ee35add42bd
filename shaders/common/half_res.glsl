// Half-resolution targets read back per pixel (GLSL only): the AO target (ambient.comp, aoAt) and
// the shadow mask (shadow_mask.glsl) hold pixel 2q at texel q, so pixel px sits at px / 2 in
// texel units; both weigh the four nearest texels bilinearly times a depth weight against the
// pixel's own view distance, so that an edge does not take the value of the surface across it.
#ifndef HV_HALF_RES_GLSL
#define HV_HALF_RES_GLSL

// The texel coordinate `uv` at which one textureGather reads the four nearest texels of pixel px
// in a target of `size` texels, b .. b + 1 for b = floor(px / 2) (clamped to the edge as the
// sampler does), and their bilinear weights in gather order (0,1), (1,1), (1,0), (0,0).
void halfResFootprint(ivec2 px, ivec2 size, out vec2 uv, out vec4 wb) {
  vec2 f = vec2(px) * 0.5;
  vec2 b = floor(f);
  vec2 t = f - b;
  uv = (b + 1.0) / vec2(size);
  wb = vec4((1.0 - t.x) * t.y, t.x * t.y, t.x * (1.0 - t.y), (1.0 - t.x) * (1.0 - t.y));
}

// The four texels' relative difference of view distance from the pixel's, from inverse view
// distances (texels `inv`, the pixel `inv_px`): |dist_texel / dist - 1| = |w_pixel - w_texel| /
// w_texel. A texel of no surface (w 0) gets about 1e30: its depth weight is 0.
vec4 halfResDistanceDiff(vec4 inv, float inv_px) {
  return abs(inv - vec4(inv_px)) / max(inv, vec4(1e-30));
}

// The depth weight: 1 at the pixel's own distance, 0 at 5% from it.
vec4 halfResDepthWeight(vec4 diff) { return clamp(1.0 - diff * 20.0, 0.0, 1.0); }

#endif
