// Tone mapping and display encoding, shared with C++ (tests compare the GPU output with it).
#ifndef HV_TONEMAP_GLSL
#define HV_TONEMAP_GLSL

#include "math.glsl"
#include "setting_values.glsl"

#ifndef HV_TONEMAP
#define HV_TONEMAP HV_TONEMAP_REINHARD
#endif
#ifndef HV_GAMMA
#define HV_GAMMA HV_GAMMA_22
#endif

// Reinhard et al. 2002, "Photographic Tone Reproduction for Digital Images", eq. 3: L/(1+L).
vec3 reinhard(vec3 c) { return c / (vec3(1.0f) + c); }

// The same curve applied to luminance (Rec. 709 weights), colors scaled by the ratio.
vec3 reinhardLuminance(vec3 c) {
  float l = dot(c, vec3(0.2126f, 0.7152f, 0.0722f));
  return c * (1.0f / (1.0f + l));
}

// Khronos PBR Neutral (Khronos Group 2024, "Khronos PBR Neutral Tone Mapper" specification):
// base colors under unit white light come out as they are (up to a small black offset), and only
// the brightest channel is compressed above 0.76, with a desaturation towards white that grows
// with the compression.
vec3 pbrNeutral(vec3 c) {
  const float start_compression = 0.8f - 0.04f;
  const float desaturation = 0.15f;
  float x = min(c.x, min(c.y, c.z));
  // Black offset: a quadratic toe below 0.08 (value and slope continuous at 0.08), 0.04 above.
  float offset = x < 0.08f ? x - 6.25f * x * x : 0.04f;
  c -= vec3(offset);
  float peak = max(c.x, max(c.y, c.z));
  if (peak < start_compression) return c;
  const float d = 1.0f - start_compression;
  float new_peak = 1.0f - d * d / (peak + d - start_compression);
  c *= new_peak / peak;
  float g = 1.0f - 1.0f / (desaturation * (peak - new_peak) + 1.0f);
  return mix(c, vec3(new_peak), g);
}

// ACES filmic curve, Narkowicz 2016, "ACES Filmic Tone Mapping Curve": a rational fit (max error
// 0.0138) of the luminance of ACES's RRT + ODT (Rec. 709), pre-exposed so that 1 maps to ~0.8,
// applied per channel. Monotonic on [0, inf) (the derivative's numerator is 1.408 x^2 +
// 0.7028 x + 0.0042), reaches 1 at x = 7.24 (clamped after).
vec3 acesFitted(vec3 x) {
  const float a = 2.51f, b = 0.03f, c = 2.43f, d = 0.59f, e = 0.14f;
  return (x * (a * x + vec3(b))) / (x * (c * x + vec3(d)) + vec3(e));
}

// IEC 61966-2-1 sRGB encoding.
float srgbEncode(float x) {
  return x <= 0.0031308f ? 12.92f * x : 1.055f * pow(x, 1.0f / 2.4f) - 0.055f;
}

vec3 outputTransform(vec3 c) {
  c = max(c, vec3(0.0f));
#if HV_TONEMAP == HV_TONEMAP_REINHARD
  c = reinhard(c);
#elif HV_TONEMAP == HV_TONEMAP_REINHARD_LUMINANCE
  c = reinhardLuminance(c);
#elif HV_TONEMAP == HV_TONEMAP_PBR_NEUTRAL
  c = pbrNeutral(c);
#elif HV_TONEMAP == HV_TONEMAP_ACES
  c = acesFitted(c);
#endif
  c = saturate(c);
#if HV_GAMMA == HV_GAMMA_22
  return pow(c, vec3(1.0f / 2.2f));
#else
  return vec3(srgbEncode(c.x), srgbEncode(c.y), srgbEncode(c.z));
#endif
}

// Triangular-distributed noise in [-1, 1] (Gjoel 2016, "Banding in Games"), from the
// interleaved-gradient hash of Jimenez 2014.
float ditherNoise(vec2 p) {
  float a = fract(52.9829189f * fract(dot(p, vec2(0.06711056f, 0.00583715f))));
  float b = fract(52.9829189f * fract(dot(p + vec2(17.0f, 59.0f), vec2(0.06711056f, 0.00583715f))));
  return a + b - 1.0f;
}

#endif
