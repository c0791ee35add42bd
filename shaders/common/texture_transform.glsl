// KHR_texture_transform (Khronos, "KHR_texture_transform" extension specification): a texture's
// UV is mapped as uv' = T(offset) * R(rotation) * S(scale) * uv, with
//   R = | cos r   sin r |    (rotation in radians, counter-clockwise in UV space, whose v axis
//       | -sin r  cos r |     points down the image).
// The C++ side (packMaterial) builds the linear part once per material; the G-buffer pass applies
// it per pixel. Shared with C++ (tests check the matrix against the extension's examples).
#ifndef HV_TEXTURE_TRANSFORM_GLSL
#define HV_TEXTURE_TRANSFORM_GLSL

// R * S as its two columns: (x, y) = first column, (z, w) = second column.
vec4 textureTransformLinear(vec2 scale, float rotation) {
  float c = cos(rotation);
  float s = sin(rotation);
  return vec4(c * scale.x, -s * scale.x, s * scale.y, c * scale.y);
}

// uv' = (R * S) * uv + offset, `linear` from textureTransformLinear.
vec2 applyTextureTransform(vec2 uv, vec4 linear, vec2 offset) {
  return vec2(linear.x * uv.x + linear.z * uv.y + offset.x,
              linear.y * uv.x + linear.w * uv.y + offset.y);
}

#endif
