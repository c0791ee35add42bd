// Tone mapping and display encoding, shared with C++ (tests compare the GPU output with it).
#ifndef HV_TONEMAP_GLSL
#define HV_TONEMAP_GLSL

#include "math.glsl"

#ifndef HV_TONEMAP
#define HV_TONEMAP 0  // 0 Reinhard per channel, 1 Reinhard on luminance, 2 none (clamp)
#endif
#ifndef HV_GAMMA
#define HV_GAMMA 0  // 0 gamma 2.2, 1 exact sRGB (IEC 61966-2-1)
#endif

// Reinhard et al. 2002, "Photographic Tone Reproduction for Digital Images", eq. 3: L/(1+L).
vec3 reinhard(vec3 c) { return c / (vec3(1.0f) + c); }

// The same curve applied to luminance (Rec. 709 weights), colors scaled by the ratio.
vec3 reinhardLuminance(vec3 c) {
  float l = dot(c, vec3(0.2126f, 0.7152f, 0.0722f));
  return c * (1.0f / (1.0f + l));
}

// IEC 61966-2-1 sRGB encoding.
float srgbEncode(float x) {
  return x <= 0.0031308f ? 12.92f * x : 1.055f * pow(x, 1.0f / 2.4f) - 0.055f;
}

vec3 outputTransform(vec3 c) {
  c = max(c, vec3(0.0f));
#if HV_TONEMAP == 0
  c = reinhard(c);
#elif HV_TONEMAP == 1
  c = reinhardLuminance(c);
#endif
  c = saturate(c);
#if HV_GAMMA == 0
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
