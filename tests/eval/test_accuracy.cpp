// The accuracy sweep's machinery (eval/light_accuracy.hpp, the reference's environment
// sampling) and what the sweep found (docs/accuracy.md, written by `halfvec accuracy`): each test
// reruns a small part of the sweep with the same geometry and states the number it came from.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "halfvec/ibl/ibl.hpp"
#include "halfvec/ibl/ibl_math.hpp"
#include "halfvec/reference/emitters.hpp"
#include "halfvec/reference/env_sampling.hpp"
#include "halfvec/eval/light_accuracy.hpp"
#include "halfvec/reference/lobes.hpp"
#include "halfvec/reference/reference.hpp"
#include "halfvec/platform/context.hpp"
#include "halfvec/render/renderer.hpp"
#include "halfvec/scene/primitives.hpp"

using namespace hv;
using namespace hv::eval;

namespace {

constexpr double kPi = 3.14159265358979323846;

Light sphereAt(float elevation_deg, float radius) {
  Light l;
  l.type = LightType::Sphere;
  const float e = float(elevation_deg * kPi / 180.0);
  l.position = {std::cos(e), 0.0f, std::sin(e)};
  l.radius = radius;
  l.range = 1.0e4f;
  return l;
}

Light tubeAt(float elevation_deg, float length, float radius, glm::vec3 axis) {
  Light l = sphereAt(elevation_deg, radius);
  l.type = LightType::Tube;
  l.length = length;
  l.axis = axis;
  return l;
}

// Specular by the reference's own emitter sampling alone (no MIS), mean and standard error.
std::pair<double, double> emitterOnlySpecular(const Light& l, const glm::vec3& V, float roughness,
                                              int n) {
  RenderSettings st;
  st.falloff_plus_one = false;
  const BrdfConfig c = BrdfConfig::fromSettings(st);
  const glm::vec3 N(0, 0, 1), P(0.0f);
  glsl::Surface s = glsl::makeSurface(N, glm::vec3(1.0f), 1.0f, roughness, 1.0f);
  reference_detail::Rng rng(11, 3);
  double sum = 0.0, sum2 = 0.0;
  for (int i = 0; i < n; ++i) {
    const auto ls = reference_detail::sampleLight(l, st, P, {rng.uniform(), rng.uniform()});
    double x = 0.0;
    const float NoL = glsl::saturate(ls.L.z);
    if (ls.pdf > 0.0f && NoL > 0.0f) {
      x = reference_detail::brdfLobes(c, s, V, ls.L, true).specular.x * ls.radiance.x * NoL /
          ls.pdf;
    }
    sum += x;
    sum2 += x * x;
  }
  const double m = sum / n;
  return {m, std::sqrt(std::max(sum2 / n - m * m, 0.0) / n)};
}

glm::vec3 viewAt(float elevation_deg) {
  const float e = float(elevation_deg * kPi / 180.0);
  return {-std::cos(e), 0.0f, std::sin(e)};  // the mirror direction of a light at azimuth 0
}

}  // namespace

// ---- The integrator the sweep uses ----

// The MIS estimate (emitter + GGX-VNDF) agrees with the reference's emitter sampling alone, for a
// sphere and a capsule, within 4 combined standard errors.
TEST(LightAccuracy, MisIntegralAgreesWithEmitterSampling) {
  struct Case {
    Light light;
    float roughness, view_el;
  };
  const Case cases[] = {{sphereAt(30.0f, 0.25f), 0.5f, 30.0f},
                        {sphereAt(45.0f, 0.1f), 0.3f, 45.0f},
                        {tubeAt(45.0f, 1.0f, 0.05f, {0, 1, 0}), 0.5f, 45.0f},
                        {tubeAt(45.0f, 1.0f, 0.1f, {1, 0, 0}), 0.4f, 40.0f}};
  for (const Case& c : cases) {
    const glm::vec3 V = viewAt(c.view_el);
    const LightIntegral mis =
        integrateLight(c.light, glm::vec3(0.0f), {0, 0, 1}, V, glm::vec3(1.0f), glm::vec3(1.0f),
                       c.roughness, 20000, 5);
    const auto [m, se] = emitterOnlySpecular(c.light, V, c.roughness, 400000);
    EXPECT_GT(m, 0.0);
    EXPECT_NEAR(mis.specular.x, m, 4.0 * std::hypot(mis.specular_se.x, se))
        << "type " << int(c.light.type) << " roughness " << c.roughness;
  }
}

// lightPdf is the density of sampleLight: over all directions it integrates to the probability
// that sampleLight returns a (front-facing) hit: 1 for the sphere, the front-facing fraction of
// the capsule's area samples for the tube. Uniform-direction Monte Carlo, 2e6 samples (about 1%).
TEST(LightAccuracy, LightPdfIsTheSamplersDensity) {
  RenderSettings st;
  const glm::vec3 P(0.0f);
  for (const Light& l : {sphereAt(40.0f, 0.3f), tubeAt(30.0f, 1.5f, 0.2f, {0, 1, 0}),
                         tubeAt(60.0f, 0.8f, 0.1f, glm::normalize(glm::vec3(1, 0.5f, 0.3f)))}) {
    reference_detail::Rng rng(7, 1);
    const int n = 2000000;
    double integral = 0.0, hits = 0.0;
    int sampled = 0, mismatched = 0;
    for (int i = 0; i < n; ++i) {
      const float z = 1.0f - 2.0f * rng.uniform(), phi = float(2.0 * kPi) * rng.uniform();
      const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
      integral += reference_detail::lightPdf(l, P, {r * std::cos(phi), r * std::sin(phi), z}) *
                  4.0 * kPi / n;
      const auto ls = reference_detail::sampleLight(l, st, P, {rng.uniform(), rng.uniform()});
      if (ls.pdf > 0.0f) {
        hits += 1.0 / n;
        // The sampled direction has the density lightPdf reports for it (1%), away from grazing
        // points of the capsule, where pdf ~ 1 / cos_e magnifies the float rounding of the
        // sampled direction (pdf < 20 here: cos_e > about 0.02).
        if (ls.pdf < 20.0f) {
          const float p = reference_detail::lightPdf(l, P, ls.L);
          ++sampled;
          if (std::abs(p - ls.pdf) > 1e-2f * ls.pdf) ++mismatched;
        }
      }
    }
    EXPECT_NEAR(integral, hits, 0.015 * hits) << "type " << int(l.type);
    EXPECT_GT(sampled, n / 20);
    EXPECT_LE(mismatched, sampled / 1000) << "type " << int(l.type);
  }
}

// The environment's luminance sampling: its pdf integrates to 1 (midpoint quadrature), sample()
// reports pdf(dir), and E[f / pdf] = the integral of f for f = luminance of a synthetic HDR with a
// small bright spot (so a sampler inconsistent with its pdf would be biased).
TEST(LightAccuracy, EnvironmentSamplingIsConsistent) {
  EnvSource env;
  env.kind = EnvironmentKind::HdrFile;
  env.equirect = makeImageRGBf(64, 32, glm::vec3(0.2f, 0.3f, 0.4f));
  env.equirect.px[10 * 64 + 40] = glm::vec3(500.0f, 400.0f, 300.0f);
  env.rotation_deg = 30.0f;
  reference_detail::EnvDistribution dist(env, 256, 128);
  auto lum = [&](const glm::vec3& d) {
    const glm::vec3 c = env.radiance(d);
    return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z;
  };
  double pdf_integral = 0.0, f_integral = 0.0;
  const int W = 2048, H = 1024;
  for (int y = 0; y < H; ++y) {
    for (int x = 0; x < W; ++x) {
      const glm::vec2 uv((x + 0.5f) / W, (y + 0.5f) / H);
      const glm::vec3 d = equirectDirection(uv);
      const double dw = 2.0 * kPi * kPi * std::sin(kPi * uv.y) / (double(W) * H);
      pdf_integral += dist.pdf(d) * dw;
      f_integral += lum(d) * dw;
    }
  }
  EXPECT_NEAR(pdf_integral, 1.0, 2e-3);
  reference_detail::Rng rng(3, 9);
  const int n = 200000;
  double est = 0.0;
  for (int i = 0; i < n; ++i) {
    float pdf = 0.0f;
    const glm::vec3 d = dist.sample({rng.uniform(), rng.uniform()}, pdf);
    ASSERT_NEAR(glm::length(d), 1.0f, 1e-4f);
    ASSERT_NEAR(pdf, dist.pdf(d), 1e-6f * pdf);
    est += lum(d) / pdf / n;
  }
  EXPECT_NEAR(est, f_integral, 0.01 * f_integral);
}

// The sky's irradiance on an upward surface by luminance sampling alone (the strategy the
// reference adds for the sun) equals a quadrature: the dome on a 500 x 2000 grid outside the
// sun's cone plus the sun's uniform disc in closed form (L_sun * solid angle * cos). Before the
// texel weights were dilated, slivers of the sun missed by every sub-sample gave this estimate a
// heavy tail (13.0 and 17.7 in two runs against 5.2). Within 4 standard errors (+0.2% for the
// quadrature).
TEST(LightAccuracy, SkyIrradianceByLuminanceSampling) {
  Environment e;
  e.kind = EnvironmentKind::Sky;
  const SkyParams sky;
  const EnvSource src = makeEnvSource(e, sky);
  const glm::vec3 sun = skySunDirection(sky);
  const double cos_r = std::cos(sky.sun_angular_radius_deg * kPi / 180.0);
  double dome = 0.0;
  const int nt = 500, np = 2000;
  for (int i = 0; i < nt; ++i) {
    const double th = (i + 0.5) / nt * kPi / 2.0;
    for (int j = 0; j < np; ++j) {
      const double ph = (j + 0.5) / np * 2.0 * kPi;
      const glm::vec3 d(float(std::sin(th) * std::cos(ph)), float(std::cos(th)),
                        float(std::sin(th) * std::sin(ph)));
      if (glm::dot(d, sun) >= cos_r) continue;
      dome += src.radiance(d).y * std::cos(th) * std::sin(th) * (kPi / 2.0 / nt) * (2.0 * kPi / np);
    }
  }
  const double sun_e = src.radiance(sun).y * 2.0 * kPi * (1.0 - cos_r) * sun.y;
  const double exact = dome + sun_e;
  reference_detail::EnvDistribution dist(src);
  reference_detail::Rng rng(5, 6);
  const int n = 200000;
  double est = 0.0, est2 = 0.0;
  for (int i = 0; i < n; ++i) {
    float pdf = 0.0f;
    const glm::vec3 d = dist.sample({rng.uniform(), rng.uniform()}, pdf);
    const double x = d.y > 0.0f ? src.radiance(d).y * d.y / pdf : 0.0;
    est += x / n;
    est2 += x * x / n;
  }
  const double se = std::sqrt((est2 - est * est) / n);
  EXPECT_GT(sun_e, dome);  // the sun dominates: the case that needs the strategy
  EXPECT_LT(se, 0.01 * exact);
  EXPECT_NEAR(est, exact, 4.0 * se + 2e-3 * exact) << "standard error " << se;
}

// ---- What the sweep found (docs/accuracy.md, `halfvec accuracy`, 4096 + 4096 samples per view).
// The tests rerun a subset of the same grid with 1024 + 1024 samples; bounds are the values this
// subset measured when the document was generated, with a margin for noise. ----

namespace {

SphereSweepGrid sphereSubgrid() {
  SphereSweepGrid g;
  g.roughness = {0.05f, 0.2f, 0.5f, 1.0f};
  g.radius = {0.01f, 0.25f, 0.5f};
  g.elevation_deg = {90.0f, 45.0f, 15.0f, 5.0f};
  g.samples = 1024;
  return g;
}

bool aboveHorizon(const SphereSweepRow& r) {
  return r.above();
}

const std::vector<SphereSweepRow>& sphereRows() {
  static const std::vector<SphereSweepRow> rows = sweepSphere(sphereSubgrid());
  return rows;
}

std::string where(const SphereSweepRow& r) {
  return "roughness " + std::to_string(r.roughness) + " r/d " + std::to_string(r.radius) +
         " elevation " + std::to_string(r.elevation_deg);
}

}  // namespace

// HorizonCorrect sphere diffuse is exact for Lambert (docs/lights.md), so the sweep sees only the
// reference's noise; KarisPoint is exact while the sphere is above the horizon and too dark when
// it straddles it (docs/accuracy.md: -46.6% at r/d 0.5, elevation 5; -100% at elevation 0).
TEST(AccuracyFindings, SphereDiffuse) {
  for (const SphereSweepRow& r : sphereRows()) {
    ASSERT_TRUE(r.diffuse[kSphereDiffuseHorizon].valid) << where(r);
    // Equal within noise: the bias (sum over the views) within 4 standard errors of that sum.
    EXPECT_LE(std::abs(r.diffuse[kSphereDiffuseHorizon].bias),
              4.0 * r.diffuse[kSphereDiffuseHorizon].noise + 1e-4)
        << where(r);
    if (aboveHorizon(r)) {
      EXPECT_LE(std::abs(r.diffuse[kSphereDiffuseKaris].bias),
                4.0 * r.diffuse[kSphereDiffuseKaris].noise + 1e-4)
          << where(r);
    }
    if (r.radius == 0.5f && r.elevation_deg == 5.0f) {
      EXPECT_LT(r.diffuse[kSphereDiffuseKaris].bias, -0.35) << where(r);
    }
  }
}

// Normalization: with the sphere above the horizon and r/d >= 0.25 it reduces the specular error
// everywhere (docs/accuracy.md: in 236 of 238 configurations); at r/d = 0.01 it is a wash (the
// factor is close to 1 except for very smooth surfaces; the two exceptions in the document are
// r/d 0.01, elevation 15, 1% apart).
TEST(AccuracyFindings, SphereNormalizationReducesSpecularError) {
  for (const SphereSweepRow& r : sphereRows()) {
    if (!aboveHorizon(r) || !r.specular[kSphereRpPlain].valid) continue;
    if (r.roughness >= 1.0f) {
      // alpha' = saturate(alpha + r/(3d)) = 1 = alpha: the normalization is exactly 1.
      EXPECT_EQ(r.specular[kSphereRp].rel_error, r.specular[kSphereRpPlain].rel_error) << where(r);
    } else if (r.radius >= 0.25f) {
      EXPECT_LT(r.specular[kSphereRp].rel_error, r.specular[kSphereRpPlain].rel_error) << where(r);
    } else {
      EXPECT_LE(r.specular[kSphereRp].rel_error, r.specular[kSphereRpPlain].rel_error + 0.02)
          << where(r);
    }
  }
}

// Bevy #13327: the normalized sphere specular is too bright where the lobe is narrower than the
// sphere, about (3/2)^2 = 2.25 times at the highlight's peak at normal incidence (document:
// roughness 0.05, r/d 0.5, elevation 90: peak 2.18) and much more toward grazing angles
// (elevation 5: 24.94); rough surfaces are right (roughness 1, r/d <= 0.25: |bias| <= 1.5%).
TEST(AccuracyFindings, SphereSpecularTooBrightForSmoothSurfaces) {
  for (const SphereSweepRow& r : sphereRows()) {
    if (r.roughness == 0.05f && r.radius == 0.5f && r.elevation_deg == 90.0f) {
      EXPECT_GT(r.specular[kSphereRp].peak, 1.8) << where(r);
      EXPECT_LT(r.specular[kSphereRp].peak, 2.6) << where(r);
    }
    if (r.roughness == 0.05f && r.radius == 0.5f && r.elevation_deg == 5.0f) {
      EXPECT_GT(r.specular[kSphereRp].peak, 15.0) << where(r);
    }
    if (r.roughness == 1.0f && r.radius <= 0.25f && r.elevation_deg >= 45.0f) {
      EXPECT_LT(std::abs(r.specular[kSphereRp].bias), 0.03) << where(r);
    }
  }
}

// Regression net: the largest error of each sphere specular variant on this subset (sphere above
// the horizon) stays under the bound measured now. Measured on this subset when
// docs/accuracy.md was generated: 9.72 (972%, default, at roughness 0.05, elevation 5) and 18713
// without normalization; bound = measured x 1.15.
TEST(AccuracyFindings, SphereErrorBounds) {
  double spec_default = 0.0, spec_plain = 0.0;
  for (const SphereSweepRow& r : sphereRows()) {
    if (!aboveHorizon(r)) continue;
    spec_default = std::max(spec_default, r.specular[kSphereRp].rel_error);
    spec_plain = std::max(spec_plain, r.specular[kSphereRpPlain].rel_error);
  }
  EXPECT_LT(spec_default, 9.72 * 1.15);
  EXPECT_GT(spec_default, 9.72 / 1.15);  // the finding itself: not silently fixed either
  EXPECT_LT(spec_plain, 18713.0 * 1.15);
}

// Spheres straddling the horizon, `ltc`: the part below the surface is cut off in world space
// (ltc.glsl, ltcSphereIntegralAbove) and the light correction taken over the part above from
// points spread over it (ltc_lights.glsl, ltcSegmentCorrection). The clip in cosine space alone
// kept the sphere's part below the surface where the LTC leaks there: on this subset (1024
// samples) a mean |bias| of 3.4 and a worst of 39 (+3900%); the cut with the correction at the
// part's centroid alone 0.372 and 3.17 (the slivers at grazing views); the bounds are 1.5 times
// what the points measured, 0.039 and 0.185 (docs/lights.md, "Straddling spheres").
TEST(AccuracyFindings, StraddlingSpheresCutAtTheSurface) {
  SphereSweepGrid g;
  g.roughness = {0.2f, 0.35f, 0.5f, 0.75f};
  g.radius = {0.1f, 0.25f};
  g.elevation_deg = {0.0f, -5.0f};
  g.samples = 1024;
  double sum = 0.0, worst = 0.0;
  int n = 0;
  for (const SphereSweepRow& r : sweepSphere(g)) {
    ASSERT_FALSE(r.above()) << where(r);
    ASSERT_TRUE(r.specular[kSphereLtc].valid) << where(r);
    sum += std::abs(r.specular[kSphereLtc].bias);
    worst = std::max(worst, std::abs(r.specular[kSphereLtc].bias));
    ++n;
  }
  std::printf("straddling spheres, ltc: mean |bias| %.3f, worst %.3f over %d\n", sum / n, worst, n);
  EXPECT_LT(sum / n, 0.039 * 1.5);
  EXPECT_LT(worst, 0.185 * 1.5);
}

// Directional lights: the sun's disk (sin sigma = 0.00465) in the sphere sweep (grid.directional).
// docs/accuracy-directional.md (4096 samples): ltc within 3.3% everywhere above the horizon; the
// representative point's grazing overshoot of the sphere (AccuracyFindings.
// SphereSpecularTooBrightForSmoothSurfaces) holds for the sun on smooth surfaces: worst bias
// +499% at roughness 0.05, +115% at 0.1, +0.0% at 0.5. Here 1024 samples (noise about 3%):
// bounds ltc < 6%, the representative point > +200% at 0.05 and < 3% at 0.5.
TEST(AccuracyFindings, SunDiskLtcRightRepresentativePointTooBrightWhenSmooth) {
  SphereSweepGrid g;
  g.directional = true;
  g.roughness = {0.05f, 0.5f};
  g.radius = {std::sin(0.5f * kSunAngularDiameter)};
  g.elevation_deg = {45.0f, 5.0f};
  g.samples = 1024;
  double worst_ltc = 0.0, rp_smooth = 0.0, rp_rough = 0.0;
  for (const SphereSweepRow& r : sweepSphere(g)) {
    ASSERT_TRUE(r.specular[kSphereLtc].valid && r.specular[kSphereRp].valid);
    worst_ltc = std::max(worst_ltc, r.specular[kSphereLtc].rel_error);
    if (r.roughness == 0.05f) rp_smooth = std::max(rp_smooth, r.specular[kSphereRp].bias);
    if (r.roughness == 0.5f) rp_rough = std::max(rp_rough, r.specular[kSphereRp].rel_error);
  }
  std::printf(
      "sun disk: ltc worst %.4f, representative point bias at 0.05 %+.3f, error at 0.5 %.4f\n",
      worst_ltc, rp_smooth, rp_rough);
  EXPECT_LT(worst_ltc, 0.06);
  EXPECT_GT(rp_smooth, 2.0);
  EXPECT_LT(rp_rough, 0.03);
}

namespace {

TubeSweepGrid tubeSubgrid() {
  TubeSweepGrid g;
  g.roughness = {0.05f, 0.35f, 1.0f};
  g.length = {0.25f, 1.0f, 2.0f};
  g.radius = {0.01f, 0.2f};
  g.samples = 1024;
  return g;
}

}  // namespace

// Tube lights: the default (eq. 19 + normalization) is far too dark on smooth surfaces (document:
// -43.9% to -94.9% bias at roughness 0.05); the normalization reduces the error of both eq. 19
// and eq. 18 on smooth surfaces. Bounds: the largest rel. error of each variant on this subset,
// measured when the document was generated: eq. 19 and eq. 18 without normalization 112.95,
// with normalization 0.9487 (the engine is ~95% too dark: the bound is measured + 0.02, rel.
// error cannot exceed 1 when too dark), diffuse (eq. 16) 0.211 (each orientation on its own:
// across the plane of incidence is the worse); bound = measured x 1.15.
TEST(AccuracyFindings, TubeLights) {
  const auto rows = sweepTube(tubeSubgrid());
  const int rp[2][2] = {{kTubeRpPlain, kTubeRp}, {kTubeRpEq18Plain, kTubeRpEq18}};
  double worst[2][2] = {{0, 0}, {0, 0}}, diffuse = 0.0;
  for (const TubeSweepRow& r : rows) {
    for (int ts = 0; ts < 2; ++ts) {
      for (int tn = 0; tn < 2; ++tn) {
        worst[ts][tn] = std::max(worst[ts][tn], r.specular[rp[ts][tn]].rel_error);
      }
    }
    diffuse = std::max(diffuse, r.diffuse[kTubeDiffuseKaris].rel_error);
    if (r.roughness == 0.05f) {
      EXPECT_LT(r.specular[kTubeRp].bias, -0.35) << r.length << " " << r.radius;
      for (int ts = 0; ts < 2; ++ts) {
        EXPECT_LT(r.specular[rp[ts][1]].rel_error, r.specular[rp[ts][0]].rel_error)
            << r.length << " " << r.radius;
      }
    }
  }
  for (int ts = 0; ts < 2; ++ts) {
    EXPECT_LT(worst[ts][0], 112.95 * 1.15) << ts;
    EXPECT_LT(worst[ts][1], 0.9487 + 0.02) << ts;
  }
  EXPECT_LT(diffuse, 0.211 * 1.15);
}

// EnvBRDFApprox against the environment BRDF table (Karis 2013 eq. 8): document (128^2 table,
// 1024 samples): mean absolute error of the f0 = 1 reflectance 0.0614, largest 0.3445 (at
// NoV 0.004, roughness 0.066). Here a 64^2 table with 512 samples (texel centers less grazing,
// so the largest error is at most the document's); bound = measured x 1.15.
TEST(AccuracyFindings, EnvBrdfApproxVsTable) {
  const int size = 64;
  const auto table = integrateEnvBrdf(size, 512, 2);
  double sum = 0.0, worst = 0.0;
  for (int j = 0; j < size; ++j) {
    for (int i = 0; i < size; ++i) {
      const float NoV = (i + 0.5f) / size, rough = (j + 0.5f) / size;
      const glm::vec2 t = table[size_t(j) * size + size_t(i)];
      const glm::vec2 a = glsl::EnvBRDFApproxScaleBias(rough, NoV);
      const double d = std::abs(double(a.x + a.y) - double(t.x + t.y));
      sum += d;
      worst = std::max(worst, d);
    }
  }
  EXPECT_LT(sum / (size * size), 0.0614 * 1.15);
  EXPECT_GT(sum / (size * size), 0.0614 / 1.15);
  EXPECT_LT(worst, 0.3445 * 1.15);
}

// Ambient light, uniform environment of radiance 1 (GPU render with the ambient term mask vs the
// reference): the split sum with the table is exact up to the table's resolution (document:
// |bias| <= 1.1% at every roughness), EnvBRDFApprox is off by the fit's error (document: -8.7%,
// -9.5%, +19.4% at roughness 0.25, 0.5, 1), SH9 irradiance is exact for a constant environment
// (document: |bias| <= 0.1%). Bounds: the document's values +- 3% (the reference here takes 64
// samples per pixel).
TEST(AccuracyFindings, AmbientUniformEnvironment) {
  auto ctx = createHeadlessContext();
  const float rough[3] = {0.25f, 0.5f, 1.0f};
  Scene s;
  s.camera.position = {0.0f, 0.0f, 6.0f};
  s.camera.fov_y_deg = 30.0f;
  const Mesh sphere = makeSphere(0.45f, 32, 16);
  for (int row = 0; row < 2; ++row) {
    for (int i = 0; i < 3; ++i) {
      Material m;
      m.base_color = glm::vec3(1.0f);
      m.metallic = row == 0 ? 1.0f : 0.0f;
      m.roughness = rough[i];
      addMeshObject(s, sphere, m, {float(i - 1), row == 0 ? 0.5f : -0.5f, 0.0f});
    }
  }
  s.environment.kind = EnvironmentKind::Uniform;
  s.environment.color = glm::vec3(1.0f);
  s.environment.cube_size = 32;
  s.environment.prefilter_samples = 32;
  const int w = 128, h = 72;
  render::Renderer r;
  r.setScene(s);
  auto renderTerm = [&](uint8_t mask, EnvBrdf env_brdf) {
    s.settings.ambient_terms = mask;
    s.settings.env_brdf = env_brdf;
    r.render(w, h);
    return r.readHdr();
  };
  const ImageRGBf spec = renderTerm(2, EnvBrdf::Table);
  const ImageRGBf spec_approx = renderTerm(2, EnvBrdf::Analytic);
  const ImageRGBf diff = renderTerm(1, EnvBrdf::Table);
  const auto g = r.readGBuffer();
  ReferenceOptions o;
  o.samples = 64;
  const ReferenceResult ref = renderReference(s, g, o);
  const double approx_doc[3] = {-0.087, -0.095, 0.194};
  for (int i = 0; i < 3; ++i) {
    double e_spec = 0, e_approx = 0, e_diff = 0, r_spec = 0, r_diff = 0;
    for (size_t p = 0; p < g.model.size(); ++p) {
      if (g.model[p] != static_cast<uint32_t>(ShadingModel::DefaultLit)) continue;
      if (std::abs(g.roughness[p] - rough[i]) > 0.01f) continue;
      if (g.metallic[p] > 0.5f) {
        e_spec += spec.px[p].x;
        e_approx += spec_approx.px[p].x;
        r_spec += ref[ReferenceAov::AmbientSpecular].px[p].x;
      } else {
        e_diff += diff.px[p].x;
        r_diff += ref[ReferenceAov::AmbientDiffuse].px[p].x;
      }
    }
    ASSERT_GT(r_spec, 0.0);
    ASSERT_GT(r_diff, 0.0);
    EXPECT_NEAR(e_spec / r_spec - 1.0, 0.0, 0.011 + 0.03) << "roughness " << rough[i];
    EXPECT_NEAR(e_approx / r_spec - 1.0, approx_doc[i], 0.03) << "roughness " << rough[i];
    EXPECT_NEAR(e_diff / r_diff - 1.0, 0.0, 0.001 + 0.03) << "roughness " << rough[i];
  }
}
