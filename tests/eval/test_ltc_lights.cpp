// The LTC light modes against the reference on small cases (the engine's formula compiled as C++,
// eval/light_accuracy.hpp, against the Monte Carlo integral over the emitter).
#include <gtest/gtest.h>

#include <cmath>

#include "halfvec/eval/light_accuracy.hpp"
#include "halfvec/shading/shading.hpp"

using namespace hv;
using namespace hv::eval;

namespace {

constexpr double kPi = 3.14159265358979323846;

glm::vec3 dirAt(float elevation_deg, float azimuth_deg = 0.0f) {
  const float e = float(elevation_deg * kPi / 180.0), a = float(azimuth_deg * kPi / 180.0);
  return {std::cos(e) * std::cos(a), std::cos(e) * std::sin(a), std::sin(e)};
}

Light light(LightType type, glm::vec3 pos, float radius, float length = 0.0f,
            glm::vec3 axis = {0, 1, 0}) {
  Light l;
  l.type = type;
  l.position = pos;
  l.radius = radius;
  l.length = length;
  l.axis = axis;
  l.range = 1e4f;
  return l;
}

// The engine's term against the reference over the sweep's views around `dir`, as the sweep
// measures it (bias over the views, peak at the mirror view), with the fitted lobe's V.
TermError ltcError(const Light& l, LightTerm term, float roughness, glm::vec3 dir,
                   float footprint) {
  EngineLightOptions o;
  o.sphere_specular = SphereSpecular::Ltc;
  o.tube_specular = TubeSpecular::Ltc;
  o.tube_diffuse = TubeDiffuse::Ltc;
  o.sphere_diffuse = SphereDiffuse::HorizonCorrect;
  o.v = VisibilityTerm::SmithGGXCorrelated;
  const glm::vec3 N(0, 0, 1), P(0.0f);
  std::vector<double> e, r, se;
  const auto views = sweepViews(dir, footprint);
  for (size_t i = 0; i < views.size(); ++i) {
    const bool diffuse = term == LightTerm::Diffuse;
    e.push_back(engineLightTerm(o, term, l, P, N, views[i], glm::vec3(1.0f), diffuse ? 0.0f : 1.0f,
                                roughness)
                    .x);
    const LightIntegral x =
        integrateLight(l, P, N, views[i], glm::vec3(1.0f), glm::vec3(1.0f), roughness, 4096, 17 + i,
                       DistributionTerm::GGX, VisibilityTerm::SmithGGXCorrelated);
    r.push_back(diffuse ? x.diffuse.x : x.specular.x);
    se.push_back(diffuse ? x.diffuse_se.x : x.specular_se.x);
  }
  return termError(e, r, se);
}

}  // namespace

// Small scenes, engine `ltc` vs the reference. Bounds (|bias| over the views, |peak - 1| at the
// mirror view): the values measured when docs/accuracy.md was generated for the same
// configurations (the accuracy sweep's grid), plus the reference's noise (4 standard errors of
// the sum) and a margin: spheres above the horizon 5% (the accuracy target, docs/accuracy.md),
// including one near the horizon at a grazing view and one overhead whose highlight's outer views
// see the lobe's flank; a sphere straddling the horizon (elevation 0) and a shading point inside a
// sphere 10%; capsules across and along the plane of incidence 10% (specular) and 2% (diffuse).
TEST(LtcLights, MatchReferenceOnSmallScenes) {
  struct Case {
    const char* name;
    Light light;
    float roughness, elevation, footprint, tol_spec, tol_diff;
  };
  const Case cases[] = {
      {"glossy sphere", light(LightType::Sphere, dirAt(45), 0.2f), 0.1f, 45, 0.22f, 0.05f, 0.02f},
      {"rough sphere", light(LightType::Sphere, dirAt(45), 0.2f), 0.7f, 45, 1.2f, 0.05f, 0.02f},
      {"straddling sphere", light(LightType::Sphere, dirAt(0), 0.3f), 0.3f, 0, 0.5f, 0.10f, 0.02f},
      // Near the horizon at a grazing view (N.V 0.087), where the lobe falls off across the light:
      // bias +23% and peak 1.36 with the LTC corrected at one point, +5.3% and 1.015 at two
      // points around the representative point, -0.7% and 0.984 with lights.glsl's
      // ltcCorrection.
      {"sphere near the horizon", light(LightType::Sphere, dirAt(5), 0.05f), 0.5f, 5, 0.18f, 0.05f,
       0.02f},
      // Overhead, at roughness 0.5: the views around the highlight at N.V 0.36-0.5 see the light in
      // the lobe's flank, where the LTC alone is 1.36-1.56 times the lobe (bias +11.6%). The
      // correction at two points around the representative point (weight 1 / (1 + 4 t)) left
      // +9.2%; ltcCorrection, its ratio trusted where two points integrate the LTC itself: +0.4%.
      {"rough sphere overhead", light(LightType::Sphere, dirAt(90), 0.25f), 0.5f, 90, 0.75f, 0.05f,
       0.02f},
      // Glossy, with the highlight's outer views at N.V 0.022, where the lobe is a thin sheet
      // along the horizon: those views read 0.60 of the reference (bias -11.4%) until the table's
      // last row was fitted to the lobe's integrals over caps (ltc_fit.hpp); -3.0% since.
      {"glossy sphere at grazing views", light(LightType::Sphere, dirAt(15), 0.25f), 0.2f, 15,
       0.333f, 0.05f, 0.02f},
      // At elevation 30, roughness 0.5: the outer views at N.V 0.07 see the light 34 degrees above
      // their mirror direction, where the LTC alone gives half the lobe's integral. The light
      // correction's ratio is right there, but its test against the LTC's integral held it back
      // while it stopped at |u| = 0.2 (bias -9.3%); at |u| = 1 (lights.glsl) -3.5%, and -0.6%
      // since the test against the axis only halves the weight where the points' density is
      // above the center's.
      {"rough sphere at 30 degrees", light(LightType::Sphere, dirAt(30), 0.25f), 0.5f, 30, 0.75f,
       0.05f, 0.02f},
      {"inside a sphere", light(LightType::Sphere, 0.5f * dirAt(60), 1.0f), 0.4f, 60, 0.8f, 0.10f,
       0.02f},
      {"capsule across", light(LightType::Tube, dirAt(45), 0.1f, 1.0f, {0, 1, 0}), 0.2f, 45, 0.9f,
       0.10f, 0.02f},
      {"capsule along", light(LightType::Tube, dirAt(45), 0.1f, 1.0f, {1, 0, 0}), 0.5f, 45, 1.0f,
       0.10f, 0.02f},
  };
  for (const Case& c : cases) {
    const glm::vec3 dir = glm::normalize(c.light.position);
    const TermError s = ltcError(c.light, LightTerm::Specular, c.roughness, dir, c.footprint);
    const TermError d = ltcError(c.light, LightTerm::Diffuse, c.roughness, dir, c.footprint);
    ASSERT_TRUE(s.valid && d.valid) << c.name;
    EXPECT_LT(std::abs(s.bias), c.tol_spec + 4.0 * s.noise) << c.name;
    EXPECT_LT(std::abs(s.peak - 1.0), c.tol_spec + 0.05) << c.name;
    if (c.light.type == LightType::Tube) {
      EXPECT_LT(std::abs(d.bias), c.tol_diff + 4.0 * d.noise) << c.name;
    }
    std::printf("%s: specular bias %+.2f%% peak %.3f (noise %.2f%%), diffuse bias %+.2f%%\n",
                c.name, 100.0 * s.bias, s.peak, 100.0 * s.noise, 100.0 * d.bias);
  }
}

// A sphere of radius 0 (shaded as r = 1e-4 d) is the point light at every view, not only near the
// highlight: over a 121 x 121 grid of views around the mirror direction (up to 70 degrees away),
// the `ltc` specular within 5% of the point light's value + 1e-5 of its peak, at roughness 0 to
// 0.1. Before the small-cone estimate of ltc.glsl's ltcSphereFormFactor, views in the lobe's far
// tail at roughness <= 0.1 were 6e4 where the point light is 1e-4 (half its peak, a firefly);
// what remains there is the LTC's own tail shape (up to 2.8x the lobe at 3e-6 of the peak).
TEST(LtcLights, TinySphereIsThePointLightAtEveryView) {
  EngineLightOptions lt;
  lt.sphere_specular = SphereSpecular::Ltc;
  lt.tube_specular = TubeSpecular::Ltc;
  lt.tube_diffuse = TubeDiffuse::Ltc;
  lt.sphere_diffuse = SphereDiffuse::HorizonCorrect;
  lt.v = VisibilityTerm::SmithGGXCorrelated;
  EngineLightOptions point;  // representative point, radius 0: the point light, with the same V
  point.v = VisibilityTerm::SmithGGXCorrelated;
  const glm::vec3 N(0, 0, 1), P(0.0f);
  for (float rough : {0.0f, 0.05f, 0.1f}) {
    Light l = light(LightType::Sphere, {0.3f, 0.2f, 1.0f}, 0.0f);
    const glm::vec3 c = glm::normalize(l.position), mirror(-c.x, -c.y, c.z);
    std::vector<std::pair<double, double>> values;
    double peak = 0.0;
    for (int i = -60; i <= 60; ++i) {
      for (int j = -60; j <= 60; ++j) {
        const glm::vec3 V =
            glm::normalize(mirror + glm::vec3(float(i) * 0.02f, float(j) * 0.02f, 0));
        if (V.z <= 0.02f) continue;
        const double e =
            engineLightTerm(lt, LightTerm::Specular, l, P, N, V, glm::vec3(1.0f), 1.0f, rough).x;
        const double p =
            engineLightTerm(point, LightTerm::Specular, l, P, N, V, glm::vec3(1.0f), 1.0f, rough).x;
        values.emplace_back(e, p);
        peak = std::max(peak, p);
      }
    }
    int bad = 0;
    for (auto [e, p] : values) bad += std::abs(e - p) > 0.05 * p + 1e-5 * peak;
    EXPECT_EQ(bad, 0) << "roughness " << rough << ", " << values.size() << " views";
  }
}

// A shading point inside a sphere light (many_lights has three, centres inside pillars) sees the
// whole hemisphere emit L_e = I / (pi r^2): the reference's diffuse is pi L_e times the Lambert
// lobe, wherever the centre is, above the surface or below it. Both sphere diffuse methods give it
// (before, the horizon-correct one clipped the sphere as if the point were on its surface and the
// Karis point one took N.L of the centre: 0 for a centre below the surface). Tolerance: 4 standard
// errors + 0.5% of the reference.
TEST(SphereDiffuse, InsideTheSphereTheWholeHemisphereEmits) {
  const glm::vec3 N(0, 0, 1), P(0.0f);
  for (SphereDiffuse method : {SphereDiffuse::KarisPoint, SphereDiffuse::HorizonCorrect}) {
    EngineLightOptions o;
    o.sphere_diffuse = method;
    for (glm::vec3 center : {glm::vec3(0.0f, 0.0f, 0.2f), glm::vec3(0.15f, -0.1f, -0.3f),
                             glm::vec3(0.3f, 0.2f, 0.05f), glm::vec3(0.0f, 0.0f, -0.45f)}) {
      const Light l = light(LightType::Sphere, center, 0.5f);
      for (float view_el : {10.0f, 60.0f}) {
        const glm::vec3 V = dirAt(view_el, 30.0f);
        const float got =
            engineLightTerm(o, LightTerm::Diffuse, l, P, N, V, glm::vec3(1.0f), 0.0f, 0.5f).x;
        const LightIntegral x =
            integrateLight(l, P, N, V, glm::vec3(1.0f), glm::vec3(0.0f), 0.5f, 4096, 5,
                           DistributionTerm::GGX, VisibilityTerm::SchlickGGX);
        EXPECT_NEAR(got, x.diffuse.x, 4.0 * x.diffuse_se.x + 5e-3 * x.diffuse.x)
            << "method " << int(method) << " centre " << center.x << "," << center.y << ","
            << center.z << " view elevation " << view_el;
      }
    }
  }
}
