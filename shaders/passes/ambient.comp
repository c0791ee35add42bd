#version 450 core
// Ambient pass (Karis 2013, "Image-Based Lighting"): split-sum specular from the GGX-prefiltered
// radiance cube and the environment BRDF (table, or Karis's analytic approximation), diffuse from
// SH9 (or an irradiance cube), Cavity on ambient diffuse (and, as an option, through Lagarde &
// de Rousiers 2014's specular occlusion). Background pixels show the environment.
// HV_IBL_SPECULAR (settings.ibl_specular): split_sum reads one prefiltered texel per lobe; sampled
// averages the cube over samples of the pixel's own lobe (ibl.glsl, sampledAmbientSpecular).
// The bake already applied the environment's intensity and rotation: the cubes are world-space.
#include "../common/frame.glsl"
#include "../common/gbuffer.glsl"
#include "../common/brdf.glsl"
#include "../common/ibl.glsl"
#include "../common/clear_coat.glsl"

// Specialization (docs/variants.md); the defaults are the uber build.
//   HV_ENVIRONMENT 1|0: 0 = no environment: black background, no image-based lighting code.
//   HV_ENV_RUNTIME_CHECK 1|0: 1 = the environment's presence is read from u_env.z (uber).
//   HV_HAS_DEFAULT_LIT 1|0: 0 = no lit material: only the background is written.
//   HV_HAS_CLEAR_COAT 1|0: a clear_coat material is drawn: its pixels add the coat's split-sum
//     specular (a second prefiltered lookup along the coat's reflection) over the base, which the
//     coat scales by coatBaseScale (clear_coat.glsl).
#ifndef HV_ENVIRONMENT
#define HV_ENVIRONMENT 1
#endif
#ifndef HV_ENV_RUNTIME_CHECK
#define HV_ENV_RUNTIME_CHECK 1
#endif
#ifndef HV_HAS_DEFAULT_LIT
#define HV_HAS_DEFAULT_LIT 1
#endif
#ifndef HV_HAS_CLEAR_COAT
#define HV_HAS_CLEAR_COAT 1
#endif
#ifndef HV_ENV_BRDF_ANALYTIC
#define HV_ENV_BRDF_ANALYTIC 0
#endif
#ifndef HV_ENERGY_COMPENSATION
#define HV_ENERGY_COMPENSATION 0
#endif
#ifndef HV_IRRADIANCE_CUBEMAP
#define HV_IRRADIANCE_CUBEMAP 0
#endif
#ifndef HV_SPECULAR_OCCLUSION
#define HV_SPECULAR_OCCLUSION 0
#endif
// Screen-space ambient occlusion (settings.ao; docs/ambient-occlusion.md): HV_AO 1 reads the AO
// pass's output (visibility, view distance, bent normal) on HV_UNIT_AO; it occludes ambient
// diffuse (with the cavity: combineOcclusion; optionally through the multi-bounce fit) and ambient
// specular (HV_AO_SPECULAR: none, Lagarde & de Rousiers 2014, the cone-cone form, or for narrow
// lobes the visibility traced along the lobe through the depth buffer).
#ifndef HV_AO
#define HV_AO 0
#endif
#ifndef HV_AO_SPECULAR
#define HV_AO_SPECULAR HV_AO_SPECULAR_LAGARDE
#endif
#ifndef HV_AO_MULTI_BOUNCE
#define HV_AO_MULTI_BOUNCE 0
#endif
// Term mask: bit 1 ambient diffuse, bit 2 ambient specular; a term left out is 0 (per-term
// images, `halfvec render --aov`). Background pixels are drawn whatever the mask, unless
// u_frame_flags has HV_FRAME_NO_BACKGROUND (per-term debug views).
#ifndef HV_AMBIENT_TERMS
#define HV_AMBIENT_TERMS 3
#endif

layout(local_size_x = HV_TILE_SIZE, local_size_y = HV_TILE_SIZE) in;

layout(binding = HV_UNIT_BASE_CAVITY) uniform sampler2D t_base_cavity;
layout(binding = HV_UNIT_MATERIAL) uniform sampler2D t_material;
layout(binding = HV_UNIT_NORMAL) uniform sampler2D t_normal;
layout(binding = HV_UNIT_RADIANCE) uniform samplerCube t_radiance;    // prefiltered: one roughness per mip
layout(binding = HV_UNIT_ENV_BRDF) uniform sampler2D t_env_brdf;      // (scale, bias) over (NoV, roughness)
layout(binding = HV_UNIT_IRRADIANCE) uniform samplerCube t_irradiance;  // E(n), not divided by pi
layout(rgba16f, binding = HV_IMAGE_HDR) uniform image2D i_hdr;
#if HV_HAS_CLEAR_COAT && HV_HAS_DEFAULT_LIT && HV_ENVIRONMENT
layout(binding = HV_UNIT_COAT) uniform sampler2D t_coat;
#endif

#define HV_BLOCK_MEMBER(type, name) type u_##name;
#define HV_BLOCK_ARRAY(type, name, count) type u_##name[count];
layout(std140, binding = HV_UBO_ENVIRONMENT) uniform EnvironmentBlock {
#include "../common/environment_block.glsl"
};
#undef HV_BLOCK_ARRAY
#undef HV_BLOCK_MEMBER

#if HV_AO && HV_HAS_DEFAULT_LIT && HV_ENVIRONMENT
#include "../common/ao.glsl"
#include "../common/half_res.glsl"
layout(binding = HV_UNIT_DEPTH) uniform sampler2D t_depth;
layout(binding = HV_UNIT_AO) uniform sampler2D t_ao;

// The AO of pixel px (x: visibility, yzw: world bent normal, read only by the cone specular
// occlusion). At full resolution its texel; at half, the four nearest texels with bilinear
// weights times a depth weight (5% of the distance), so that an edge does not take
// the occlusion of the surface across it; where no texel is within that, the nearest in distance.
// The four texels come as one textureGather per channel at the corner they share. `depth`: the
// pixel's reversed-Z depth.
vec4 aoAt(ivec2 px, float depth) {
  ivec2 size = textureSize(t_ao, 0);
  if (size.x >= int(u_viewport.x)) {
    vec4 a = texelFetch(t_ao, px, 0);
#if HV_AO_SPECULAR == HV_AO_SPECULAR_CONE
    return vec4(a.x, octDecode(a.zw));
#else
    return vec4(a.x, 0.0, 0.0, 1.0);
#endif
  }
  // Inverse view distances (1 / m), as the AO target holds them (gtao.comp).
  float inv_dist = depth / u_frame_params.x;
  // Texel q holds pixel 2q (gtao.comp): the four nearest texels (half_res.glsl).
  vec2 uv;
  vec4 wb;
  halfResFootprint(px, size, uv, wb);
  vec4 vis = textureGather(t_ao, uv, 0);
  vec4 inv = textureGather(t_ao, uv, 1);
  // A background texel (w 0) never counts.
  vec4 diff = halfResDistanceDiff(inv, inv_dist);
  vec4 w = wb * halfResDepthWeight(diff);
  float wsum = w.x + w.y + w.z + w.w;
#if HV_AO_SPECULAR == HV_AO_SPECULAR_CONE
  vec4 bx = textureGather(t_ao, uv, 2);
  vec4 by = textureGather(t_ao, uv, 3);
  vec4 a[4];
  for (int k = 0; k < 4; ++k) a[k] = vec4(vis[k], octDecode(vec2(bx[k], by[k])));
#else
  vec4 a[4];
  for (int k = 0; k < 4; ++k) a[k] = vec4(vis[k], 0.0, 0.0, 1.0);
#endif
  vec4 nearest = a[0];
  float nearest_diff = diff[0];
  vec4 sum = a[0] * w[0];
  for (int k = 1; k < 4; ++k) {
    sum += a[k] * w[k];
    if (diff[k] < nearest_diff) {
      nearest_diff = diff[k];
      nearest = a[k];
    }
  }
  return wsum > 1e-4 ? sum / wsum : nearest;
}

#if HV_AO_SPECULAR == HV_AO_SPECULAR_TRACED
// The traced specular occlusion (ao_specular: traced; constants and weight: ao.glsl,
// HV_AO_TRACE_*) of a lobe of perceptual roughness r along dir (world, unit) from the surface
// point P (world; main reconstructs it once for the base and the coat) whose reversed-Z depth is
// `depth`: the visibility of the environment along that ray, 0 where something on screen lies
// across it within HV_AO_TRACE_REACH ao_radius, else 1, weighted against Lagarde's occlusion from
// the AO (`lagarde`) by aoTraceWeight: a ray stands for a narrow lobe, not a wide one. Points off
// screen or behind the camera end the march unoccluded (the depth buffer knows nothing there).
// Depth is read bilinearly (PassContext::bilinear): a plane's reversed-Z depth is affine in
// screen space, so a floor seen at a grazing angle does not occlude itself between texel centres.
// The march's count is 0 where the weight is (rough lobes): a SIMD row of them skips it.
float tracedSpecularOcclusion(vec3 P, float depth, vec3 dir, float roughness, float lagarde) {
  float weight = aoTraceWeight(roughness);
  float radius = u_frame_params.z;
  float reach = HV_AO_TRACE_REACH * radius;
  float start = HV_AO_TRACE_START * u_frame_params.x / max(depth, 1e-9);
  float visible = 1.0;
  int steps = weight > 0.0 && depth > 0.0 ? HV_AO_TRACE_STEPS : 0;
  for (int k = 0; k < steps; ++k) {
    float u = (float(k) + 0.5) / float(HV_AO_TRACE_STEPS);
    float t = start + reach * u * u;
    vec4 c = u_view_proj * vec4(P + dir * t, 1.0);
    if (c.w <= 0.0) break;
    vec2 s = c.xy / c.w * 0.5 + 0.5;
    if (any(lessThan(s, vec2(0.0))) || any(greaterThan(s, vec2(1.0)))) break;
    float d = textureLod(t_depth, s, 0.0).r;
    // Reversed Z: view distance = near / depth; the point lies c.w from the camera.
    float gap = c.w - u_frame_params.x / max(d, 1e-9);
    if (d > 0.0 && gap > HV_AO_TRACE_EPSILON * c.w && gap < aoTraceThickness(radius, t)) {
      visible = 0.0;
      break;
    }
  }
  return mix(lagarde, visible, weight);
}
#endif

// The screen-space AO's occlusion of the coat's ambient specular: the base's rule (settings.
// ao_specular) on the coat's normal, roughness, reflection and lookup direction (dirc).
float coatSpecularOcclusion(vec3 P, float depth, Surface cs, float NoVc, vec3 Rc, vec3 dirc,
                            vec4 ao, float vis) {
#if HV_AO_SPECULAR == HV_AO_SPECULAR_LAGARDE
  return specularOcclusion(NoVc, vis, cs.alpha);
#elif HV_AO_SPECULAR == HV_AO_SPECULAR_TRACED
  return tracedSpecularOcclusion(P, depth, dirc, cs.roughness,
                                 specularOcclusion(NoVc, vis, cs.alpha));
#elif HV_AO_SPECULAR == HV_AO_SPECULAR_CONE
  return specularOcclusionCone(safeNormalize(ao.yzw), cs.N, Rc, vis, cs.alpha);
#else
  return 1.0;
#endif
}
#endif

void main() {
  ivec2 px = ivec2(gl_GlobalInvocationID.xy);
  if (px.x >= int(u_viewport.x) || px.y >= int(u_viewport.y)) return;
  // One cube lookup and one store per pixel, whether it shows the background or a surface: a SIMD
  // implementation (llvmpipe) runs both sides of a branch under a mask, so separate background
  // and surface paths cost every pixel two cube samples and two stores (docs/performance.md,
  // "Where the ambient pass's time goes").
  vec4 mat = texelFetch(t_material, px, 0);
  uint model = decodeShadingModel(mat.b);
  bool background = model == HV_MODEL_BACKGROUND;
  vec4 hdr = imageLoad(i_hdr, px);
  vec4 result = hdr;  // unlit surfaces keep what the G-buffer pass wrote (emissive)
  vec2 uv = (vec2(px) + 0.5) / vec2(u_viewport.xy);
  // The view ray through the pixel, to a far point on it (reversed Z: depth 1e-3 is far away).
  // The camera is a pinhole (perspective only), so the surface seen in the pixel lies on the same
  // ray: no depth fetch is needed (its saving: docs/performance.md).
  vec3 ray = normalize(reconstructWorldPosition(uv, 1e-3, u_inv_view_proj) - u_camera_pos.xyz);
#if HV_ENVIRONMENT
  bool env_present = true;
#if HV_ENV_RUNTIME_CHECK
  env_present = u_env.z >= 0.5;
#endif
  vec3 dir = ray;
  float lod = 0.0;
#if HV_HAS_DEFAULT_LIT
  vec4 bc = texelFetch(t_base_cavity, px, 0);
  vec3 N = octDecode(texelFetch(t_normal, px, 0).xy);
  vec3 V = -ray;
  Surface s = makeSurface(N, bc.rgb, mat.r, decodeRoughness16(mat.ga), bc.a);
  // N.V clamped away from 0: at grazing angles the table's first column is the limit anyway.
  float NoV = clamp(dot(N, V), 1e-4, 1.0);
  vec3 R = reflect(-V, N);
  if (!background) {
    dir = prefilteredDirection(N, R, s.alpha);
    lod = specularLookupMip(s.roughness, u_env.x);
  }
#endif
  // The environment seen along the view ray (background) or prefiltered along R (surface).
  vec3 radiance = textureLod(t_radiance, dir, lod).rgb;
  if (background) result = vec4(env_present ? radiance : vec3(0.0), 1.0);
#if HV_HAS_DEFAULT_LIT
  if (isLitModel(model) && env_present) {
#if HV_IRRADIANCE_CUBEMAP
    vec3 E = textureLod(t_irradiance, N, 0.0).rgb;
#else
    vec3 sh[9];
    for (int i = 0; i < 9; ++i) sh[i] = u_sh[i].rgb;
    vec3 E = evalSH9Irradiance(sh, N);
#endif
#if HV_ENV_BRDF_ANALYTIC
    vec2 ab = EnvBRDFApproxScaleBias(s.roughness, NoV);
#else
    vec2 ab = texture(t_env_brdf, vec2(NoV, s.roughness)).rg;
#endif
#if HV_AO
    float depth = texelFetch(t_depth, px, 0).r;  // the AO upsample's and the march's
    vec4 ao = aoAt(px, depth);
#if HV_AO_SPECULAR == HV_AO_SPECULAR_TRACED
    vec3 P = reconstructWorldPosition(uv, depth, u_inv_view_proj);  // the base's and coat's march
#else
    vec3 P = vec3(0.0);
#endif
    float vis = combineOcclusion(s.cavity, ao.x);
#if HV_AO_MULTI_BOUNCE
    vec3 diffuse_vis = gtaoMultiBounce(vis, s.diffuse_color);
#else
    vec3 diffuse_vis = vec3(vis);
#endif
    float specular_vis = 1.0;
#if HV_AO_SPECULAR == HV_AO_SPECULAR_LAGARDE
    specular_vis = specularOcclusion(NoV, vis, s.alpha);
#elif HV_AO_SPECULAR == HV_AO_SPECULAR_TRACED
    specular_vis =
        tracedSpecularOcclusion(P, depth, dir, s.roughness, specularOcclusion(NoV, vis, s.alpha));
#elif HV_AO_SPECULAR == HV_AO_SPECULAR_CONE
    specular_vis = specularOcclusionCone(safeNormalize(ao.yzw), N, R, vis, s.alpha);
#endif
    // The occlusion replaces the cavity in ambientDiffuse (it holds the cavity already).
    Surface open_s = s;
    open_s.cavity = 1.0;
    vec3 diffuse = ambientDiffuse(open_s, E) * diffuse_vis;
    vec3 specular = ambientSpecularFromCube(t_radiance, s, V, radiance, ab, NoV, u_env.x,
                                            HV_ENERGY_COMPENSATION != 0, false) *
                    specular_vis;
#define HV_COAT_OCCLUSION(cs, NoVc, Rc, dirc) \
  coatSpecularOcclusion(P, depth, cs, NoVc, Rc, dirc, ao, vis)
#else
    vec3 diffuse = ambientDiffuse(s, E);
    vec3 specular = ambientSpecularFromCube(t_radiance, s, V, radiance, ab, NoV, u_env.x,
                                            HV_ENERGY_COMPENSATION != 0,
                                            HV_SPECULAR_OCCLUSION != 0);
#define HV_COAT_OCCLUSION(cs, NoVc, Rc, dirc) 1.0
#endif
#if HV_HAS_CLEAR_COAT
    // The coat (clear_coat.glsl): the base under it scaled, its own split-sum lobe added, with
    // the base's environment BRDF, energy compensation and specular occlusion rules.
    if (model == HV_MODEL_CLEAR_COAT) {
      vec4 ct = texelFetch(t_coat, px, 0);
      vec3 Nc = octDecode(ct.xy);
      Surface cs = makeCoatSurface(Nc, ct.w, bc.a);
      float NoVc = clamp(dot(Nc, V), 1e-4, 1.0);
      vec3 Rc = reflect(-V, Nc);
      vec3 dirc = prefilteredDirection(Nc, Rc, cs.alpha);
      vec3 coat_radiance =
          textureLod(t_radiance, dirc, specularLookupMip(cs.roughness, u_env.x)).rgb;
#if HV_ENV_BRDF_ANALYTIC
      vec2 abc = EnvBRDFApproxScaleBias(cs.roughness, NoVc);
#else
      vec2 abc = texture(t_env_brdf, vec2(NoVc, cs.roughness)).rg;
#endif
      float scale = coatBaseScale(ct.z, Nc, V);
      diffuse *= scale;
      specular = specular * scale +
                 ambientSpecularFromCube(t_radiance, cs, V, coat_radiance, abc, NoVc, u_env.x,
                                         HV_ENERGY_COMPENSATION != 0,
                                         HV_AO == 0 && HV_SPECULAR_OCCLUSION != 0) *
                     (ct.z * HV_COAT_OCCLUSION(cs, NoVc, Rc, dirc));
    }
#endif
#if (HV_AMBIENT_TERMS & 1) == 0
    diffuse = vec3(0.0);
#endif
#if (HV_AMBIENT_TERMS & 2) == 0
    specular = vec3(0.0);
#endif
    result = vec4(hdr.rgb + diffuse + specular, hdr.a);
  }
#endif
#else
  if (background) result = vec4(0.0, 0.0, 0.0, 1.0);
#endif
  if (background && (u_frame_flags & HV_FRAME_NO_BACKGROUND) != 0u) {
    result = vec4(0.0, 0.0, 0.0, 1.0);
  }
  imageStore(i_hdr, px, vec4(min(result.rgb, vec3(HV_HDR_MAX)), result.a));
}
