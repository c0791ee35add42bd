#version 450 core
// Debug views of the G-buffer channels and of the light culling (u_debug_view selects,
// hv::render::DebugView). Values are shown as stored, without tone mapping.
#include "../common/frame.glsl"
#include "../common/gbuffer.glsl"

layout(binding = HV_UNIT_BASE_CAVITY) uniform sampler2D t_base_cavity;
layout(binding = HV_UNIT_MATERIAL) uniform sampler2D t_material;
layout(binding = HV_UNIT_NORMAL) uniform sampler2D t_normal;
layout(binding = HV_UNIT_DEPTH) uniform sampler2D t_depth;
layout(std430, binding = HV_BINDING_TILE_RANGES) readonly buffer TileRangeBlock { uvec2 tile_ranges[]; };
layout(binding = HV_UNIT_DEBUG_HDR) uniform sampler2D t_hdr;

layout(location = 0) in vec2 v_uv;
layout(location = 0) out vec4 o_color;

vec3 heat(float t) {  // blue -> green -> red
  t = clamp(t, 0.0, 1.0);
  return clamp(vec3(2.0 * t - 0.5, 1.0 - abs(2.0 * t - 1.0) * 1.2, 1.5 - 2.0 * t), 0.0, 1.0);
}

void main() {
  ivec2 px = ivec2(gl_FragCoord.xy);
  vec4 bc = texelFetch(t_base_cavity, px, 0);
  vec4 mat = texelFetch(t_material, px, 0);
  uint model = decodeShadingModel(mat.b);
  vec3 c = vec3(0.0);
  switch (u_debug_view) {
    case 1u: c = pow(bc.rgb, vec3(1.0 / 2.2)); break;  // base color, display-encoded
    case 2u: c = vec3(mat.r); break;
    case 3u: c = vec3(decodeRoughness16(mat.ga)); break;
    case 4u: c = vec3(bc.a); break;
    case 5u: c = model == HV_MODEL_BACKGROUND ? vec3(0.0)
                                              : octDecode(texelFetch(t_normal, px, 0).xy) * 0.5 + 0.5; break;
    case 6u: {
      float d = texelFetch(t_depth, px, 0).r;  // reversed Z: show view distance on a log scale
      c = d > 0.0 ? vec3(clamp(1.0 - log2(u_frame_params.x / d + 1.0) / 10.0, 0.0, 1.0)) : vec3(0.0);
      break;
    }
    case 7u: c = model == HV_MODEL_BACKGROUND ? vec3(0.0)
               : model == HV_MODEL_UNLIT ? vec3(1.0, 0.8, 0.2) : vec3(0.2, 0.6, 1.0); break;
    case 8u: {
      uvec2 tile = uvec2(px) / uvec2(HV_TILE_SIZE, HV_TILE_HEIGHT);
      uint n = tile_ranges[tile.y * u_viewport.z + tile.x].y;
      c = n == 0u ? vec3(0.0) : heat(log2(float(n) + 1.0) / 10.0);  // 1 .. 1023 lights
      break;
    }
    case 14u: {
      // predicted_error: the light pass's (error, radiance, lit) (light_shade.comp, probe 3);
      // the error relative to the radiance on a log scale, 0.1% blue .. 100% red, 3% green.
      vec3 e = texelFetch(t_hdr, px, 0).rgb;
      float rel = e.x / max(e.y, 1e-20);
      c = e.z > 0.5 ? heat((log(max(rel, 1e-4)) / log(10.0) + 3.0) / 3.0) : vec3(0.0);
      break;
    }
  }
  o_color = vec4(c, 1.0);
}
