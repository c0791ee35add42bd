#version 450 core
// Light pass: for each lit pixel, sums the direct light of its tile's lights (or of every light in
// the brute-force baseline) into the HDR target, on top of the emissive the G-buffer pass wrote.
#include "../common/frame.glsl"
#include "../common/gbuffer.glsl"
#include "../common/lights.glsl"

layout(local_size_x = HV_TILE_SIZE, local_size_y = HV_TILE_SIZE) in;

layout(binding = 0) uniform sampler2D t_base_cavity;
layout(binding = 1) uniform sampler2D t_material;
layout(binding = 2) uniform sampler2D t_normal;
layout(binding = 3) uniform sampler2D t_depth;
layout(rgba16f, binding = 0) uniform image2D i_hdr;

layout(std430, binding = HV_BINDING_LIGHTS) readonly buffer LightBlock { GpuLight lights[]; };
#if !HV_CULLING_BRUTE_FORCE
layout(std430, binding = HV_BINDING_TILE_RANGES) readonly buffer TileRangeBlock { uvec2 tile_ranges[]; };
layout(std430, binding = HV_BINDING_TILE_INDICES) readonly buffer TileIndexBlock {
  uint tile_index_count;
  uint pad0, pad1, pad2;
  uint tile_indices[];
};
#endif

void main() {
  ivec2 px = ivec2(gl_GlobalInvocationID.xy);
  if (px.x >= int(u_viewport.x) || px.y >= int(u_viewport.y)) return;
  vec4 mat = texelFetch(t_material, px, 0);
  uint model = uint(mat.b * 255.0 + 0.5);
  if (model != HV_MODEL_DEFAULT_LIT) return;

  vec4 bc = texelFetch(t_base_cavity, px, 0);
  vec3 N = octDecode(texelFetch(t_normal, px, 0).xy);
  float depth = texelFetch(t_depth, px, 0).r;
  vec2 uv = (vec2(px) + 0.5) / vec2(u_viewport.xy);
  vec3 P = reconstructWorldPosition(uv, depth, u_inv_view_proj);
  vec3 V = normalize(u_camera_pos.xyz - P);
  Surface s = makeSurface(N, bc.rgb, mat.r, mat.g, bc.a);

  vec3 sum = vec3(0.0);
#if HV_CULLING_BRUTE_FORCE
  uint n = u_counts.x;
  for (uint i = 0u; i < n; ++i) sum += evaluateLight(lights[i], s, P, V);
#else
  uvec2 range = tile_ranges[gl_WorkGroupID.y * u_viewport.z + gl_WorkGroupID.x];
  uint end = min(range.x + range.y, u_counts.y);
  for (uint i = range.x; i < end; ++i) sum += evaluateLight(lights[tile_indices[i]], s, P, V);
#endif
  vec4 hdr = imageLoad(i_hdr, px);
  imageStore(i_hdr, px, vec4(min(hdr.rgb + sum, vec3(HV_HDR_MAX)), hdr.a));
}
