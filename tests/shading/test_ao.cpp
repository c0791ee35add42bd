// The ambient occlusion math of shaders/common/ao.glsl (compiled as C++): GTAO's slice integral
// (Jimenez et al. 2016, eq. 10) against numerical integration and, averaged over slices, the
// open hemisphere's visibility of exactly 1 for any normal; the multi-bounce fit's limits; the
// cone-cone specular occlusion's limits; the 4x4 noise pattern the denoise averages away.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "halfvec/shading/ao.hpp"

namespace g = hv::glsl;

namespace {

constexpr double kPi = 3.14159265358979323846;

// Midpoint-rule integral of cos(h - n)+ |sin h| over [h0, h1] (the slice measure of eq. 9 / 10).
double sliceNumeric(double h0, double h1, double n) {
  const int steps = 20000;
  double sum = 0.0;
  for (int i = 0; i < steps; ++i) {
    const double h = h0 + (h1 - h0) * (i + 0.5) / steps;
    sum += std::max(std::cos(h - n), 0.0) * std::abs(std::sin(h));
  }
  return sum * (h1 - h0) / steps;  // an open slice at n = 0 integrates to 1
}

// The slice geometry of gtao.comp for view vector V and normal N along screen angle phi, with
// open horizons (nothing occludes): projected normal length times the clamped slice integral.
double openSlice(glm::vec3 V, glm::vec3 N, float phi) {
  const glm::vec3 d3(std::cos(phi), std::sin(phi), 0.0f);
  const glm::vec3 ortho = glm::normalize(d3 - glm::dot(d3, V) * V);
  const glm::vec3 axis = glm::cross(ortho, V);
  const glm::vec3 pn = N - axis * glm::dot(N, axis);
  const float len = glm::length(pn);
  const float n = (glm::dot(pn, ortho) >= 0.0f ? 1.0f : -1.0f) *
                  std::acos(std::clamp(glm::dot(pn, V) / len, -1.0f, 1.0f));
  const float h0 = g::gtaoClampLow(-float(kPi), n), h1 = g::gtaoClampHigh(float(kPi), n);
  return len * g::gtaoSliceVisibility(h0, h1, n);
}

}  // namespace

TEST(Gtao, SliceIntegralMatchesQuadrature) {
  for (float n : {-1.2f, -0.4f, 0.0f, 0.3f, 1.0f}) {
    for (float h1 : {0.1f, 0.7f, 1.3f}) {
      for (float h0 : {-1.4f, -0.5f, -0.05f}) {
        const float c0 = g::gtaoClampLow(h0, n), c1 = g::gtaoClampHigh(h1, n);
        EXPECT_NEAR(g::gtaoSliceVisibility(c0, c1, n), sliceNumeric(c0, c1, n), 2e-5)
            << "n " << n << " h0 " << h0 << " h1 " << h1;
      }
    }
  }
  EXPECT_NEAR(g::gtaoSliceVisibility(-0.5f * float(kPi), 0.5f * float(kPi), 0.0f), 1.0, 1e-6);
  EXPECT_NEAR(g::gtaoSliceVisibility(0.0f, 0.0f, 0.0f), 0.0, 1e-6);  // fully occluded
}

// The cosine form of eq. 10 the AO pass runs equals the angle form with the clamps, for horizon
// cosines and normal angles over their whole ranges, and returns the clamped angles.
TEST(Gtao, SliceVisibilityFromCosinesMatchesAngles) {
  for (float n = -1.5f; n <= 1.5f; n += 0.1f) {
    for (float c0 = -1.0f; c0 <= 1.0f; c0 += 0.125f) {
      for (float c1 = -1.0f; c1 <= 1.0f; c1 += 0.125f) {
        const float a0 = g::gtaoClampLow(-std::acos(c0), n);
        const float a1 = g::gtaoClampHigh(std::acos(c1), n);
        float h0 = 0.0f, h1 = 0.0f;
        const float v = g::gtaoSliceVisibilityCos(c0, c1, n, std::cos(n), std::sin(n), h0, h1);
        EXPECT_NEAR(v, g::gtaoSliceVisibility(a0, a1, n), 2e-5f)
            << "n " << n << " c0 " << c0 << " c1 " << c1;
        EXPECT_NEAR(h0, a0, 1e-6f);
        EXPECT_NEAR(h1, a1, 1e-6f);
      }
    }
  }
}

// Averaged over the slices around V, the open hemisphere of any visible normal has visibility 1
// (eq. 9): what makes GTAO exactly 1 on an open plane, whatever the view angle, once the 4x4
// pattern's rotations are averaged.
TEST(Gtao, OpenHemisphereAveragesToOne) {
  const glm::vec3 V(0.0f, 0.0f, 1.0f);
  for (float tilt_deg : {0.0f, 20.0f, 45.0f, 70.0f, 85.0f}) {
    for (float az : {0.0f, 0.8f, 2.0f}) {
      const float t = glm::radians(tilt_deg);
      const glm::vec3 N(std::sin(t) * std::cos(az), std::sin(t) * std::sin(az), std::cos(t));
      const int slices = 4096;
      double sum = 0.0;
      for (int i = 0; i < slices; ++i) sum += openSlice(V, N, float(kPi * (i + 0.5) / slices));
      EXPECT_NEAR(sum / slices, 1.0, 1e-3) << "tilt " << tilt_deg << " az " << az;
      // The 16 rotations of a 4x4 block times each quality's directions: 16 or 32 slices.
      for (int q : {HV_AO_QUALITY_LOW, HV_AO_QUALITY_MEDIUM, HV_AO_QUALITY_HIGH}) {
        const int n = 16 * g::aoDirections(q);
        double block = 0.0;
        for (int i = 0; i < n; ++i) block += openSlice(V, N, float(kPi * (i + 0.5) / n));
        EXPECT_NEAR(block / n, 1.0, 5e-3) << "tilt " << tilt_deg << " quality " << q;
      }
    }
  }
}

TEST(Gtao, MultiBounceKeepsItsLimits) {
  for (float albedo : {0.0f, 0.3f, 0.9f}) {
    const glm::vec3 a(albedo);
    EXPECT_NEAR(g::gtaoMultiBounce(1.0f, a).x, 1.0f, 1e-3f);  // nothing occluded: no change
    EXPECT_NEAR(g::gtaoMultiBounce(0.0f, a).x, 0.0f, 1e-6f);  // nothing visible: no bounce
    for (float v : {0.2f, 0.5f, 0.8f}) EXPECT_GE(g::gtaoMultiBounce(v, a).x, v);
  }
  // Brighter albedo, more light back: monotone in albedo at a fixed visibility.
  EXPECT_LT(g::gtaoMultiBounce(0.5f, glm::vec3(0.1f)).x,
            g::gtaoMultiBounce(0.5f, glm::vec3(0.9f)).x);
}

TEST(Gtao, ConesOfVisibilityAndSpecular) {
  // A cone of half-angle a holds sin^2(a) of the cosine-weighted hemisphere.
  for (float A : {0.0f, 0.25f, 0.5f, 1.0f}) {
    const float c = g::visibilityConeCos(A);
    EXPECT_NEAR(1.0f - c * c, A, 1e-6f);
  }
  EXPECT_NEAR(g::specularConeCos(0.0f), 1.0f, 1e-6f);  // a mirror: a line
  EXPECT_NEAR(g::specularConeCos(1.0f), 0.0f, 1e-6f);  // alpha 1: half of the lobe in 90 degrees
  // Nested caps: the smaller one; disjoint: 0; the same cap: itself.
  EXPECT_NEAR(g::capIntersectionOver2Pi(0.9f, 0.5f, 1.0f), 0.1f, 1e-5f);
  EXPECT_NEAR(g::capIntersectionOver2Pi(0.95f, 0.95f, std::cos(1.0f)), 0.0f, 1e-6f);
  EXPECT_NEAR(g::capIntersectionOver2Pi(0.7f, 0.7f, 1.0f), 0.3f, 1e-5f);
  const glm::vec3 up(0.0f, 0.0f, 1.0f);
  EXPECT_NEAR(g::specularOcclusionCone(up, up, up, 1.0f, 0.3f), 1.0f, 1e-5f);  // open, R = B
  EXPECT_NEAR(g::specularOcclusionCone(up, up, up, 0.0f, 0.3f), 0.0f, 1e-5f);  // none visible
  // An open surface (visibility 1, B = N) is never occluded, even where a rough lobe's cone
  // dips below the horizon.
  for (float deg : {0.0f, 30.0f, 60.0f, 85.0f}) {
    const glm::vec3 R(std::sin(glm::radians(deg)), 0.0f, std::cos(glm::radians(deg)));
    EXPECT_NEAR(g::specularOcclusionCone(up, up, R, 1.0f, 0.8f), 1.0f, 1e-5f) << deg;
  }
  // Partial overlap lies between, and falls as R turns away from the bent normal.
  float last = 1.0f;
  for (float deg : {10.0f, 30.0f, 50.0f, 70.0f}) {
    const glm::vec3 R(std::sin(glm::radians(deg)), 0.0f, std::cos(glm::radians(deg)));
    const float so = g::specularOcclusionCone(up, up, R, 0.6f, 0.5f);
    EXPECT_LE(so, last + 1e-6f) << deg;
    EXPECT_GE(so, 0.0f);
    last = so;
  }
  EXPECT_LT(last, 0.9f);
}

// Every 4x4 window of the pattern holds all 16 rotations and all 16 step offsets.
TEST(Gtao, NoisePatternCoversSixteenValuesPerBlock) {
  for (int oy = 0; oy < 4; ++oy) {
    for (int ox = 0; ox < 4; ++ox) {
      std::set<float> rot, off;
      for (int y = 0; y < 4; ++y) {
        for (int x = 0; x < 4; ++x) {
          const glm::vec2 n = g::gtaoNoise(ox + x + 37, oy + y + 11);
          rot.insert(n.x);
          off.insert(n.y);
          EXPECT_GT(n.x, 0.0f);
          EXPECT_LT(n.x, 1.0f);
        }
      }
      EXPECT_EQ(rot.size(), 16u);
      EXPECT_EQ(off.size(), 16u);
    }
  }
}
