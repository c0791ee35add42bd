// Tiled culling: a light's culling record (CullLight: cull_layout.glsl), for the stages that
// compute it (light_cull_bin.comp; light_cull_few.comp).
#ifndef HV_LIGHT_CULL_LIGHT_GLSL
#define HV_LIGHT_CULL_LIGHT_GLSL

#include "light_cull_common.glsl"

layout(std430, binding = HV_BINDING_LIGHTS) readonly buffer LightBlock { GpuLight lights[]; };

// Light i's bounding sphere (lightCullSphere) in view space, its exact rectangle of tiles
// (sphereTileRect: tangent planes through the eye; HV_CULL_RECT_EMPTY when the sphere lies entirely
// nearer than the near plane or off screen), its type, and for a spot its cone (tested against
// blocks and tiles: coneTouchesBox).
CullLight cullLightRecord(uint i) {
  vec4 world = lightCullSphere(lights[i]);
  vec3 c = (u_view * vec4(world.xyz, 1.0)).xyz;
  float r = world.w;
  uint type = uint(lightType(lights[i]));  // HV_LIGHT_POINT/SPHERE/TUBE = 0/1/2
  ivec4 rect;
  bool visible = type <= 2u && sphereTileRect(c, r, vec2(u_proj[0][0], u_proj[1][1]),
                                              u_frame_params.x, vec2(u_viewport.xy),
                                              ivec2(u_viewport.zw),
                                              vec2(HV_TILE_SIZE, HV_TILE_HEIGHT), rect);
  CullLight l;
  l.sphere = vec4(c, r);
  // A spot's cone (spotCone, spot.glsl: direction * scale, -cos_outer * scale) in view space,
  // from its center (the apex of the cone lightCone reads), for the cone-versus-tile test.
  vec4 apex = vec4(0.0), axis = vec4(0.0);
#if HV_HAS_SPOT_LIGHTS
  if ((lights[i].type & HV_LIGHT_SPOT_FLAG) != 0u) {
    vec4 cone = lights[i].axis_length;
    float scale = length(cone.xyz);
    vec3 d = mat3(u_view) * (cone.xyz / scale);
    // The range is widened by the 1e-4 the bounding sphere is (spotBoundingSphere), the cosine
    // lowered by 1e-4 against its rounding from the scaled cone.
    apex = vec4((u_view * vec4(lights[i].position_radius.xyz, 1.0)).xyz,
                lightCullRadius(lights[i]) * 1.0001);
    axis = vec4(normalize(d), clamp(-cone.w / scale, 0.0, 1.0) - 1e-4);
  }
#endif
  l.cone_apex = apex;
  l.cone_axis = axis;
  l.rect = visible ? uvec4(uint(rect.x) | (uint(rect.y) << HV_CULL_RECT_SHIFT),
                           uint(rect.z) | (uint(rect.w) << HV_CULL_RECT_SHIFT), type, 0u)
                   : uvec4(HV_CULL_RECT_EMPTY, 0u, 0u, 0u);
  return l;
}

#endif
