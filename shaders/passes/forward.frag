#version 450 core
// Forward pass of blended surfaces (glTF alphaMode BLEND): drawn after the deferred passes, back
// to front, depth-tested against the opaque depth without writing it, each fragment lit at once by
// the same code the deferred passes run (the material of surface_material.glsl, the lights of
// lights.glsl with their shadows, the split-sum environment of ibl.glsl) and blended over the HDR
// target with its alpha as coverage (glTF 2.0, 3.9.4 "Alpha Coverage": the rendered colour is
// composited over the background with alpha). The same defines as the light and ambient programs
// select the same approximations (docs/gltf.md, "Alpha blending").
#include "../common/frame.glsl"
#include "../common/gbuffer.glsl"
// The error budget's table: unit 10 holds the environment here (bindings.glsl).
#define HV_ERROR_TABLE_UNIT HV_UNIT_FORWARD_ERROR_TABLE
#include "../common/lights.glsl"
#include "../common/ibl.glsl"
#include "../common/clear_coat.glsl"
#include "surface_material.glsl"

#ifndef HV_ENVIRONMENT
#define HV_ENVIRONMENT 1
#endif
#ifndef HV_ENV_RUNTIME_CHECK
#define HV_ENV_RUNTIME_CHECK 1
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
#ifndef HV_AMBIENT_TERMS
#define HV_AMBIENT_TERMS 3
#endif

layout(std430, binding = HV_BINDING_LIGHTS) readonly buffer LightBlock { GpuLight lights[]; };
// The lights whose culling sphere meets this draw's bounds (ForwardPass::lightsReaching): the
// tile lists are built from the opaque depth, which a blended surface in front of it is not
// part of, so the forward pass culls per draw, on the CPU.
layout(std430, binding = HV_BINDING_FORWARD_LIGHTS) readonly buffer DrawLightBlock {
  uint draw_lights[];
};
layout(location = HV_LOC_FORWARD_LIGHTS) uniform uvec2 u_draw_lights;  // offset, count

#if HV_ENVIRONMENT
layout(binding = HV_UNIT_FORWARD_RADIANCE) uniform samplerCube t_radiance;
layout(binding = HV_UNIT_FORWARD_ENV_BRDF) uniform sampler2D t_env_brdf;
layout(binding = HV_UNIT_FORWARD_IRRADIANCE) uniform samplerCube t_irradiance;
#define HV_BLOCK_MEMBER(type, name) type u_##name;
#define HV_BLOCK_ARRAY(type, name, count) type u_##name[count];
layout(std140, binding = HV_UBO_ENVIRONMENT) uniform EnvironmentBlock {
#include "../common/environment_block.glsl"
};
#undef HV_BLOCK_ARRAY
#undef HV_BLOCK_MEMBER

// The ambient specular of surface s seen from V (ambient.comp's: along the prefiltered direction,
// or sampled over the lobe (settings.ibl_specular), with the environment BRDF, energy compensation
// and the cavity's specular occlusion).
vec3 ambientSpecularOf(Surface s, vec3 V) {
  float NoV = clamp(dot(s.N, V), 1e-4, 1.0);
  vec3 R = reflect(-V, s.N);
  vec3 radiance = textureLod(t_radiance, prefilteredDirection(s.N, R, s.alpha),
                             specularLookupMip(s.roughness, u_env.x)).rgb;
#if HV_ENV_BRDF_ANALYTIC
  vec2 ab = EnvBRDFApproxScaleBias(s.roughness, NoV);
#else
  vec2 ab = texture(t_env_brdf, vec2(NoV, s.roughness)).rg;
#endif
  return ambientSpecularFromCube(t_radiance, s, V, radiance, ab, NoV, u_env.x,
                                 HV_ENERGY_COMPENSATION != 0, HV_SPECULAR_OCCLUSION != 0);
}

// Ambient light of surface s seen from V: ambient.comp's surface path (split-sum specular along
// the prefiltered direction, SH9 or irradiance-cube diffuse, the cavity), without screen-space AO,
// which a surface absent from the depth buffer cannot have. With a coat of weight `coat` (surface
// cs, clear_coat.glsl) the base is scaled by base_scale and the coat's own lobe added.
vec3 ambientLight(Surface s, vec3 V, Surface cs, float coat, float base_scale) {
#if HV_ENV_RUNTIME_CHECK
  if (u_env.z < 0.5) return vec3(0.0);
#endif
#if HV_IRRADIANCE_CUBEMAP
  vec3 E = textureLod(t_irradiance, s.N, 0.0).rgb;
#else
  vec3 sh[9];
  for (int i = 0; i < 9; ++i) sh[i] = u_sh[i].rgb;
  vec3 E = evalSH9Irradiance(sh, s.N);
#endif
  vec3 diffuse = ambientDiffuse(s, E) * base_scale;
  vec3 specular = ambientSpecularOf(s, V) * base_scale;
#if HV_MAT_CLEAR_COAT
  if (coat > 0.0) specular += ambientSpecularOf(cs, V) * coat;
#endif
#if (HV_AMBIENT_TERMS & 1) == 0
  diffuse = vec3(0.0);
#endif
#if (HV_AMBIENT_TERMS & 2) == 0
  specular = vec3(0.0);
#endif
  return diffuse + specular;
}
#endif

layout(location = 0) out vec4 o_hdr;  // blended: src alpha, one minus src alpha

void main() {
  SurfaceMaterial sm = surfaceMaterial();
#if HV_MAT_ALPHA_MASK
  if (sm.masked_out) discard;  // only masked materials have a discard (docs/variants.md)
#endif
  float alpha = clamp(sm.base.a, 0.0, 1.0);
  vec3 color = (u_frame_flags & HV_FRAME_NO_EMISSIVE) != 0u ? vec3(0.0) : sm.emissive;
  if (isLitModel(u_material.shading_model)) {
    // The fragment's world position as the deferred passes reconstruct it from the depth buffer.
    vec2 uv = gl_FragCoord.xy / vec2(u_viewport.xy);
    vec3 P = reconstructWorldPosition(uv, gl_FragCoord.z, u_inv_view_proj);
    vec3 V = normalize(u_camera_pos.xyz - P);
    Surface s = makeSurface(sm.n, clamp(sm.base.rgb, 0.0, 1.0), clamp(sm.metallic, 0.0, 1.0),
                            sm.roughness, clamp(sm.cavity, 0.0, 1.0));
    ShadingPoint sp = makeShadingPoint(s, P, V);
    // The coat (clear_coat.glsl): weight 0 and base scale 1 off clear_coat materials.
    Surface cs = makeCoatSurface(sm.coat_n, sm.coat_roughness, s.cavity);
    float coat = clamp(sm.coat, 0.0, 1.0);
    float base_scale = coatBaseScale(coat, sm.coat_n, V);
#if HV_MAT_CLEAR_COAT
    ShadingPoint csp = makeShadingPoint(cs, P, V);
#endif
    vec3 direct = vec3(0.0);
    vec3 coat_direct = vec3(0.0);
    for (uint i = 0u; i < u_draw_lights.y; ++i) {
      GpuLight l = lights[draw_lights[u_draw_lights.x + i]];
#if HV_SHADOWS
      vec3 sP[HV_SHADOW_RECEIVERS];
      vec3 sN[HV_SHADOW_RECEIVERS];
      for (int j = 0; j < HV_SHADOW_RECEIVERS; ++j) {
        sP[j] = P;
        sN[j] = s.N;
      }
      float vis = anyLightShadow(l, sP, sN, bvec4(true, false, false, false)).x;
#else
      float vis = 1.0;
#endif
      direct += evaluateLightAt(l, s, sp) * vis;
#if HV_MAT_CLEAR_COAT
      if (coat > 0.0) coat_direct += evaluateLightAt(l, cs, csp) * vis;
#endif
    }
    color += direct * base_scale + coat_direct * coat;
#if HV_ENVIRONMENT
    color += ambientLight(s, V, cs, coat, base_scale);
#endif
  }
  o_hdr = vec4(min(color, vec3(HV_HDR_MAX)), alpha);
}
