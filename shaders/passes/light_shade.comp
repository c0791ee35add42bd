#version 450 core
// Light pass: for each lit pixel, sums the direct light of its tile's lights (or of every light in
// the brute-force baseline) into the HDR target, on top of the emissive the G-buffer pass wrote.
// A tile's list is sorted by light type (light_cull_walk.glsl), so the tiled path runs one loop per
// type calling that type's evaluation directly: no per-light branch on the type, whose three
// arms a SIMD CPU implementation (llvmpipe) would otherwise all execute under a mask. (A per-pixel
// range test does not pay there either: an `if` costs its body even when no lane takes it; only
// loop exits are real jumps. The tile lists are the early-out.)
#include "../common/frame.glsl"
#include "../common/gbuffer.glsl"
#include "../common/lights.glsl"
#include "../common/clear_coat.glsl"
// `shadow_resolution: half`: the shadowed lights' visibility from the shadow mask pass.
#if HV_SHADOWS && HV_SHADOW_RESOLUTION == HV_SHADOW_RESOLUTION_HALF
#define HV_SHADOW_MASK 1
#else
#define HV_SHADOW_MASK 0
#endif
#if HV_SHADOW_MASK
#include "../common/shadow_mask.glsl"
#endif

// HV_HAS_CLEAR_COAT 1|0: a clear_coat material is drawn. Its pixels shade every light twice, the
// base (scaled by coatBaseScale) and the coat's lobe (clear_coat.glsl); an invocation with no
// such pixel skips the second evaluation.
#ifndef HV_HAS_CLEAR_COAT
#define HV_HAS_CLEAR_COAT 1
#endif

// Each invocation shades HV_LIGHT_PIXELS pixels of a tile column (HV_TILE_HEIGHT must be a
// multiple): a light's data is fetched once and evaluated for all of them, so the fetch (a gather
// per lane on llvmpipe, a load on a GPU) is paid once per HV_LIGHT_PIXELS evaluations. A
// workgroup covers HV_LIGHT_GROUP_TILES tiles stacked vertically (frame.glsl), one tile per
// HV_TILE_HEIGHT / HV_LIGHT_PIXELS invocation rows, each tile with its own light list. With the
// defaults, an 8 x 4 tile is one row of 8 invocations (one SIMD row on llvmpipe) and a workgroup
// 8 x 8 invocations (docs/lights.md, "Light pass").
#ifndef HV_LIGHT_PIXELS
#define HV_LIGHT_PIXELS 4
#endif
#define HV_LIGHT_ROWS_PER_TILE (HV_TILE_HEIGHT / HV_LIGHT_PIXELS)
layout(local_size_x = HV_TILE_SIZE, local_size_y = HV_LIGHT_ROWS_PER_TILE * HV_LIGHT_GROUP_TILES) in;

layout(binding = HV_UNIT_BASE_CAVITY) uniform sampler2D t_base_cavity;
layout(binding = HV_UNIT_MATERIAL) uniform sampler2D t_material;
layout(binding = HV_UNIT_NORMAL) uniform sampler2D t_normal;
layout(binding = HV_UNIT_DEPTH) uniform sampler2D t_depth;
#if HV_HAS_CLEAR_COAT
layout(binding = HV_UNIT_COAT) uniform sampler2D t_coat;
#endif
layout(rgba16f, binding = HV_IMAGE_HDR) uniform image2D i_hdr;

layout(std430, binding = HV_BINDING_LIGHTS) readonly buffer LightBlock { GpuLight lights[]; };
#ifndef HV_LIGHTS_TEXTURE
#define HV_LIGHTS_TEXTURE 0
#endif
#if !HV_CULLING_BRUTE_FORCE
layout(std430, binding = HV_BINDING_TILE_RANGES) readonly buffer TileRangeBlock { uvec2 tile_ranges[]; };
layout(std430, binding = HV_BINDING_TILE_TYPES) readonly buffer TileTypeBlock { uvec2 tile_types[]; };
layout(std430, binding = HV_BINDING_TILE_INDICES) readonly buffer TileIndexBlock {
  uint tile_index_count;
  uint pad0, pad1, pad2;
  uint tile_indices[];
};
#endif

#if !HV_CULLING_BRUTE_FORCE
#if HV_LIGHTS_TEXTURE
// The same two buffers as buffer textures (light_pass.cpp): texelFetch is a vector gather on
// llvmpipe, an SSBO read at a loaded index is one load per lane (about 3x slower loop there).
// The light texels are fetched as uints and reinterpreted: the record's uint fields (type,
// shadow_cube) are small integers, denormal bit patterns as floats, which a float fetch need not
// preserve; uintBitsToFloat restores every float field bit for bit.
layout(binding = HV_UNIT_LIGHT_TEXELS) uniform usamplerBuffer t_lights;       // 4 RGBA32UI texels per GpuLight
layout(binding = HV_UNIT_TILE_INDEX_TEXELS) uniform usamplerBuffer t_tile_indices;  // header (4 uints), then indices
GpuLight tileLight(uint i) {
  int base = int(texelFetch(t_tile_indices, int(i) + HV_TILE_LIST_HEADER_UINTS).r) * 4;
  GpuLight l;
  l.position_radius = uintBitsToFloat(texelFetch(t_lights, base));
  l.color_inv_range = uintBitsToFloat(texelFetch(t_lights, base + 1));
  l.axis_length = uintBitsToFloat(texelFetch(t_lights, base + 2));
  uvec4 last = texelFetch(t_lights, base + 3);  // range, type, cull_radius, shadow_cube
  l.range = uintBitsToFloat(last.x);
  l.type = last.y;
  l.cull_radius = uintBitsToFloat(last.z);
  l.shadow_cube = last.w;
  return l;
}
#else
GpuLight tileLight(uint i) { return lights[tile_indices[i]]; }
#endif
#endif

// Benchmark probes (render::LightPassProbe, `halfvec bench --breakdown`); 0 = the real pass. Both
// probes start every pixel's sum at setupProbeValue (probes.glsl), a function of every field of
// the per-pixel setup, so the setup they include is really computed (the compiler drops what is
// not stored). 1: the same loops and light fetches with no shading: each light adds its
// premultiplied color (times step(0, radius) and, for tubes, step(0, length), both 1, so that
// every texel the real evaluation reads is read). 2: no light loop. Both render wrong images by
// design; LightPass.BenchmarkProbesDoWhatTheyMeasure checks each stored value.
#ifndef HV_LIGHT_PROBE
#define HV_LIGHT_PROBE 0
#endif
#if HV_LIGHT_PROBE == 1 || HV_LIGHT_PROBE == 2
#include "../common/probes.glsl"
#endif
#if HV_LIGHT_PROBE == 3
// The predicted_error view (hv::DebugView::PredictedError, HV_SPHERE_BUDGET compiled in): per
// pixel, x = the sum over its lights of the budget's predicted error of the representative point
// (sphereLightPredictedError), y = the sum of their radiance, both in luminance, shadows left out;
// lights the budget does not judge (points, tubes) add their radiance with no error. The debug
// view pass (debug_view.frag) shows x / y.
#define HV_EVAL_POINT(l, S, SP, j) vec3(0.0, dot(evaluatePointLightAt(l, S[j], SP[j]), HV_ERR_LUMA), 0.0)
#define HV_EVAL_SPHERE(l, S, SP, j) vec3(sphereLightPredictedError(l, S[j], SP[j]), 0.0)
#define HV_EVAL_TUBE(l, S, SP, j) vec3(0.0, dot(evaluateTubeLightAt(l, S[j], SP[j]), HV_ERR_LUMA), 0.0)
#define HV_EVAL_DIRECTIONAL(l, S, SP, j) vec3(directionalLightPredictedError(l, S[j], SP[j]), 0.0)
// The brute-force loop's lights, of any type.
vec3 probeAnyLight(GpuLight l, Surface s, ShadingPoint sp) {
  int type = lightType(l);
  vec3 r = vec3(0.0, dot(evaluateLightAt(l, s, sp), HV_ERR_LUMA), 0.0);
#if HV_HAS_SPHERE_LIGHTS
  if (type == HV_LIGHT_SPHERE) r = vec3(sphereLightPredictedError(l, s, sp), 0.0);
#endif
#if HV_HAS_DIRECTIONAL_LIGHTS
  if (type == HV_LIGHT_DIRECTIONAL) r = vec3(directionalLightPredictedError(l, s, sp), 0.0);
#endif
  return r;
}
#elif HV_LIGHT_PROBE == 1
vec3 probeLight(GpuLight l) { return l.color_inv_range.rgb * step(0.0, l.position_radius.w); }
#define HV_EVAL_POINT(l, S, SP, j) probeLight(l)
#define HV_EVAL_SPHERE(l, S, SP, j) probeLight(l)
#define HV_EVAL_TUBE(l, S, SP, j) (probeLight(l) * step(0.0, l.axis_length.w))
#define HV_EVAL_DIRECTIONAL(l, S, SP, j) probeLight(l)
#elif HV_SHADOWS
// Shadowed lights (shadows.glsl): each light's radiance times its visibility at the
// invocation's pixels, computed for all of them at once (HV_SHADOW_OF, before the pixel loop);
// a light without a map (shadow_cube = 0) costs the test only. With `shadow_resolution: half`
// the visibility is the shadow mask pass's, resolved to every pixel (shadow_mask.glsl).
#if HV_SHADOW_RECEIVERS != HV_LIGHT_PIXELS
#error "shadowVisibility takes one receiver per pixel of the invocation"
#endif
#if HV_SHADOW_MASK
#define HV_SHADOW_OF(l) vec4 vis = shadowMaskVisibility(l, mask_px)
#define HV_SUN_SHADOW_OF(l) HV_SHADOW_OF(l)
#else
#define HV_SHADOW_OF(l) vec4 vis = lightShadow(l, shadow_P, shadow_N, bvec4(lit[0], lit[1], lit[2], lit[3]))
#define HV_SUN_SHADOW_OF(l) \
  vec4 vis = sunShadowVisibility(float(l.shadow_cube) - 1.0f, shadow_P, shadow_N, bvec4(lit[0], lit[1], lit[2], lit[3]))
#endif
#define HV_EVAL_POINT(l, S, SP, j) (evaluatePointLightAt(l, S[j], SP[j]) * vis[j])
#define HV_EVAL_SPHERE(l, S, SP, j) (evaluateSphereLightAt(l, S[j], SP[j]) * vis[j])
#define HV_EVAL_TUBE(l, S, SP, j) (evaluateTubeLightAt(l, S[j], SP[j]) * vis[j])
#define HV_EVAL_DIRECTIONAL(l, S, SP, j) (evaluateDirectionalLightAt(l, S[j], SP[j]) * vis[j])
#else
#define HV_EVAL_POINT(l, S, SP, j) evaluatePointLightAt(l, S[j], SP[j])
#define HV_EVAL_SPHERE(l, S, SP, j) evaluateSphereLightAt(l, S[j], SP[j])
#define HV_EVAL_TUBE(l, S, SP, j) evaluateTubeLightAt(l, S[j], SP[j])
#define HV_EVAL_DIRECTIONAL(l, S, SP, j) evaluateDirectionalLightAt(l, S[j], SP[j])
#endif

// One light's radiance added at the invocation's pixels: the base's into sum, and with clear
// coat the coat lobe's into coat_sum where some pixel has a coat.
#if HV_HAS_CLEAR_COAT
#define HV_ACCUMULATE(EVAL, l)                                                      \
  for (int j = 0; j < HV_LIGHT_PIXELS; ++j) sum[j] += EVAL(l, s, sp, j);           \
  if (any_coat) {                                                                  \
    for (int j = 0; j < HV_LIGHT_PIXELS; ++j) coat_sum[j] += EVAL(l, cs, csp, j);  \
  }
#else
#define HV_ACCUMULATE(EVAL, l) \
  for (int j = 0; j < HV_LIGHT_PIXELS; ++j) sum[j] += EVAL(l, s, sp, j);
#endif

#ifndef HV_SHADOW_OF
#define HV_SHADOW_OF(l)
#endif
#if HV_SHADOWS && HV_LIGHT_PROBE == 0
#define HV_VIS(j) vis[j]
#else
#define HV_VIS(j) 1.0
#endif
// The sphere and tube loops in two parts (HV_SPLIT_LOOP, below) in the tiled pass when it shades:
// spheres with an error budget, the representative point everywhere and the LTC where the budget
// asks for it; spheres and tubes with `ltc`, the whole light everywhere and the cut at the
// horizon where the light straddles it (lights.glsl).
#define HV_SPHERE_SPLIT_LOOPS                                                                \
  ((HV_SPHERE_BUDGET || HV_SPHERE_SPECULAR == HV_SPHERE_SPECULAR_LTC) && HV_HAS_SPHERE_LIGHTS && \
   HV_LIGHT_PROBE == 0)
#define HV_TUBE_SPLIT_LOOPS \
  (HV_TUBE_SPECULAR == HV_TUBE_SPECULAR_LTC && HV_HAS_TUBE_LIGHTS && HV_LIGHT_PROBE == 0)
#if HV_SPHERE_BUDGET
#define HV_SPHERE_FIRST evaluateSphereLightRpAt
#define HV_SPHERE_SECOND sphereLightLtcCorrection
#else
#define HV_SPHERE_FIRST evaluateSphereLightWholeAt
#define HV_SPHERE_SECOND sphereLightStraddleCorrection
#endif
// The split loop's parts that depend on the build: each light's shadow kept for its second part
// (a filter is costly), and the coat lobe: in the same two parts, its pairs marked in the same
// mask (the second part is 0 for a lobe that does not need it; HV_SPLIT_COAT_*), or whole in the
// first loop (the budget's spheres: HV_SPLIT_COAT_WHOLE_SPHERE).
#if HV_SHADOWS
#define HV_SPLIT_VIS_DECL vec4 chunk_vis[32];
#define HV_SPLIT_VIS_KEEP(k) chunk_vis[k] = vis;
#define HV_SPLIT_VIS_LOAD(b) vec4 vis = chunk_vis[b];
#else
#define HV_SPLIT_VIS_DECL
#define HV_SPLIT_VIS_KEEP(k)
#define HV_SPLIT_VIS_LOAD(b)
#endif
#if HV_HAS_CLEAR_COAT
#define HV_SPLIT_COAT_FIRST(FIRST, l, bit)                                 \
  if (any_coat) {                                                          \
    for (int j = 0; j < HV_LIGHT_PIXELS; ++j) {                            \
      bool need;                                                           \
      coat_sum[j] += FIRST(l, cs[j], csp[j], need) * HV_VIS(j);            \
      ltc_marks[j] |= (need && lit[j] && coat[j] > 0.0) ? bit : 0u;        \
    }                                                                      \
  }
#define HV_SPLIT_COAT_SECOND(SECOND, l, j)                                        \
  if (any_coat) {                                                                 \
    Surface csj = cs[0];                                                          \
    ShadingPoint cspj = csp[0];                                                   \
    for (int k = 1; k < HV_LIGHT_PIXELS; ++k) {                                   \
      csj = k == j ? cs[k] : csj;                                                 \
      cspj = k == j ? csp[k] : cspj;                                              \
    }                                                                             \
    vec3 cc = SECOND(l, csj, cspj) * HV_VIS(j);                                   \
    for (int k = 0; k < HV_LIGHT_PIXELS; ++k) coat_sum[k] += k == j ? cc : vec3(0.0); \
  }
#define HV_SPLIT_COAT_WHOLE_SPHERE(FIRST, l, bit)                                             \
  if (any_coat) {                                                                             \
    for (int j = 0; j < HV_LIGHT_PIXELS; ++j) coat_sum[j] += HV_EVAL_SPHERE(l, cs, csp, j);   \
  }
#else
#define HV_SPLIT_COAT_FIRST(FIRST, l, bit)
#define HV_SPLIT_COAT_SECOND(SECOND, l, j)
#define HV_SPLIT_COAT_WHOLE_SPHERE(FIRST, l, bit)
#endif
#define HV_SPLIT_COAT_NONE(SECOND, l, j)
// The tile list's lights BEGIN .. END - 1 of one type in two parts. Every light shaded with the
// first part (FIRST(l, s, sp, need): the representative point with an error budget,
// error_budget.glsl; the whole light with `ltc`), each pixel's pairs that need the second (the
// LTC where the budget asks for it; the cut at the horizon where a light straddles it) marked in
// a bit mask, then corrected by a loop over the marked pairs alone (SECOND(l, s, sp), added). A
// SIMD CPU implementation runs an `if` body whether or not a lane takes it (see the top), so a
// per-pair branch (or any loop holding one) would cost the second part everywhere; a loop ends
// when no lane has a marked pair left. The lights go 32 at a time (one mask word per pixel:
// registers, where arrays indexed at run time would go to memory). Each pass of the correction
// loop takes one marked pair, the lowest marked pixel's lowest marked light, and evaluates the
// second part for that pixel alone (its Surface chosen by selects, not an index into the array):
// a loop over marked lights that evaluated every pixel of the invocation for each (the marked
// ones kept) paid the LTC for pixels that did not need it, and held HV_LIGHT_PIXELS inlined
// copies of it, whose mere presence slowed the pass (docs/lights.md, "Where the budget's time
// goes"). Each pixel still adds its lights' corrections in light order.
#define HV_SPLIT_LOOP(BEGIN, END, FIRST, SECOND, COAT_FIRST, COAT_SECOND)          \
  if (BEGIN < END) {                                                              \
    uint chunk = BEGIN;                                                           \
    do {                                                                          \
      uint chunk_end = min(END, chunk + 32u);                                     \
      uint ltc_marks[HV_LIGHT_PIXELS];                                            \
      for (int j = 0; j < HV_LIGHT_PIXELS; ++j) ltc_marks[j] = 0u;                \
      HV_SPLIT_VIS_DECL                                                           \
      uint i = chunk;                                                             \
      do {                                                                        \
        GpuLight l = tileLight(i);                                                \
        HV_SHADOW_OF(l);                                                          \
        HV_SPLIT_VIS_KEEP(i - chunk)                                              \
        uint bit = 1u << (i - chunk);                                             \
        for (int j = 0; j < HV_LIGHT_PIXELS; ++j) {                               \
          bool need;                                                              \
          sum[j] += FIRST(l, s[j], sp[j], need) * HV_VIS(j);                      \
          ltc_marks[j] |= (need && lit[j]) ? bit : 0u;                            \
        }                                                                         \
        COAT_FIRST(FIRST, l, bit)                                                 \
      } while (++i < chunk_end);                                                  \
      uint marks = ltc_marks[0];                                                  \
      for (int j = 1; j < HV_LIGHT_PIXELS; ++j) marks |= ltc_marks[j];            \
      while (marks != 0u) {                                                       \
        int j = HV_LIGHT_PIXELS - 1;                                              \
        uint mj = ltc_marks[j];                                                   \
        for (int k = HV_LIGHT_PIXELS - 2; k >= 0; --k) {                          \
          j = ltc_marks[k] != 0u ? k : j;                                         \
          mj = ltc_marks[k] != 0u ? ltc_marks[k] : mj;                            \
        }                                                                         \
        int b = findLSB(mj);                                                      \
        uint keep = ~(1u << uint(b));                                             \
        for (int k = 0; k < HV_LIGHT_PIXELS; ++k) ltc_marks[k] &= k == j ? keep : ~0u; \
        marks = ltc_marks[0];                                                     \
        for (int k = 1; k < HV_LIGHT_PIXELS; ++k) marks |= ltc_marks[k];          \
        Surface sj = s[0];                                                        \
        ShadingPoint spj = sp[0];                                                 \
        for (int k = 1; k < HV_LIGHT_PIXELS; ++k) {                               \
          sj = k == j ? s[k] : sj;                                                \
          spj = k == j ? sp[k] : spj;                                             \
        }                                                                         \
        GpuLight l = tileLight(chunk + uint(b));                                  \
        HV_SPLIT_VIS_LOAD(b)                                                      \
        vec3 c = SECOND(l, sj, spj) * HV_VIS(j);                                  \
        for (int k = 0; k < HV_LIGHT_PIXELS; ++k) sum[k] += k == j ? c : vec3(0.0); \
        COAT_SECOND(SECOND, l, j)                                                 \
      }                                                                           \
      chunk = chunk_end;                                                          \
    } while (chunk < END);                                                        \
  }
#ifndef HV_SUN_SHADOW_OF
#define HV_SUN_SHADOW_OF(l)
#endif

// This invocation's tile row (may lie below the viewport in the last row of workgroups).
uint tileRow() {
  return gl_WorkGroupID.y * HV_LIGHT_GROUP_TILES + gl_LocalInvocationID.y / HV_LIGHT_ROWS_PER_TILE;
}
ivec2 pixelOf(int j) {
  return ivec2(gl_WorkGroupID.x * HV_TILE_SIZE + gl_LocalInvocationID.x,
               tileRow() * HV_TILE_HEIGHT +
                   (gl_LocalInvocationID.y % HV_LIGHT_ROWS_PER_TILE) * HV_LIGHT_PIXELS + j);
}

void main() {
  // The G-buffer of this invocation's pixels. A pixel that is not lit (background, unlit model,
  // outside the viewport) is still evaluated with the others, branch-free, and not stored.
  Surface s[HV_LIGHT_PIXELS];
  ShadingPoint sp[HV_LIGHT_PIXELS];
  bool lit[HV_LIGHT_PIXELS];
  bool any_lit = false;
#if HV_HAS_CLEAR_COAT
  Surface cs[HV_LIGHT_PIXELS];
  ShadingPoint csp[HV_LIGHT_PIXELS];
  float coat[HV_LIGHT_PIXELS];
  float base_scale[HV_LIGHT_PIXELS];
  bool any_coat = false;
  vec3 coat_sum[HV_LIGHT_PIXELS];
  for (int j = 0; j < HV_LIGHT_PIXELS; ++j) coat_sum[j] = vec3(0.0);
#endif
  for (int j = 0; j < HV_LIGHT_PIXELS; ++j) {
    ivec2 px = pixelOf(j);
    vec4 mat = texelFetch(t_material, px, 0);
    uint model = decodeShadingModel(mat.b);
    lit[j] = isLitModel(model) && px.x < int(u_viewport.x) && px.y < int(u_viewport.y);
    any_lit = any_lit || lit[j];
    vec4 bc = texelFetch(t_base_cavity, px, 0);
    vec3 N = octDecode(texelFetch(t_normal, px, 0).xy);
    float depth = texelFetch(t_depth, px, 0).r;
    vec2 uv = (vec2(px) + 0.5) / vec2(u_viewport.xy);
    vec3 P = reconstructWorldPosition(uv, depth, u_inv_view_proj);
    vec3 V = normalize(u_camera_pos.xyz - P);
    s[j] = makeSurface(N, bc.rgb, mat.r, decodeRoughness16(mat.ga), bc.a);
    sp[j] = makeShadingPoint(s[j], P, V);
#if HV_HAS_CLEAR_COAT
    // The coat (clear_coat.glsl) where the model has one; elsewhere weight 0, base scale 1.
    vec4 ct = texelFetch(t_coat, px, 0);
    bool coated = model == HV_MODEL_CLEAR_COAT;
    coat[j] = coated ? ct.z : 0.0;
    vec3 Nc = coated ? octDecode(ct.xy) : N;
    cs[j] = makeCoatSurface(Nc, ct.w, bc.a);
    csp[j] = makeShadingPoint(cs[j], P, V);
    base_scale[j] = coatBaseScale(coat[j], Nc, V);
    any_coat = any_coat || (coated && lit[j]);
#endif
  }
  if (!any_lit) return;
#if HV_SHADOW_MASK
  // The resolved mask's pixels (shadowMaskVisibility).
  ivec2 mask_px[HV_LIGHT_PIXELS];
  for (int j = 0; j < HV_LIGHT_PIXELS; ++j) mask_px[j] = pixelOf(j);
#elif HV_SHADOWS
  vec3 shadow_P[HV_LIGHT_PIXELS];
  vec3 shadow_N[HV_LIGHT_PIXELS];
  for (int j = 0; j < HV_LIGHT_PIXELS; ++j) {
    shadow_P[j] = sp[j].P;
    shadow_N[j] = s[j].N;
  }
#endif

  vec3 sum[HV_LIGHT_PIXELS];
#if HV_LIGHT_PROBE == 1 || HV_LIGHT_PROBE == 2
  for (int j = 0; j < HV_LIGHT_PIXELS; ++j) sum[j] = setupProbeValue(s[j], sp[j]);
#else
  for (int j = 0; j < HV_LIGHT_PIXELS; ++j) sum[j] = vec3(0.0);
#endif
#if HV_CULLING_BRUTE_FORCE
  uint n = u_light_count;
  for (uint i = 0u; i < n; ++i) {
    GpuLight l = lights[i];
#if HV_LIGHT_PROBE == 3
#define HV_EVAL_ANY(l, S, SP, j) probeAnyLight(l, S[j], SP[j])
#elif HV_SHADOW_MASK
    HV_SHADOW_OF(l);
#define HV_EVAL_ANY(l, S, SP, j) (evaluateLightAt(l, S[j], SP[j]) * vis[j])
#elif HV_SHADOWS
    vec4 vis = anyLightShadow(l, shadow_P, shadow_N, bvec4(lit[0], lit[1], lit[2], lit[3]));
#define HV_EVAL_ANY(l, S, SP, j) (evaluateLightAt(l, S[j], SP[j]) * vis[j])
#else
#define HV_EVAL_ANY(l, S, SP, j) evaluateLightAt(l, S[j], SP[j])
#endif
    HV_ACCUMULATE(HV_EVAL_ANY, l)
  }
#else
  uint tile = tileRow() * u_viewport.z + gl_WorkGroupID.x;  // tileRow() < tiles y: a pixel is lit
  uvec2 range = tile_ranges[tile];
  uvec2 split = tile_types[tile];  // points, then spheres, then tubes
  uint end = min(range.x + range.y, u_tile_capacity);
  uint end_point = min(range.x + split.x, end);
  uint end_sphere = min(end_point + split.y, end);
  // One loop per type, each a do-while behind an if: the exit test at the end of the body. A SIMD
  // CPU implementation (llvmpipe) runs a loop body under a mask until no lane is left, so a test
  // at the top costs one extra, fully masked body per loop: one wasted evaluation of each type
  // per tile row (its saving: docs/lights.md, "Tiled culling").
#if HV_HAS_POINT_LIGHTS && HV_LIGHT_PROBE != 2
  if (range.x < end_point) {
    uint i = range.x;
    do {
      GpuLight l = tileLight(i);
      HV_SHADOW_OF(l);
      HV_ACCUMULATE(HV_EVAL_POINT, l)
    } while (++i < end_point);
  }
#endif
#if HV_HAS_SPHERE_LIGHTS && HV_LIGHT_PROBE != 2
#if HV_SPHERE_SPLIT_LOOPS && HV_SPHERE_BUDGET
  HV_SPLIT_LOOP(end_point, end_sphere, HV_SPHERE_FIRST, HV_SPHERE_SECOND, HV_SPLIT_COAT_WHOLE_SPHERE,
                HV_SPLIT_COAT_NONE)
#elif HV_SPHERE_SPLIT_LOOPS
  HV_SPLIT_LOOP(end_point, end_sphere, HV_SPHERE_FIRST, HV_SPHERE_SECOND, HV_SPLIT_COAT_FIRST,
                HV_SPLIT_COAT_SECOND)
#else
  if (end_point < end_sphere) {
    uint i = end_point;
    do {
      GpuLight l = tileLight(i);
      HV_SHADOW_OF(l);
      HV_ACCUMULATE(HV_EVAL_SPHERE, l)
    } while (++i < end_sphere);
  }
#endif
#endif
#if HV_TUBE_SPLIT_LOOPS
  HV_SPLIT_LOOP(end_sphere, end, evaluateTubeLightWholeAt, tubeLightStraddleCorrection,
                HV_SPLIT_COAT_FIRST, HV_SPLIT_COAT_SECOND)
#elif HV_HAS_TUBE_LIGHTS && HV_LIGHT_PROBE != 2
  if (end_sphere < end) {
    uint i = end_sphere;
    do {
      GpuLight l = tileLight(i);
      HV_SHADOW_OF(l);
      HV_ACCUMULATE(HV_EVAL_TUBE, l)
    } while (++i < end);
  }
#endif
#if HV_HAS_DIRECTIONAL_LIGHTS && HV_LIGHT_PROBE != 2
  // The directional lights, which no tile list holds: every pixel shades each of them (the
  // brute-force loop above reaches them through evaluateLightAt). The index is uniform across
  // the dispatch, so its fetch is one load, not a gather.
  for (int k = 0; k < 4; ++k) {
    uint d = u_directional_lights[k];
    if (d == 0u) break;
    GpuLight l = lights[d - 1u];
    HV_SUN_SHADOW_OF(l);
    HV_ACCUMULATE(HV_EVAL_DIRECTIONAL, l)
  }
#endif
#endif
#if HV_HAS_CLEAR_COAT && HV_LIGHT_PROBE != 3
  // f_base (1 - c F_c) + c f_coat (clear_coat.glsl), summed over the lights.
  for (int j = 0; j < HV_LIGHT_PIXELS; ++j) sum[j] = sum[j] * base_scale[j] + coat_sum[j] * coat[j];
#endif
#if HV_LIGHT_PROBE == 3
  for (int j = 0; j < HV_LIGHT_PIXELS; ++j) sum[j].z = 1.0;  // lit: the view shows x / y
#endif
  for (int j = 0; j < HV_LIGHT_PIXELS; ++j) {
    if (!lit[j]) continue;
    ivec2 px = pixelOf(j);
    vec4 hdr = imageLoad(i_hdr, px);
    imageStore(i_hdr, px, vec4(min(hdr.rgb + sum[j], vec3(HV_HDR_MAX)), hdr.a));
  }
}
