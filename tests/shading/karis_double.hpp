// Karis 2013's specular lobe in double precision, written from the paper independently of
// brdf.glsl: the yardstick the float shaders are measured against (test_brdf.cpp, test_lights.cpp).
#pragma once

#include <algorithm>

namespace hv::test {

// D V for a white metal (F = 1): eq. 2, GGX D with alpha = roughness^2, and eq. 4, Schlick-GGX
// G / (4 N.L N.V) with the Disney remap k = (roughness + 1)^2 / 8. Roughness is clamped to 0.045
// (HV_MIN_ROUGHNESS), as makeSurface does.
inline double karisSpecularDouble(double roughness, double NoH, double NoV, double NoL) {
  constexpr double kPi = 3.14159265358979323846;
  const double r = std::max(roughness, 0.045);
  const double a2 = r * r * r * r;
  const double d = NoH * NoH * (a2 - 1.0) + 1.0;
  const double k = (r + 1.0) * (r + 1.0) / 8.0;
  return a2 / (kPi * d * d) * 0.25 / ((NoV * (1.0 - k) + k) * (NoL * (1.0 - k) + k));
}

}  // namespace hv::test
