// G-buffer layout and encodings, shared by the passes and the C++ tests (docs/gbuffer.md).
//   RT0 RGBA8 sRGB : BaseColor.rgb (sRGB-encoded by the hardware), Cavity (linear alpha)
//   RT1 RGBA8      : Metallic, Roughness high byte, shading-model ID / 255, Roughness low byte
//                    (perceptual roughness in 16 bits: encodeRoughness16, docs/gbuffer.md)
//   RT2 RG16 snorm : octahedral normal (world space)
//   depth 32F      : reversed-Z depth; world position is reconstructed from it
//   RT3 RGBA16 snorm (scenes with a clear_coat material only): the coat's octahedral normal (xy),
//                    layer weight (z) and perceptual roughness (w) (encodeCoat)
// 16 bytes per pixel including depth, 24 with the coat target. Emissive goes straight into the
// HDR target.
#ifndef HV_GBUFFER_GLSL
#define HV_GBUFFER_GLSL

#include "math.glsl"

// Shading-model IDs (hv::ShadingModel). 0 = background: the ambient pass draws the sky there.
const uint HV_MODEL_BACKGROUND = 0u;
const uint HV_MODEL_UNLIT = 1u;
const uint HV_MODEL_DEFAULT_LIT = 2u;
const uint HV_MODEL_CLEAR_COAT = 3u;  // default lit under a clear coat (clear_coat.glsl)

// The models the light and ambient passes light (hv::isLit).
bool isLitModel(uint id) { return id == HV_MODEL_DEFAULT_LIT || id == HV_MODEL_CLEAR_COAT; }

// The shading-model ID in RT1's blue channel, written as ID / 255 (which the unorm8 target stores
// exactly, as the roughness bytes below) and read back as the nearest code. The one encoding:
// gbuffer.frag writes it, the light, ambient and debug-view passes and the C++ read-backs
// (Renderer::readGBuffer, Renderer::lightWork) decode it.
float encodeShadingModel(uint id) { return float(id) / 255.0f; }
uint decodeShadingModel(float stored) { return uint(stored * 255.0f + 0.5f); }

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
// The unorm8 quantization of an 8-bit target channel (GL 4.5 spec eq. 2.3, rounded to nearest).
float quantizeUnorm8(float x) { return round(clamp(x, 0.0f, 1.0f) * 255.0f) / 255.0f; }

// Perceptual roughness in 16 bits, split over two unorm8 channels of RT1 (high byte, low byte).
// One 8-bit code moves the GGX highlight peak (1 / (pi alpha^2), alpha = roughness^2: 4x the
// relative roughness step) by up to 17% at the minimum roughness 0.045 and 8% at 0.1; 16 bits
// keep it below 0.07% over 0.045-1 (measured in tests/shading/test_gbuffer_encoding.cpp,
// docs/gbuffer.md). Each byte is written as k / 255, which the unorm8 target stores exactly.
vec2 encodeRoughness16(float roughness) {
  float q = round(clamp(roughness, 0.0f, 1.0f) * 65535.0f);
  float high = floor(q / 256.0f);
  return vec2(high / 255.0f, (q - high * 256.0f) / 255.0f);
}

// `e` = (high, low) as read back from the unorm8 channels.
float decodeRoughness16(vec2 e) {
  return (round(e.x * 255.0f) * 256.0f + round(e.y * 255.0f)) / 65535.0f;
}

// The coat target: octahedral normal, weight and roughness, each a snorm16 (15 bits over 0..1:
// a roughness step of 3e-5, below the 16 bits of the base's at its 0.045 minimum).
vec4 encodeCoat(vec3 nc, float clearcoat, float roughness) {
  return vec4(octEncode(nc), clamp(clearcoat, 0.0f, 1.0f), clamp(roughness, 0.0f, 1.0f));
}

// Reversed-Z perspective: depth 1 at the near plane, 0 at infinity (precision of 32F depth is
// then nearly uniform in log distance). The position comes from the inverse view-projection.
vec3 reconstructWorldPosition(vec2 uv, float depth, mat4 inv_view_proj) {
  vec4 clip = vec4(uv.x * 2.0f - 1.0f, uv.y * 2.0f - 1.0f, depth, 1.0f);
  vec4 w = inv_view_proj * clip;
  return vec3(w.x, w.y, w.z) / w.w;
}

// The shading normal a surface is lit with, given the unit direction V to the viewer: N itself
// where it faces the viewer, else N reflected about the plane across V, N - 2 (N.V) V (unit, and
// N'.V = -N.V > 0). A normal map or an interpolated vertex normal can face away from the viewer on
// a face that does not (Schuessler et al. 2017, "Microfacet-based Normal Mapping for Robust Monte
// Carlo Path Tracing", introduction, list such back-facing normals among normal mapping's
// problems): the microfacet BRDF is then no reflectance. With N.V clamped to HV_MIN_NOV
// (brdf.glsl), H = (V + L) / |V + L| lies along N for L near -V, where D and the V term peak, and a
// Monte Carlo estimate of it never converges (docs/gbuffer.md, "Normals facing away from the
// viewer"). Reflecting N keeps the shading continuous at N.V = 0 (N' = N there) and every view
// above the horizon of the normal the BRDF sees. The G-buffer stores this normal, so the deferred
// passes, the forward pass and the reference (which reads the G-buffer) shade the same one.
vec3 viewFacingNormal(vec3 N, vec3 V) { return N - (2.0f * min(dot(N, V), 0.0f)) * V; }

#endif
