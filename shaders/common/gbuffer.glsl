// G-buffer layout and encodings, shared by the passes and the C++ tests (docs/gbuffer.md).
//   RT0 RGBA8 sRGB : BaseColor.rgb (sRGB-encoded by the hardware), Cavity (linear alpha)
//   RT1 RGBA8      : Metallic, Roughness (perceptual), shading-model ID / 255, unused
//   RT2 RG16 snorm : octahedral normal (world space)
//   depth 32F      : reversed-Z depth; world position is reconstructed from it
// 16 bytes per pixel including depth. Emissive goes straight into the HDR target.
#ifndef HV_GBUFFER_GLSL
#define HV_GBUFFER_GLSL

#include "math.glsl"

// Shading-model IDs (hv::ShadingModel). 0 = background: the ambient pass draws the sky there.
const uint HV_MODEL_BACKGROUND = 0u;
const uint HV_MODEL_UNLIT = 1u;
const uint HV_MODEL_DEFAULT_LIT = 2u;

float signNotZero(float v) { return v >= 0.0f ? 1.0f : -1.0f; }

// Octahedral normal encoding (Meyer et al. 2010, "On floating-point normal vectors"; Cigolle et
// al. 2014, "A Survey of Efficient Representations for Independent Unit Vectors", alg. 1).
// Returns coordinates in [-1, 1]^2.
vec2 octEncode(vec3 n) {
  float l1 = abs(n.x) + abs(n.y) + abs(n.z);
  float px = n.x / l1;
  float py = n.y / l1;
  if (n.z < 0.0f) {
    float ox = (1.0f - abs(py)) * signNotZero(px);
    float oy = (1.0f - abs(px)) * signNotZero(py);
    px = ox;
    py = oy;
  }
  return vec2(px, py);
}

vec3 octDecode(vec2 e) {
  vec3 v = vec3(e.x, e.y, 1.0f - abs(e.x) - abs(e.y));
  // Fold the lower hemisphere back (Cigolle 2014); branch-free form of the same reflection.
  float t = max(-v.z, 0.0f);
  v.x += v.x >= 0.0f ? -t : t;
  v.y += v.y >= 0.0f ? -t : t;
  return normalize(v);
}

// The snorm16 quantization the RG16_SNORM target applies (GL 4.5 spec eq. 2.3), for CPU tests.
float quantizeSnorm16(float x) { return round(clamp(x, -1.0f, 1.0f) * 32767.0f) / 32767.0f; }
float quantizeUnorm10(float x) { return round(clamp(x, 0.0f, 1.0f) * 1023.0f) / 1023.0f; }

// Reversed-Z perspective: depth 1 at the near plane, 0 at infinity (precision of 32F depth is
// then nearly uniform in log distance). The position comes from the inverse view-projection.
vec3 reconstructWorldPosition(vec2 uv, float depth, mat4 inv_view_proj) {
  vec4 clip = vec4(uv.x * 2.0f - 1.0f, uv.y * 2.0f - 1.0f, depth, 1.0f);
  vec4 w = inv_view_proj * clip;
  return vec3(w.x, w.y, w.z) / w.w;
}

#endif
