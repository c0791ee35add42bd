#version 450 core
// Tiled culling, second stage (light_cull_common.glsl): one invocation per light of the batch and
// band of HV_CULL_BIN_GROUP_ROWS group rows (so that a light covering the screen is binned by
// several invocations, not by one): the light's bounding sphere (lightCullSphere) in view space and
// its exact rectangle of tiles (sphereTileRect: tangent planes through the eye; none when the
// sphere lies entirely nearer than the near plane or off screen) and, for a spot, its cone (tested
// against blocks and tiles: light_cull_walk.glsl); then, for every group of the
// band that the rectangle overlaps and the sphere touches (sphere-box distance to the group's
// AABB), the light's bit in the group's light mask (atomicOr: the same masks whatever the order).
#include "light_cull_common.glsl"

layout(local_size_x = HV_CULL_BIN_LIGHTS) in;
layout(std430, binding = HV_BINDING_LIGHTS) readonly buffer LightBlock { GpuLight lights[]; };

void main() {
  uint i = u_batch.first + gl_GlobalInvocationID.x;
  if (i >= u_batch.end) return;
  vec4 world = lightCullSphere(lights[i]);
  vec3 c = (u_view * vec4(world.xyz, 1.0)).xyz;
  float r = world.w;
  uint type = uint(lightType(lights[i]));  // HV_LIGHT_POINT/SPHERE/TUBE = 0/1/2
  ivec4 rect;
  bool visible = type <= 2u && sphereTileRect(c, r, vec2(u_proj[0][0], u_proj[1][1]),
                                              u_frame_params.x, vec2(u_viewport.xy),
                                              ivec2(u_viewport.zw),
                                              vec2(HV_TILE_SIZE, HV_TILE_HEIGHT), rect);
  vec4 sphere = vec4(c, r);
  if (gl_GlobalInvocationID.y == 0u) {
    cull_lights[i].sphere = sphere;
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
    cull_lights[i].cone_apex = apex;
    cull_lights[i].cone_axis = axis;
    cull_lights[i].rect = visible ? uvec4(uint(rect.x) | (uint(rect.y) << HV_CULL_RECT_SHIFT),
                                          uint(rect.z) | (uint(rect.w) << HV_CULL_RECT_SHIFT),
                                          type, 0u)
                                  : uvec4(HV_CULL_RECT_EMPTY, 0u, 0u, 0u);
  }
  if (!visible) return;
  uvec4 g = uvec4(rect) / uint(HV_CULL_GROUP_TILES);  // the rectangle's groups
  uint band0 = gl_GlobalInvocationID.y * uint(HV_CULL_BIN_GROUP_ROWS);
  uint y0 = max(g.y, band0), y1 = min(g.w, band0 + uint(HV_CULL_BIN_GROUP_ROWS) - 1u);
  uint bit = 1u << ((i - u_batch.first) % 32u), w = (i - u_batch.first) / 32u;
  for (uint y = y0; y <= y1; ++y) {
    for (uint x = g.x; x <= g.z; ++x) {
      uint group = groupIndex(uvec2(x, y));
      vec4 lo = cull_bounds[groupBoundsAt(group)];
      if (lo.w != 0.0 && sphereTouchesBox(sphere, lo.xyz, cull_bounds[groupBoundsAt(group) + 1u].xyz)) {
        // The summary bit is set by the light that finds the word empty.
        uint at = groupMasksAt(group);
        if (atomicOr(cull_masks[at + u_batch.summary_words + w], bit) == 0u) {
          atomicOr(cull_masks[at + w / 32u], 1u << (w % 32u));
        }
      }
    }
  }
}
