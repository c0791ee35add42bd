#version 450 core
// The G-buffer's base color and cavity as the passes read them (render::Renderer::readGBuffer):
// each texel fetched through the SRGB8_ALPHA8 target's own decode into an RGBA32F image, so that
// the CPU reference shades the very values the light and ambient passes do. The GL spec lets an
// implementation's sRGB decode differ from the exact curve (GL 4.5 section 8.24: "approximately
// equal"), and the reference measures the shading's error alone; the other targets (unorm,
// snorm, float) convert exactly by the spec and are read back as they are.
#include "../common/bindings.glsl"

layout(local_size_x = HV_TILE_SIZE, local_size_y = HV_TILE_SIZE) in;

layout(binding = HV_UNIT_BASE_CAVITY) uniform sampler2D t_base_cavity;
layout(rgba32f, binding = HV_IMAGE_READBACK) uniform writeonly image2D i_decoded;

void main() {
  ivec2 px = ivec2(gl_GlobalInvocationID.xy);
  ivec2 size = textureSize(t_base_cavity, 0);
  if (px.x >= size.x || px.y >= size.y) return;
  imageStore(i_decoded, px, texelFetch(t_base_cavity, px, 0));
}
