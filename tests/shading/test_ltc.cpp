// The LTC integrals (shaders/common/ltc_integrals.glsl, ltc.glsl) and the committed table, run as
// C++: each closed form against a numerical integral of the same distribution, and the table's
// cells against the properties its fit guarantees.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "halfvec/shading/ltc_table.hpp"
#include "halfvec/shading/shading.hpp"

namespace {

namespace g = hv::glsl;
constexpr double kPi = 3.14159265358979323846;

// M (up to a positive factor) of an LTC: the inverse of its rows alpha M^-1.
glm::dmat3 ltcMatrix(const g::Ltc& l) {
  return glm::inverse(
      glm::transpose(glm::dmat3(glm::dvec3(l.i0), glm::dvec3(l.i1), glm::dvec3(l.i2))));
}

// Integral of the LTC over the directions where `inside` holds: the fraction of clamped-cosine
// samples w_o (cosine space) whose image M w_o is inside (the LTC's own density as the sampling
// pdf, so the estimate is a hit count). n points of a (0.5 + i) / n x golden-ratio lattice.
template <class F>
double ltcHitFraction(const g::Ltc& l, F inside, long n) {
  const glm::dmat3 M = ltcMatrix(l);
  long hit = 0;
  for (long i = 0; i < n; ++i) {
    const double u1 = (double(i) + 0.5) / double(n),
                 u2 = std::fmod(double(i) * 0.6180339887498949, 1.0);
    const double r = std::sqrt(u1), phi = 2.0 * kPi * u2;
    const glm::dvec3 wo(r * std::cos(phi), r * std::sin(phi), std::sqrt(1.0 - u1));
    if (inside(glm::normalize(M * wo))) ++hit;
  }
  return double(hit) / double(n);
}

// An LTC of made-up parameters (not a table cell): general widths, skew and tilt.
g::Ltc testLtc(std::mt19937_64& rng, float& alpha) {
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  alpha = 0.002f + 0.6f * u(rng);
  const float th = 1.3f * u(rng);
  const glm::vec3 V(std::sin(th), 0.0f, std::cos(th));
  const glm::vec3 shape(0.6f + u(rng), 0.4f + u(rng), -0.4f + 0.8f * u(rng));
  const float dx = -0.9f * u(rng);
  return g::makeLtcAxis({0, 0, 1}, V, alpha, shape, dx, std::sqrt(1.0f - dx * dx));
}

}  // namespace

// The sphere's integral under an LTC (its cone's image, an elliptical cone, in closed form)
// against the hit fraction of 4M LTC samples, for spheres whose image lies above the cosine
// horizon (there the closed form is exact; the horizon-straddling approximation is measured by the
// accuracy sweep). Tolerance: 4 standard errors of the count + 1e-4 relative.
TEST(LtcIntegrals, SphereMatchesMonteCarlo) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int checked = 0;
  for (int trial = 0; trial < 60 && checked < 25; ++trial) {
    float alpha = 0.0f;
    const g::Ltc l = testLtc(rng, alpha);
    const glm::dmat3 M = ltcMatrix(l);
    const glm::dvec3 axis = glm::normalize(M * glm::dvec3(0, 0, 1));
    const glm::dvec3 c = glm::normalize(
        axis + 2.0 * double(std::max(alpha, 0.05f)) * u(rng) *
                   glm::normalize(glm::dvec3(u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5)));
    const double r = 0.005 + 0.4 * u(rng) * u(rng);
    // Above the cosine horizon: the sphere cap's image has z > 0 (checked on its boundary).
    const double cosmax = std::sqrt(1.0 - r * r);
    const glm::vec3 F = g::ltcSphereFormFactor(l, glm::vec3(c), float(r));
    const double f = glm::length(glm::dvec3(F));
    if (F.z <= 0.0f || F.z * F.z < f * f * f) continue;  // cos^2 >= sin^2 of the equivalent cap
    const double exact = g::ltcSphereIntegral(l, glm::vec3(c), float(r));
    const long n = 4000000;
    const double mc = ltcHitFraction(
        l, [&](const glm::dvec3& w) { return glm::dot(w, c) >= cosmax; }, n);
    const double se = std::sqrt(std::max(mc * (1.0 - mc), 1e-12) / double(n));
    EXPECT_NEAR(exact, mc, 4.0 * se + 1e-4 * mc)
        << "alpha " << alpha << " r/d " << r << " trial " << trial;
    ++checked;
  }
  EXPECT_GE(checked, 20);
}

// Lambert's polygon formula: the rectangle's integral under an LTC against the hit fraction (ray
// vs the planar rectangle in double), for rectangles above the cosine horizon.
TEST(LtcIntegrals, QuadMatchesMonteCarlo) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int checked = 0;
  for (int trial = 0; trial < 40 && checked < 12; ++trial) {
    float alpha = 0.0f;
    const g::Ltc l = testLtc(rng, alpha);
    const glm::dvec3 axis = glm::normalize(ltcMatrix(l) * glm::dvec3(0, 0, 1));
    const glm::dvec3 center = axis + 0.3 * glm::dvec3(u(rng) - 0.5, u(rng) - 0.5, 0.0);
    const glm::dvec3 a = 0.3 * glm::normalize(glm::cross(center, glm::dvec3(0, 1, 0))) * u(rng);
    const glm::dvec3 b = 0.2 * glm::normalize(glm::cross(center, a)) * (0.2 + u(rng));
    const glm::vec3 p[4] = {glm::vec3(center - a - b), glm::vec3(center + a - b),
                            glm::vec3(center + a + b), glm::vec3(center - a + b)};
    glm::vec3 F = g::quadFormFactor(g::ltcToCosine(l, p[0]), g::ltcToCosine(l, p[1]),
                                    g::ltcToCosine(l, p[2]), g::ltcToCosine(l, p[3]));
    F *= glm::dot(F, g::ltcToCosine(l, glm::vec3(center))) >= 0.0f ? 1.0f : -1.0f;
    const double f = glm::length(glm::dvec3(F));
    if (F.z <= 0.0f || F.z * F.z < f * f * f) continue;  // keep rectangles above the horizon
    const glm::dvec3 n = glm::normalize(glm::cross(a, b));
    const double mc = ltcHitFraction(
        l,
        [&](const glm::dvec3& w) {
          const double t = glm::dot(center, n) / glm::dot(w, n);
          if (!(t > 0.0)) return false;
          const glm::dvec3 x = w * t - center;
          return std::abs(glm::dot(x, a)) <= glm::dot(a, a) &&
                 std::abs(glm::dot(x, b)) <= glm::dot(b, b);
        },
        2000000);
    const double se = std::sqrt(std::max(mc * (1.0 - mc), 1e-12) / 2e6);
    EXPECT_NEAR(F.z, mc, 4.0 * se + 2e-4 * mc) << "trial " << trial;
    ++checked;
  }
  EXPECT_GE(checked, 8);
}

// With the identity LTC the sphere's integral is its irradiance / pi: sin^2(sigma) times the
// horizon-clipped sphere factor (Lagarde & de Rousiers 2014; exact for a Lambertian emitter),
// above and across the horizon (the elliptical cone is then a circular cone: the sphere-cap
// horizon approximation is exact). Tolerance 2e-4 relative.
TEST(LtcIntegrals, IdentityLtcIsTheSphereIrradiance) {
  const g::Ltc l = g::ltcIdentity({0, 0, 1});
  for (float el : {90.0f, 45.0f, 10.0f, 3.0f, 0.0f, -3.0f}) {
    for (float r : {0.01f, 0.1f, 0.3f, 0.7f}) {
      const float e = el * float(kPi) / 180.0f;
      const glm::vec3 c(std::cos(e), 0.0f, std::sin(e));
      const double exact = double(r) * r * g::sphereHorizonFactor(c.z, r * r);
      const double ltc = g::ltcSphereIntegral(l, c, r);
      EXPECT_NEAR(ltc, exact, 2e-4 * exact + 1e-9) << "elevation " << el << " r/d " << r;
    }
  }
}

// Every cell of the committed table: widths > 0, a tilt within +-pi/2, a magnitude n_f in (0, 1] (a
// directional albedo with F = 1), a Fresnel weight integral in [0, n_f], and an LTC that
// integrates to 1: the integral of ltcDensity over the sphere, estimated from 4096 directions
// drawn half uniformly on the sphere and half from the LTC itself (balance heuristic), is 1 within
// 3% (the estimate's spread; a wrong Jacobian in ltcDensity is off by a factor).
TEST(LtcTable, CellsAreValidAndNormalized) {
  const std::span<const float> t = hv::ltcTableData();
  constexpr int n = HV_LTC_TABLE_SIZE;
  ASSERT_EQ(t.size(), size_t(n) * n * hv::kLtcFloatsPerCell);
  double worst = 0.0;
  for (int j = 0; j < n; j += 3) {
    for (int i = 0; i < n; i += 3) {
      const float* c = t.data() + (size_t(j) * n + size_t(i)) * hv::kLtcFloatsPerCell;
      ASSERT_GT(c[0], 0.0f);
      ASSERT_GT(c[1], 0.0f);
      ASSERT_LE(std::abs(c[3]), 1.5708f);  // the axis's tilt from the mirror direction
      EXPECT_GT(c[4], 0.0f);
      EXPECT_LE(c[4], 1.0f + 1e-4f);
      EXPECT_GE(c[5], 0.0f);
      EXPECT_LE(c[5], c[4]);
      const glm::vec2 rn = g::ltcCellParameters(i, j);
      const float alpha = rn.x * rn.x;
      const glm::vec3 V(std::sqrt(1.0f - rn.y * rn.y), 0.0f, rn.y);
      const g::Ltc l = g::makeLtc({0, 0, 1}, V, alpha, glm::vec4(c[0], c[1], c[2], c[3]));
      const glm::dmat3 M = ltcMatrix(l);
      const int m = 2048;
      double sum = 0.0;
      for (int k = 0; k < m; ++k) {
        const glm::vec2 u = g::hammersley(uint32_t(k), uint32_t(m));
        const double z = 1.0 - 2.0 * u.x, s = std::sqrt(std::max(0.0, 1.0 - z * z));
        const glm::dvec3 wu(s * std::cos(2.0 * kPi * u.y), s * std::sin(2.0 * kPi * u.y), z);
        const glm::dvec3 wl = glm::normalize(M * glm::dvec3(g::sampleCosineHemisphere(u)));
        for (const glm::dvec3& w : {wu, wl}) {
          const double d = g::ltcDensity(l, glm::vec3(w));
          sum += d / (m * (0.5 / (4.0 * kPi) + 0.5 * d));
        }
      }
      const double integral = 0.5 * sum;
      worst = std::max(worst, std::abs(integral - 1.0));
      EXPECT_NEAR(integral, 1.0, 0.03) << "cell " << i << ", " << j;
    }
  }
  std::printf("largest |integral - 1|: %.4f\n", worst);
}

// The fit's error per cell (the L1 distance between the cell's LTC and its normalized lobe, which
// bounds the relative error of any emitter's integral) is below a bound per region of N.V,
// measured when the table was generated (`halfvec ltc-fit`, which minimizes the L3 norm; the L1
// distance it reports): N.V >= 0.5: 0.164; N.V >= 0.2: 0.370; N.V >= 0.05: 0.668; below, the last
// row (N.V = HV_LTC_MIN_NOV): 1.745. There the lobe is a thin sheet along the horizon that no LTC
// follows pointwise, and the row is fitted to the lobe's integrals over caps as well (the cap
// term, ltc_fit.hpp), which trades pointwise distance for what lights see (0.779 with the norm
// alone; docs/lights.md). Bound = measured + 10%.
TEST(LtcTable, FitErrorBoundPerCell) {
  const std::span<const float> t = hv::ltcTableData();
  constexpr int n = HV_LTC_TABLE_SIZE;
  double worst[4] = {0, 0, 0, 0};
  for (int j = 0; j < n; ++j) {
    const float NoV = g::ltcCellParameters(0, j).y;
    const int region = NoV >= 0.5f ? 0 : NoV >= 0.2f ? 1 : NoV >= 0.05f ? 2 : 3;
    for (int i = 0; i < n; ++i) {
      const float e = t[(size_t(j) * n + size_t(i)) * hv::kLtcFloatsPerCell + 6];
      worst[region] = std::max(worst[region], double(e));
    }
  }
  std::printf("worst L1 distance: N.V >= 0.5 %.3f, >= 0.2 %.3f, >= 0.05 %.3f, below %.3f\n",
              worst[0], worst[1], worst[2], worst[3]);
  EXPECT_LT(worst[0], 0.18);
  EXPECT_LT(worst[1], 0.41);
  EXPECT_LT(worst[2], 0.735);
  EXPECT_LT(worst[3], 1.92);
}

// Thin cones: the table's LTC at roughness 0.1 and grazing views (N.V 0.03-0.06), spheres of r/d
// 0.02-0.2 in the lobe's tail well off the mirror direction, where the image of the sphere's cone
// is thin or elongated in cosine space (mu, l1 << l2). The float form factor against a double
// quadrature of the LTC's density over the cone (midpoint rule, 160 x 320 in polar coordinates
// around the cone's axis), for cones whose image lies above the cosine horizon at every quadrature
// point (there the form factor's z is the integral). With coneFormFactor's float eigenvalues
// alone, 135 of these 253 cones were off by more than 2x (worst 600x)
// (docs/lights.md, "Thin cones"); tolerance 0.5%.
TEST(LtcIntegrals, ThinConesInTheTailMatchQuadrature) {
  const glm::vec3 N(0, 0, 1);
  int checked = 0, within = 0;
  double worst = 0.0;
  for (float NoV : {0.03f, 0.045f, 0.06f}) {
    const glm::vec3 V(std::sqrt(1.0f - NoV * NoV), 0.0f, NoV);
    const float rough = 0.1f, alpha = rough * rough;
    const g::Ltc l = g::makeLtc(N, V, alpha, hv::ltcTableSample(0, g::ltcTableUv(rough, NoV)));
    const glm::dmat3 rows =
        glm::transpose(glm::dmat3(glm::dvec3(l.i0), glm::dvec3(l.i1), glm::dvec3(l.i2)));
    const double det_inv = glm::determinant(rows);
    auto density = [&](const glm::dvec3& w) {
      const glm::dvec3 x = rows * w;
      const double x2 = glm::dot(x, x);
      return std::max(x.z, 0.0) / kPi * det_inv / (x2 * x2);
    };
    for (float el : {5.0f, 15.0f, 35.0f, 60.0f}) {
      for (float az : {40.0f, 80.0f, 120.0f, 160.0f, -60.0f, -140.0f}) {
        for (float rd : {0.02f, 0.05f, 0.1f, 0.2f}) {
          const float e = float(el * kPi / 180.0), a = float(az * kPi / 180.0);
          // Azimuth from the mirror direction (-V's azimuth is 180 degrees).
          const glm::vec3 c(-std::cos(e) * std::cos(a), std::cos(e) * std::sin(a), std::sin(e));
          const glm::vec3 F = g::ltcSphereFormFactor(l, c, rd);
          const glm::dvec3 cd = glm::normalize(glm::dvec3(c));
          glm::dvec3 e1 = glm::normalize(glm::cross(cd, glm::dvec3(0, 0, 1)));
          const glm::dvec3 e2 = glm::cross(cd, e1);
          const double sigma = std::asin(double(rd));
          const int nt = 160, np = 320;
          double sum = 0.0;
          bool below = false;  // part of the cone's image below the cosine horizon
          for (int i = 0; i < nt; ++i) {
            const double th = sigma * (i + 0.5) / nt;
            for (int j = 0; j < np; ++j) {
              const double ph = 2.0 * kPi * (j + 0.5) / np;
              const glm::dvec3 w =
                  std::cos(th) * cd + std::sin(th) * (std::cos(ph) * e1 + std::sin(ph) * e2);
              sum += density(w) * std::sin(th);
              below |= (rows * w).z < 0.0;
            }
          }
          const double quad = sum * (sigma / nt) * (2.0 * kPi / np);
          if (below || quad <= 0.0) continue;
          const double rel = std::abs(double(F.z) - quad) / quad;
          ++checked;
          if (rel < 5e-3) {
            ++within;
            worst = std::max(worst, rel);
          } else {
            std::printf("off: N.V %g elevation %g azimuth %g r/d %g: %g vs %g\n", NoV, el, az, rd,
                        F.z, quad);
          }
        }
      }
    }
  }
  EXPECT_GE(checked, 250);
  EXPECT_EQ(within, checked);
  std::printf("thin cones: %d of %d within 0.5%%, worst of those %.3g\n", within, checked, worst);
}
