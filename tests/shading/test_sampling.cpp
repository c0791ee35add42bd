// Samplers of shaders/common/sampling.glsl, run as C++.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "halfvec/shading/shading.hpp"

namespace {

namespace g = hv::glsl;
constexpr double kPi = 3.14159265358979323846;

// Same quadrature as test_brdf.cpp: integral over mu in [0,1], mu = 1 - w, w log-spaced.
double integrateMu(const std::function<double(double)>& f, int n = 4000) {
  const double lo = std::log(1e-10), h = -lo / n;
  double sum = 0.0;
  for (int i = 0; i <= n; ++i) {
    double w = std::exp(lo + h * i);
    double wt = (i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0);
    sum += wt * f(1.0 - w) * w;
  }
  return sum * h / 3.0;
}

TEST(Sampling, HammersleyValues) {
  // Radical inverse of 1, 2, 3 in base 2: 0.5, 0.25, 0.75; i = 0 gives (0, 0).
  EXPECT_FLOAT_EQ(g::hammersley(0u, 4u).y, 0.0f);
  EXPECT_FLOAT_EQ(g::hammersley(1u, 4u).x, 0.25f);
  EXPECT_FLOAT_EQ(g::hammersley(1u, 4u).y, 0.5f);
  EXPECT_FLOAT_EQ(g::hammersley(2u, 4u).y, 0.25f);
  EXPECT_FLOAT_EQ(g::hammersley(3u, 4u).y, 0.75f);
  EXPECT_FLOAT_EQ(g::hammersley(5u, 8u).y, 0.625f);  // 101b -> 0.101b
  EXPECT_LT(g::hammersley(0xFFFFFFFFu, 1u).y, 1.0f);
}

// Duff et al. frame: orthonormal and right-handed to 1e-5 for normals all over the sphere,
// including the poles (the N.z = -1 case is the one Frisvad's original failed on).
TEST(Sampling, TangentFrameOrthonormal) {
  std::vector<glm::vec3> normals = {{0, 0, 1}, {0, 0, -1}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}};
  for (int i = 0; i < 200; ++i) {
    glm::vec2 u = g::hammersley(uint32_t(i), 200u);
    float z = 1.0f - 2.0f * u.x, r = std::sqrt(std::max(0.0f, 1 - z * z));
    normals.push_back({r * std::cos(6.2831853f * u.y), r * std::sin(6.2831853f * u.y), z});
  }
  normals.push_back(glm::normalize(glm::vec3(1e-4f, 0, -1)));
  for (glm::vec3 N : normals) {
    glm::vec3 T, B;
    g::tangentFrame(N, T, B);
    EXPECT_NEAR(glm::length(T), 1.0f, 1e-5f);
    EXPECT_NEAR(glm::length(B), 1.0f, 1e-5f);
    EXPECT_NEAR(glm::dot(T, B), 0.0f, 1e-5f);
    EXPECT_NEAR(glm::dot(T, N), 0.0f, 1e-5f);
    EXPECT_NEAR(glm::dot(B, N), 0.0f, 1e-5f);
    EXPECT_NEAR(glm::dot(glm::cross(T, B), N), 1.0f, 1e-5f);
  }
}

// importanceSampleGGX draws H with pdf D(h)(n.h): (a) the estimator of integral D(h)(n.h) dw
// with that pdf is exactly 1 per sample (pdf formula consistent with D); (b) the sample moments
// E[(n.h)^k] and E[(t.h)^2] match the quadrature of the same moments under D(h)(n.h), which fails
// if the sampler and pdfGGX disagree. 4096 Hammersley samples; tolerance 1e-2 absolute.
TEST(Sampling, ImportanceSampleGGXMatchesPdf) {
  const glm::vec3 N = glm::normalize(glm::vec3(0.3f, -0.5f, 0.8f));
  glm::vec3 T, B;
  g::tangentFrame(N, T, B);
  const uint32_t n = 4096;
  for (float alpha : {0.05f, 0.2f, 0.5f, 1.0f}) {
    double est = 0, m2 = 0, m8 = 0, t2 = 0;
    for (uint32_t i = 0; i < n; ++i) {
      glm::vec3 H = g::importanceSampleGGX(g::hammersley(i, n), alpha, N);
      ASSERT_NEAR(glm::length(H), 1.0f, 1e-4f);
      float NoH = glm::dot(N, H);
      ASSERT_GE(NoH, 0.0f);
      est += g::D_GGX(alpha, NoH) * NoH / g::pdfGGX(alpha, NoH);
      m2 += NoH * NoH;
      m8 += std::pow(NoH, 8.0);
      t2 += glm::dot(T, H) * glm::dot(T, H);
    }
    auto moment = [&](double k) {
      return 2 * kPi * integrateMu([&](double mu) {
               return std::pow(mu, k) * g::D_GGX(alpha, float(mu)) * mu;
             });
    };
    EXPECT_NEAR(est / n, 1.0, 1e-5);
    EXPECT_NEAR(m2 / n, moment(2), 1e-2) << "alpha " << alpha;
    EXPECT_NEAR(m8 / n, moment(8), 1e-2) << "alpha " << alpha;
    // Isotropy: E[(t.h)^2] = (1 - E[(n.h)^2]) / 2.
    EXPECT_NEAR(t2 / n, 0.5 * (1.0 - moment(2)), 1e-2) << "alpha " << alpha;
  }
}

// Directional albedo of GGX + Smith correlated (F = 1) three ways, which must agree to 1%:
// quadrature over H, importance sampling with pdfGGX (L pdf = D NoH / (4 VoH)) and VNDF sampling
// with pdfGGXVNDF (L pdf = D_V / (4 VoH)). Checks both samplers against their pdfs.
TEST(Sampling, AlbedoEstimatorsAgree) {
  for (float alpha : {0.1f, 0.4f, 0.9f}) {
    for (float NoV : {0.2f, 0.7f, 1.0f}) {
      glm::vec3 V(std::sqrt(1 - NoV * NoV), 0, NoV);
      auto integrand = [&](glm::vec3 H) {  // f NoL as a function of H, before the Jacobian
        float VoH = glm::dot(V, H);
        glm::vec3 L = 2.0f * VoH * H - V;
        if (VoH <= 0.0f || L.z <= 0.0f) return 0.0;
        return double(g::D_GGX(alpha, H.z) * g::V_SmithGGXCorrelated(alpha, NoV, L.z) * L.z);
      };
      double quad = 0;
      const int nphi = 128;
      for (int p = 0; p < nphi; ++p) {
        double phi = 2 * kPi * (p + 0.5) / nphi;
        quad += integrateMu(
                    [&](double mu) {
                      double s = std::sqrt(1 - mu * mu);
                      glm::vec3 H(s * std::cos(phi), s * std::sin(phi), mu);
                      return integrand(H) * 4.0 * glm::dot(V, H);
                    },
                    800) *
                (2 * kPi / nphi);
      }
      const uint32_t n = 1u << 16;
      double is = 0, vndf = 0;
      for (uint32_t i = 0; i < n; ++i) {
        glm::vec2 u = g::hammersley(i, n);
        glm::vec3 H = g::importanceSampleGGX(u, alpha, glm::vec3(0, 0, 1));
        double pdfL = g::pdfGGX(alpha, H.z) / (4.0 * std::max(glm::dot(V, H), 1e-7f));
        is += integrand(H) / pdfL;
        glm::vec3 Hv = g::sampleGGXVNDF(V, alpha, u);
        double pdfLv = g::pdfGGXVNDF(V, Hv, alpha) / (4.0 * std::max(glm::dot(V, Hv), 1e-7f));
        vndf += pdfLv > 0 ? integrand(Hv) / pdfLv : 0.0;
      }
      is /= n;
      vndf /= n;
      EXPECT_NEAR(is, quad, 1e-2 * quad) << "alpha " << alpha << " NoV " << NoV;
      EXPECT_NEAR(vndf, quad, 1e-2 * quad) << "alpha " << alpha << " NoV " << NoV;
    }
  }
}

// The VNDF pdf integrates to 1 over the hemisphere of H (Heitz 2018 eq. 2: that is the Smith
// G1 normalization), tolerance 2e-3.
TEST(Sampling, VndfPdfIntegratesToOne) {
  for (float alpha : {0.1f, 0.5f, 1.0f})
    for (float NoV : {0.1f, 0.5f, 1.0f}) {
      glm::vec3 V(std::sqrt(1 - NoV * NoV), 0, NoV);
      double I = 0;
      const int nphi = 128;
      for (int p = 0; p < nphi; ++p) {
        double phi = 2 * kPi * (p + 0.5) / nphi;
        I += integrateMu(
                 [&](double mu) {
                   double s = std::sqrt(1 - mu * mu);
                   return double(g::pdfGGXVNDF(
                       V, glm::vec3(s * std::cos(phi), s * std::sin(phi), mu), alpha));
                 },
                 800) *
             (2 * kPi / nphi);
      }
      EXPECT_NEAR(I, 1.0, 2e-3) << "alpha " << alpha << " NoV " << NoV;
    }
}

// Cosine sampling: unit vectors in the upper hemisphere, E[cos] = 2/3, E[1/pdf] = 2 pi... the
// latter has infinite variance at the horizon, so check E[cos^2] = 1/2 instead (tolerance 1e-3).
TEST(Sampling, CosineHemisphere) {
  const uint32_t n = 1u << 14;
  double m1 = 0, m2 = 0, est = 0;
  for (uint32_t i = 0; i < n; ++i) {
    glm::vec3 d = g::sampleCosineHemisphere(g::hammersley(i, n));
    ASSERT_NEAR(glm::length(d), 1.0f, 1e-5f);
    ASSERT_GE(d.z, 0.0f);
    m1 += d.z;
    m2 += d.z * d.z;
    est += d.z / std::max(g::pdfCosineHemisphere(d.z), 1e-12f);  // integral of cos = pi
  }
  EXPECT_NEAR(m1 / n, 2.0 / 3.0, 1e-3);
  EXPECT_NEAR(m2 / n, 0.5, 1e-3);
  EXPECT_NEAR(est / n, kPi, 1e-4);
}

}  // namespace
