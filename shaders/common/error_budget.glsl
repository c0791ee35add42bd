// The error budget (settings.max_error, docs/lights.md "Error budget"): per pixel and light, the
// representative point's predicted error decides whether that light's specular is worth the LTC.
// Shared by GLSL and C++ (see halfvec/shading/glsl.hpp): the light pass, the generator of the
// table (`halfvec error-fit`, engine/eval/src/error_fit.cpp) and the calibration of
// `halfvec accuracy` run this very code.
//
// The table holds, per cell, t = ln(E_rp / R): the log of how much brighter the representative
// point (Karis 2013 eqs. 10, 11, 14) is than the exact integral of the same BRDF over a sphere
// light, measured against the reference (engine/reference) for a white f0 = 1 lobe. Its axes are
// what determine that error: the perceptual roughness, the light's angular radius (sin sigma =
// r / d), N.V, the angle between the light's center and the reflection ray R in units of the
// lobe's footprint 2 alpha + sigma (the sweep's unit, engine/eval light_accuracy.hpp sweepViews),
// and the azimuth of the light around R: toward N, sideways (either side: N, V and R are
// symmetric about their plane) or toward the horizon, where the point's error differs in sign as
// well as size (a mean over azimuths cancels it: docs/lights.md, "Error budget"). A sphere that
// straddles the horizon always takes the LTC: there the representative point ignores the horizon
// and is off without bound (docs/accuracy.md). Its cells are measured all the same: the cells of
// spheres just above the horizon interpolate toward them, where the point's error grows.
//
// Defines: HV_ERROR_BUDGET 0|1 (compiled only with a budget: render_settings.hpp max_error);
// HV_ERROR_TABLE_UNIT, the texture unit of the table (bindings.glsl: each pass has its own).
#ifndef HV_ERROR_BUDGET_GLSL
#define HV_ERROR_BUDGET_GLSL

#include "math.glsl"
#include "brdf.glsl"

#ifndef HV_ERROR_BUDGET
#define HV_ERROR_BUDGET 0
#endif
#if HV_ERROR_BUDGET && !defined(HV_CPP)
#include "bindings.glsl"
#ifndef HV_ERROR_TABLE_UNIT
#define HV_ERROR_TABLE_UNIT HV_UNIT_ERROR_TABLE
#endif
#endif

// Cells per axis. Texel ((m * HV_ERR_OFFSET_CELLS + l) * HV_ERR_ROUGHNESS_CELLS + i, j, k) of one
// R32F 3D texture holds cell (i roughness, j sin sigma, k N.V, l offset, m azimuth): linear
// filtering in x stays inside one (offset, azimuth) block (the roughness coordinate is clamped
// to it); the lookup takes the nearest offset and azimuth (sphereRpLogRatio).
#define HV_ERR_ROUGHNESS_CELLS 16
#define HV_ERR_SIN_CELLS 16
#define HV_ERR_NOV_CELLS 16
#define HV_ERR_OFFSET_CELLS 16
#define HV_ERR_AZIMUTH_CELLS 5  // cos(phi) from 1 (toward N) through 0 (sideways) to -1 (horizon)
#define HV_ERR_TEXELS_X (HV_ERR_ROUGHNESS_CELLS * HV_ERR_OFFSET_CELLS * HV_ERR_AZIMUTH_CELLS)
#define HV_ERR_CELLS (HV_ERR_TEXELS_X * HV_ERR_SIN_CELLS * HV_ERR_NOV_CELLS)
// Footprints per offset cell: the last cell, 3.75 footprints from R, stands for every farther one.
const float HV_ERR_OFFSET_STEP = 0.25f;
// The luminance the budget judges errors in (Rec. 709 weights, as tonemap.glsl).
const vec3 HV_ERR_LUMA = vec3(0.2126f, 0.7152f, 0.0722f);
// Smallest sin(sigma) and N.V of the table (below them, the first and last cells).
const float HV_ERR_MIN_SIN = 0.005f;
const float HV_ERR_MIN_NOV = 0.02f;

// Cell coordinates (0 .. cells - 1) of a configuration. Roughness, sin sigma and 1 - N.V on a
// square-root scale: more cells where the error changes fastest (glossy lobes, small lights,
// grazing views).
vec4 errorCellCoord(float roughness, float sin_sigma, float NoV, float offset) {
  float x = sqrt(saturate((roughness - HV_MIN_ROUGHNESS) / (1.0f - HV_MIN_ROUGHNESS)));
  float y = sqrt(saturate((sin_sigma - HV_ERR_MIN_SIN) / (1.0f - HV_ERR_MIN_SIN)));
  float z = sqrt(saturate((1.0f - NoV) / (1.0f - HV_ERR_MIN_NOV)));
  float w = saturate(offset / (HV_ERR_OFFSET_STEP * float(HV_ERR_OFFSET_CELLS - 1)));
  return vec4(x * float(HV_ERR_ROUGHNESS_CELLS - 1), y * float(HV_ERR_SIN_CELLS - 1),
              z * float(HV_ERR_NOV_CELLS - 1), w * float(HV_ERR_OFFSET_CELLS - 1));
}

// The configuration a cell is measured at (the inverse of errorCellCoord): roughness, sin sigma,
// N.V and the offset in footprints.
vec4 errorCellParameters(int i, int j, int k, int l) {
  float x = float(i) / float(HV_ERR_ROUGHNESS_CELLS - 1);
  float y = float(j) / float(HV_ERR_SIN_CELLS - 1);
  float z = float(k) / float(HV_ERR_NOV_CELLS - 1);
  return vec4(HV_MIN_ROUGHNESS + (1.0f - HV_MIN_ROUGHNESS) * x * x,
              HV_ERR_MIN_SIN + (1.0f - HV_ERR_MIN_SIN) * y * y,
              1.0f - (1.0f - HV_ERR_MIN_NOV) * z * z, HV_ERR_OFFSET_STEP * float(l));
}

// Azimuth coordinate (0 .. cells - 1) of cos(phi), phi the light's azimuth around R from the
// direction toward N; and the cos(phi) of azimuth cell m.
float errorAzimuthCoord(float cos_phi) {
  return (1.0f - clamp(cos_phi, -1.0f, 1.0f)) * 0.5f * float(HV_ERR_AZIMUTH_CELLS - 1);
}
float errorCellCosAzimuth(int m) { return 1.0f - 2.0f * float(m) / float(HV_ERR_AZIMUTH_CELLS - 1); }

// The lobe's footprint around R (radians): the unit of the offset axis.
float errorFootprint(float alpha, float sin_sigma) {
  return 2.0f * alpha + asin(min(sin_sigma, 1.0f));
}

#if HV_ERROR_BUDGET
// The table, sampled like the C++ side (halfvec/shading/error_table.hpp): trilinear, clamp to
// edge, level 0.
#ifdef HV_CPP
float errorTableFetch(vec3 uvw) { return ::hv::errorTableSample(uvw); }
#else
layout(binding = HV_ERROR_TABLE_UNIT) uniform sampler3D t_error_table;
float errorTableFetch(vec3 uvw) { return textureLod(t_error_table, uvw, 0.0f).r; }
#endif

// t = ln(E_rp / R) at a configuration: one trilinear fetch, blending roughness, sin sigma and
// N.V in the block of the nearest offset and azimuth. Blending those two as well (four fetches)
// cost more than the representative point itself on llvmpipe, and the nearest cell alone
// predicted the measured error far less often (docs/lights.md, "Error budget").
float sphereRpLogRatio(float roughness, float sin_sigma, float NoV, float offset, float cos_phi) {
  vec4 c = errorCellCoord(roughness, sin_sigma, NoV, offset);
  float block = floor(errorAzimuthCoord(cos_phi) + 0.5f) * float(HV_ERR_OFFSET_CELLS) +
                floor(c.w + 0.5f);
  vec3 uvw = vec3((block * float(HV_ERR_ROUGHNESS_CELLS) + c.x + 0.5f) / float(HV_ERR_TEXELS_X),
                  (c.y + 0.5f) / float(HV_ERR_SIN_CELLS), (c.z + 0.5f) / float(HV_ERR_NOV_CELLS));
  return errorTableFetch(uvw);
}

// The pixel-light pair's predicted error and radiance (x, y): with the exact specular estimated
// as E_rp e^-t, the error |E_rp - exact| and the radiance diffuse + exact, in luminance. The
// budget compares the two (sphereNeedsLtc): a glossy highlight under a dim diffuse needs the LTC,
// the same highlight on a bright diffuse may not.
vec2 predictedPairError(vec3 diffuse, vec3 rp_specular, float log_ratio) {
  vec3 exact = rp_specular * exp(-log_ratio);
  return vec2(dot(abs(rp_specular - exact), HV_ERR_LUMA), dot(diffuse + exact, HV_ERR_LUMA));
}

// The table's t for a sphere seen in direction L (unit, its center) under sin sigma, from the
// surface's N, its reflection ray R and N.V.
float sphereRpLogRatioAt(Surface s, vec3 R, float NoV, vec3 L, float sin_sigma) {
  float NoL = dot(s.N, L);
  float LoR = clamp(dot(L, R), -1.0f, 1.0f);
  float offset = acos(LoR) / errorFootprint(s.alpha, sin_sigma);
  // cos(phi): L's part across R along N's (the plane of N and R; R.N = N.V for the mirror ray),
  // over both parts' lengths; 0 where either is 0 (L on R, or R on N: every azimuth is alike).
  float across = (1.0f - LoR * LoR) * (1.0f - NoV * NoV);
  float cos_phi = (NoL - NoV * LoR) * inversesqrt(max(across, 1e-12f));
  cos_phi = across > 1e-12f ? cos_phi : 0.0f;
  return sphereRpLogRatio(s.roughness, sin_sigma, NoV, offset, cos_phi);
}

// A sphere (or the sun's disk) seen in direction L under sin sigma straddles the horizon, touches
// it, or holds the shading point (sin sigma > 1): the representative point is not predicted
// there. Touching counts, within a float rounding (1e-4 of sin sigma): a sphere tangent to the
// surface is the limit of the straddling ones, where the point's error grows without bound and
// the cells above the horizon interpolate toward it (the sweep's tangent configuration, r/d 0.5
// at elevation 30, measured 28% for the point, predicted 43%, and read 7.2% with the budget at
// 0.05 when its float test said "above": docs/lights.md, "Error budget").
bool sphereStraddles(Surface s, vec3 L, float sin_sigma) {
  return abs(dot(s.N, L)) <= sin_sigma * 1.0001f;
}

// The sphere light's (or the sun's) pair: the LTC where the table's predicted error exceeds the
// budget, and always where the sphere straddles the horizon.
bool sphereNeedsLtc(Surface s, vec3 R, float NoV, vec3 L, float sin_sigma, vec3 diffuse,
                    vec3 rp_specular, float max_error) {
  if (sphereStraddles(s, L, sin_sigma)) return true;
  vec2 e = predictedPairError(diffuse, rp_specular, sphereRpLogRatioAt(s, R, NoV, L, sin_sigma));
  return e.x > max_error * e.y;
}

// The predicted_error view's pair (light_shade.comp, HV_LIGHT_PROBE 3): predictedPairError, a
// straddling sphere counting its whole radiance as error; times the light's color (luminance)
// and the cavity, as combineTerms scales the pair.
vec2 sphereViewError(Surface s, vec3 R, float NoV, vec3 L, float sin_sigma, vec3 diffuse,
                     vec3 rp_specular, vec3 radiant) {
  vec2 e = predictedPairError(diffuse, rp_specular, sphereRpLogRatioAt(s, R, NoV, L, sin_sigma));
  vec2 pair = sphereStraddles(s, L, sin_sigma)
                  ? vec2(dot(diffuse + rp_specular, HV_ERR_LUMA))
                  : e;
  return pair * s.cavity * dot(radiant, HV_ERR_LUMA);
}
#endif

#endif
