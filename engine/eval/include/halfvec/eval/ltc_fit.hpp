// Fitting the LTC table of shaders/common/ltc.glsl to the engine's own specular lobe:
// GGX D x height-correlated Smith V x cos, F = 1, evaluated with the terms of brdf.glsl compiled
// as C++. Per cell of (roughness, N.V): the magnitude n_f and the Fresnel weight integral are
// integrated (not fitted); the widths a_x, a_y, the skew s of M and the tilt of its axis (started
// at the lobe's mean direction, which is not the best axis: fitting it too cut the distance below
// by 2x to 7x at roughness 0.045-0.1) are fitted by Nelder-Mead, minimizing
// integral |D_ltc - f cos / n_f|^3 over the sphere (the L3 norm, as Heitz et al. 2016 section 4:
// it weighs the lobe's peak, which small lights see, more than the L1 norm does; measured on the
// sphere sweep, docs/lights.md). In the cells of N.V <= cap_max_nov (the committed table: the
// last row, N.V = 0.02) and the glossy cells at grazing views (roughness <= cap_glossy_roughness,
// N.V <= cap_glossy_nov) the norm is taken relative to its value at the start, plus cap_weight
// times the relative squared error of the LTC's integrals over caps of 3, 14 and 29 degrees on
// the lobe (what sphere lights of those sizes see). There the lobe is a thin sheet along the
// horizon that no LTC follows pointwise, and lights see its integral; in every cell, the cap term
// shaded small lights near the horizon worse (docs/lights.md measures both). Each
// cell reports its L1 distance, which bounds the error of
// any emitter's integral: for every region P of directions, |integral over P of
// (D_ltc - f cos / n_f)| <= the distance, so a cell of distance e shades any light within e n_f
// of the exact lobe (before the horizon approximation). Deterministic: fixed
// Hammersley samples, cells of one N.V row fitted in order from rough to smooth, each starting
// from the previous one; rows in parallel (core's parallelFor). `halfvec ltc-fit` runs it and
// writes engine/shading/src/ltc_table.cpp.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace hv::eval {

// The parameters of one cell as the fit works with them (ltc.glsl): widths divided by alpha, the
// skew s, and the x component d_x of the lobe's mean direction in the frame (T1, T2, N); the table
// stores the axis as its tilt from the mirror direction instead (ltc.glsl, ltcTiltFromAxis).
struct LtcParams {
  float ax = 1.0f, ay = 1.0f, sk = 0.0f, dx = 0.0f;
};

// Integrals of the fitted lobe f (n.l) (F = 1) at one (roughness, N.V): n_f = its integral (the
// directional albedo), fresnel = integral of f (n.l) (1 - V.H)^5, mean = the unit mean direction
// (y = 0 by symmetry), from samples_per_dim^2 GGX visible-normal samples (Hammersley).
struct LtcLobeMoments {
  double norm = 0.0, fresnel = 0.0;
  glm::dvec3 mean{0.0, 0.0, 1.0};
};
LtcLobeMoments integrateLtcLobe(float roughness, float NoV, int samples_per_dim);

// The normalized lobe f (n.l) / norm at unit l (frame: N = +z, V = (sin, 0, N.V)); 0 below the
// horizon.
double ltcLobeValue(float roughness, float NoV, double norm, const glm::vec3& l);

// L1 distance integral |D_ltc - f (n.l) / n_f| over the sphere of the cell's LTC with parameters
// p, estimated by multiple importance sampling (balance heuristic) from samples_per_dim^2
// directions drawn from the lobe (GGX visible normals) and as many from the LTC.
double ltcFitError(const LtcParams& p, float roughness, float NoV, double norm,
                   int samples_per_dim);

struct LtcFitOptions {
  int size = 64;              // cells per side (must equal HV_LTC_TABLE_SIZE to be used)
  int fit_samples = 32;       // per dimension, per strategy, for the fit's error estimate
  int moment_samples = 256;   // per dimension, for n_f, the Fresnel integral and the mean
  int max_iterations = 400;   // Nelder-Mead iterations per cell
  double error_power = 3.0;   // the fit minimizes integral |D_ltc - lobe|^error_power
  double cap_weight = 100.0;  // + this x the caps' relative squared error (0: the norm alone)
  int cap_samples = 128;      // per dimension, for the lobe's integral over each cap
  double cap_max_nov = 0.03;  // the cap term only in the cells of N.V <= this (the last row)
  // and in the glossy cells of roughness <= cap_glossy_roughness up to N.V cap_glossy_nov (0: none)
  double cap_glossy_roughness = 0.28;
  double cap_glossy_nov = 0.15;
  int threads = 0;                                    // 0: all cores
  std::function<void(int done, int total)> progress;  // one call per finished row (may be empty)
};

struct LtcCell {
  LtcParams params;
  double norm = 0.0, fresnel = 0.0;
  double error = 0.0;  // the fitted cell's L1 distance (ltcFitError with the fit's samples)
  int iterations = 0;
};

// The relative squared error of the cell's LTC with parameters p over the fit's caps (the term
// cap_weight multiplies): sum over the caps of (integral of D_ltc - the lobe's)^2 / sum of the
// lobe's integrals^2, the LTC's integrals as ltcSphereIntegral shades a sphere light.
double ltcCapError(const LtcParams& p, float roughness, float NoV, double norm,
                   int samples_per_dim);

// One cell fitted from `start` (the previous cell of its row, or the identity for the first).
LtcCell fitLtcCell(float roughness, float NoV, const LtcParams& start, const LtcFitOptions& o);

struct LtcTable {
  int size = 0;
  std::vector<LtcCell> cells;  // row j (N.V index) after row j - 1
  const LtcCell& at(int i, int j) const { return cells[size_t(j) * size_t(size) + size_t(i)]; }
};

// The whole table: rows in parallel, each fitted from roughness 1 down to the minimum.
LtcTable fitLtcTable(const LtcFitOptions& o);

// The start of cell (i, j) in fitLtcTable: the fitted cell (i + 1, j), or the identity.
LtcParams ltcFitStart(const LtcTable& t, int i, int j);

// The C++ source of engine/shading/src/ltc_table.cpp for `t`, with a header naming `command`.
std::string ltcTableSource(const LtcTable& t, const LtcFitOptions& o, const std::string& command);

// A cache file of a fitted table: binary, keyed by the options and kLtcFitVersion (a fit with
// other options or another version of the fitting code does not match).
inline constexpr int kLtcFitVersion = 5;
std::string ltcCacheKey(const LtcFitOptions& o);
bool loadLtcCache(const std::string& path, const LtcFitOptions& o, LtcTable& t);
std::string ltcCacheBytes(const LtcTable& t, const LtcFitOptions& o);

}  // namespace hv::eval
