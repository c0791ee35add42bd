// Lights of shaders/common/lights.glsl (default defines), run as C++.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "halfvec/shading/light_gpu.hpp"
#include "karis_double.hpp"

namespace hv::glsl {
namespace {
#include "light_sweep.inc"
}  // namespace
}  // namespace hv::glsl

namespace {

namespace g = hv::glsl;
constexpr double kPi = 3.14159265358979323846;

glm::vec3 shade(const hv::Light& l, const g::Surface& s, glm::vec3 P, glm::vec3 V) {
  return g::evaluateLight(hv::toGlsl(hv::packLight(l)), s, P, V);
}

TEST(Lights, PackLayoutAndValues) {
  hv::Light l;
  l.type = hv::LightType::Tube;
  l.position = {1, 2, 3};
  l.color = {1.0f, 0.5f, 0.25f};
  l.intensity = 8.0f;
  l.radius = 0.1f;
  l.length = 2.0f;
  l.axis = {0, 0, 3};  // normalized by packLight
  l.range = 5.0f;
  hv::GpuLight gl = hv::packLight(l);
  EXPECT_EQ(gl.position_radius, glm::vec4(1, 2, 3, 0.1f));
  EXPECT_EQ(gl.color_inv_range, glm::vec4(8.0f, 4.0f, 2.0f, 0.2f));
  EXPECT_EQ(gl.axis_length, glm::vec4(0, 0, 1, 2.0f));
  EXPECT_FLOAT_EQ(gl.range, 5.0f);
  EXPECT_EQ(gl.type, unsigned(HV_LIGHT_TUBE));
  EXPECT_FLOAT_EQ(gl.cull_radius, 6.0f);  // range + len/2
  EXPECT_EQ(gl.shadow_cube, 0u);          // none until the shadow pass writes one
  EXPECT_FLOAT_EQ(g::lightCullRadius(hv::toGlsl(gl)), 6.0f);
  // Points ignore radius/length; degenerate axis and range are sanitized.
  l.type = hv::LightType::Point;
  l.axis = {0, 0, 0};
  l.range = 0.0f;
  gl = hv::packLight(l);
  EXPECT_EQ(gl.position_radius.w, 0.0f);
  EXPECT_EQ(gl.axis_length, glm::vec4(1, 0, 0, 0));
  EXPECT_TRUE(std::isfinite(gl.color_inv_range.w));
  EXPECT_EQ(gl.type, unsigned(HV_LIGHT_POINT));
  std::vector<hv::Light> lights(2);
  lights[1].type = hv::LightType::Tube;
  auto defs = hv::lightTypeDefines(lights);
  ASSERT_EQ(defs.size(), 5u);
  EXPECT_EQ(defs[0], std::make_pair(std::string("HV_HAS_POINT_LIGHTS"), std::string("1")));
  EXPECT_EQ(defs[1], std::make_pair(std::string("HV_HAS_SPHERE_LIGHTS"), std::string("0")));
  EXPECT_EQ(defs[2], std::make_pair(std::string("HV_HAS_TUBE_LIGHTS"), std::string("1")));
  EXPECT_EQ(defs[3], std::make_pair(std::string("HV_HAS_SPOT_LIGHTS"), std::string("0")));
  EXPECT_EQ(defs[4], std::make_pair(std::string("HV_HAS_DIRECTIONAL_LIGHTS"), std::string("0")));
  // A directional light: the unit direction toward it, the sine of its angular radius, E times
  // the color, no range, and its own type code (the culling bins types 0-2 only).
  hv::Light d;
  d.type = hv::LightType::Directional;
  d.direction = {0.0f, 0.0f, -2.0f};
  d.angular_diameter = 0.5f;
  d.intensity = 4.0f;
  d.color = {1.0f, 0.5f, 0.25f};
  gl = hv::packLight(d);
  EXPECT_EQ(gl.position_radius, glm::vec4(0, 0, 1, std::sin(0.25f)));
  EXPECT_EQ(gl.color_inv_range, glm::vec4(4.0f, 2.0f, 1.0f, 0.0f));
  EXPECT_EQ(gl.type, unsigned(HV_LIGHT_DIRECTIONAL));
  EXPECT_EQ(gl.cull_radius, 0.0f);
  lights[0] = d;
  defs = hv::lightTypeDefines(lights);
  EXPECT_EQ(defs[0].second, "0");
  EXPECT_EQ(defs[4].second, "1");
}

// Karis 2013 eq. 20 and the tube's energy normalization, by hand. A metallic white surface at the
// origin (N = +z) looked at straight down: R = N passes through the center of a tube (axis x,
// len 1, r 0.1) at height 2, so the segment point (eq. 19) is the center, the sphere
// representative point (eq. 11) is the center too, and H = N: NoH = NoL = NoV = VoH = 1, F = 1,
// Vis = 1/4, D = 1/(pi alpha^2). The specular is then I W/(d^2+1) D Vis times the normalization,
// which must be the product of
//   line:   alpha / alpha_l, alpha_l = saturate(alpha + 0.5 saturate(len / d))  (eq. 20, UE4 form)
//   sphere: (alpha / alpha_s)^2, alpha_s = saturate(alpha + r / (3 d))           (eqs. 10, 14)
// with d = 2 (center and segment point coincide). Tolerance 2e-4 relative: D_GGX's
// (NoH^2 (a^2 - 1) + 1) at NoH = 1 rounds to ~6e-8 / a^2 relative (7e-5 at roughness 0.2). The
// sphere light of the same radius gives the sphere factor alone, so tube / sphere is the line
// factor (the D rounding cancels: 1e-5).
TEST(Lights, TubeNormalizationIsLineTimesSphere) {
  for (float roughness : {0.2f, 0.5f, 0.9f}) {
    const g::Surface s = g::makeSurface({0, 0, 1}, glm::vec3(1.0f), 1.0f, roughness, 1.0f);
    const float a = roughness * roughness;
    hv::Light l;
    l.type = hv::LightType::Tube;
    l.position = {0, 0, 2};
    l.axis = {1, 0, 0};
    l.length = 1.0f;
    l.radius = 0.1f;
    l.intensity = 3.0f;
    l.range = 10.0f;
    const glm::vec3 V(0, 0, 1), P(0.0f);
    const float d = 2.0f, len = 1.0f, r = 0.1f;
    const float window = std::pow(1.0f - std::pow(d / l.range, 4.0f), 2.0f);
    const float base = 3.0f * window / (d * d + 1.0f) / (float(kPi) * a * a) * 0.25f;
    const float line = a / std::min(a + 0.5f * std::min(len / d, 1.0f), 1.0f);
    const float sphere = std::pow(a / std::min(a + r / (3.0f * d), 1.0f), 2.0f);
    const glm::vec3 tube = shade(l, s, P, V);
    EXPECT_NEAR(tube.x, base * line * sphere, 2e-4f * base * line * sphere) << roughness;
    l.type = hv::LightType::Sphere;
    l.length = 0.0f;
    const glm::vec3 sph = shade(l, s, P, V);
    EXPECT_NEAR(sph.x, base * sphere, 2e-4f * base * sphere) << "roughness " << roughness;
    EXPECT_NEAR(tube.x / sph.x, line, 1e-5f) << "roughness " << roughness;
  }
  // The helpers by hand: alpha 0.25, len 1, d 2: 0.25 / 0.5; len / d = 5 saturates: 0.25 / 0.75.
  EXPECT_NEAR(g::lineNormalization(0.25f, 1.0f, 4.0f), 0.5f, 1e-6f);
  EXPECT_NEAR(g::lineNormalization(0.25f, 10.0f, 4.0f), 0.25f / 0.75f, 1e-6f);
  EXPECT_NEAR(g::sphereNormalization(0.25f, 0.75f, 1.0f), 0.25f, 1e-6f);  // (0.25 / 0.5)^2
}

// Karis eq. 9 by hand, exact zeros at and beyond the culling radius for every light type, and a
// point light straight above a surface evaluated by hand from the terms (tolerance 1e-5).
TEST(Lights, FalloffByHand) {
  // d = 2, R = 4: window = (1 - (1/2)^4)^2 = (15/16)^2; / (d^2 + 1) = / 5.
  EXPECT_NEAR(g::distanceFalloff(4.0f, 0.0f, 0.25f), (15.0f / 16.0f) * (15.0f / 16.0f) / 5.0f,
              1e-7f);
  EXPECT_EQ(g::falloffWindow(16.0f, 0.25f), 0.0f);  // d = R
  EXPECT_EQ(g::falloffWindow(17.0f, 0.25f), 0.0f);  // beyond R
  EXPECT_EQ(g::falloffWindow(0.0f, 0.25f), 1.0f);
  // Beyond the culling radius every light type is exactly 0.
  g::Surface s = g::makeSurface({0, 0, 1}, glm::vec3(1.0f), 0.0f, 0.5f, 1.0f);
  for (int type = 0; type < 3; ++type) {
    hv::Light l;
    l.type = hv::LightType(type);
    l.radius = 0.2f;
    l.length = 3.0f;
    l.axis = {1, 0, 0};
    l.range = 2.0f;
    float cull = hv::packLight(l).cull_radius;
    l.position = glm::vec3(0, 0, cull * 1.0001f);
    EXPECT_EQ(shade(l, s, glm::vec3(0.0f), glm::vec3(0, 0, 1)), glm::vec3(0.0f)) << type;
    l.position = glm::normalize(glm::vec3(0.3f, 0.0f, 0.9f)) * (cull * 1.0001f);
    EXPECT_EQ(shade(l, s, glm::vec3(0.0f), glm::vec3(0, 0, 1)), glm::vec3(0.0f)) << type;
  }
  // Point light straight above a white Lambert surface (metallic 0): diffuse radiance =
  // I falloff / pi; specular adds D V F at NoH = 1, checked against the terms themselves.
  hv::Light p;
  p.position = {0, 0, 2};
  p.intensity = 10.0f;
  p.range = 4.0f;
  glm::vec3 c = shade(p, s, glm::vec3(0.0f), glm::vec3(0, 0, 1));
  float falloff = (15.0f / 16.0f) * (15.0f / 16.0f) / 5.0f;
  float spec = g::D_GGX(0.25f, 1.0f) * g::V_SchlickGGX(0.5f * 0.5625f, 1.0f, 1.0f) * 0.04f;
  EXPECT_NEAR(c.x, 10.0f * falloff * (1.0f / float(kPi) + spec), 1e-5f);
}

// The 1 cm minimum distance and the capsule radius bound the point falloff: inside a sphere the
// radiance equals that on its surface (window aside).
TEST(Lights, SphereInteriorClamp) {
  EXPECT_FLOAT_EQ(g::distanceFalloff(0.0f, 0.5f, 0.0f), 1.0f / (0.25f + 1.0f));
  EXPECT_FLOAT_EQ(g::distanceFalloff(0.0f, 0.0f, 0.0f), 1.0f / (1e-4f + 1.0f));
}

// A sphere of radius 1e-4 is the point light, and a tube of length 1e-4 is the sphere (radius
// 0.2 and 0), relative tolerance 2e-3 + absolute 1e-6 (the normalizations differ by
// ~2 (r / 3d) / alpha and ~0.5 len / (d alpha): <= 7e-4 for roughness >= 0.3 at d >= 1).
TEST(Lights, DegenerateShapesMatch) {
  const glm::vec3 views[] = {glm::vec3(0, 0, 1), glm::normalize(glm::vec3(0.5f, 0.1f, 0.8f)),
                             glm::normalize(glm::vec3(-0.9f, 0.3f, 0.2f))};
  const glm::vec3 pos[] = {glm::vec3(0, 0, 1.5f), glm::vec3(1.0f, 0.5f, 1.0f),
                           glm::vec3(-2.0f, 0.3f, 0.6f), glm::vec3(1.5f, -1.0f, 0.1f)};
  int compared = 0;
  for (float roughness : {0.3f, 0.6f, 1.0f})
    for (float metallic : {0.0f, 1.0f}) {
      g::Surface s =
          g::makeSurface({0, 0, 1}, glm::vec3(0.9f, 0.6f, 0.3f), metallic, roughness, 1.0f);
      for (const glm::vec3& V : views)
        for (const glm::vec3& P : pos) {
          hv::Light point;
          point.position = P;
          point.intensity = 20.0f;
          point.range = 8.0f;
          hv::Light sphere = point;
          sphere.type = hv::LightType::Sphere;
          sphere.radius = 1e-4f;
          glm::vec3 a = shade(point, s, glm::vec3(0.0f), V);
          glm::vec3 b = shade(sphere, s, glm::vec3(0.0f), V);
          for (int k = 0; k < 3; ++k) EXPECT_NEAR(b[k], a[k], 2e-3f * a[k] + 1e-6f);
          for (float radius : {0.0f, 0.2f}) {
            sphere.radius = radius;
            hv::Light tube = sphere;
            tube.type = hv::LightType::Tube;
            tube.length = 1e-4f;
            tube.axis = glm::normalize(glm::vec3(1, 2, 0.5f));
            glm::vec3 c = shade(sphere, s, glm::vec3(0.0f), V);
            glm::vec3 d = shade(tube, s, glm::vec3(0.0f), V);
            for (int k = 0; k < 3; ++k)
              EXPECT_NEAR(d[k], c[k], 2e-3f * c[k] + 1e-6f)
                  << "roughness " << roughness << " radius " << radius << " P " << P.x;
            ++compared;
          }
        }
    }
  EXPECT_EQ(compared, 3 * 2 * 3 * 4 * 2);
}

// Lagarde & de Rousiers horizon factor against brute force: the integral of max(cos, 0) over the
// sphere's solid-angle cap, divided by pi sin^2(sigma), by quadrature over the cap (polar grid
// around the cap axis). Tolerance 2e-3 absolute (the factor is <= 1).
TEST(Lights, SphereHorizonFactorMatchesQuadrature) {
  for (float sin_sigma : {0.05f, 0.3f, 0.7f, 0.95f})
    for (float theta_deg : {0.0f, 30.0f, 60.0f, 80.0f, 90.0f, 100.0f, 120.0f, 170.0f}) {
      double theta = theta_deg * kPi / 180.0;
      double cos_sigma = std::sqrt(1.0 - double(sin_sigma) * sin_sigma);
      // Cap axis in the xz plane at angle theta from the normal z.
      glm::dvec3 axis(std::sin(theta), 0.0, std::cos(theta));
      glm::dvec3 t1(std::cos(theta), 0.0, -std::sin(theta)), t2(0.0, 1.0, 0.0);
      const int nu = 400, nphi = 400;
      double sum = 0.0;
      for (int i = 0; i < nu; ++i) {
        double u = cos_sigma + (1.0 - cos_sigma) * (i + 0.5) / nu;  // cos of angle to axis
        double su = std::sqrt(1.0 - u * u);
        for (int j = 0; j < nphi; ++j) {
          double phi = 2.0 * kPi * (j + 0.5) / nphi;
          glm::dvec3 w = axis * u + t1 * (su * std::cos(phi)) + t2 * (su * std::sin(phi));
          sum += std::max(w.z, 0.0);
        }
      }
      double integral = sum * (1.0 - cos_sigma) * 2.0 * kPi / (double(nu) * nphi);
      double expected = integral / (kPi * sin_sigma * sin_sigma);
      float got = g::sphereHorizonFactor(float(std::cos(theta)), sin_sigma * sin_sigma);
      EXPECT_NEAR(got, expected, 2e-3) << "sin_sigma " << sin_sigma << " theta " << theta_deg;
    }
}

// Karis 2013's representative-point sphere specular evaluated in double precision, written here
// from the paper independently of lights.glsl: eq. 11 (the point of the sphere closest to the
// reflection ray), eqs. 2 and 4 with F = 1 (karisSpecularDouble, karis_double.hpp), eqs. 10 and 14
// (normalization (alpha / alpha')^2, alpha' = saturate(alpha + r / (3 d)), the widening
// docs/lights.md states), eq. 9 (falloff window / (d^2 + 1)), times N.L.
double karisSphereSpecularDouble(double roughness, glm::dvec3 center, double radius, glm::dvec3 V,
                                 double I, double range) {
  const glm::dvec3 N(0, 0, 1);
  const glm::dvec3 R = 2.0 * glm::dot(N, V) * N - V;
  const double d2 = glm::dot(center, center), d = std::sqrt(d2);
  const glm::dvec3 to_ray = glm::dot(center, R) * R - center;
  const double t = std::min(radius / std::max(glm::length(to_ray), 1e-300), 1.0);
  const glm::dvec3 L = glm::normalize(center + to_ray * t);
  const glm::dvec3 H = glm::normalize(V + L);
  const double NoL = std::max(glm::dot(N, L), 0.0), NoV = std::max(glm::dot(N, V), 1e-4);
  const double NoH = std::max(glm::dot(N, H), 0.0);
  const double a = std::max(roughness, 0.045) * std::max(roughness, 0.045);
  const double a_p = std::min(a + radius / (3.0 * d), 1.0);
  const double norm = (a / a_p) * (a / a_p);
  const double window = std::pow(std::clamp(1.0 - std::pow(d / range, 4.0), 0.0, 1.0), 2.0);
  return NoL > 0.0 ? hv::test::karisSpecularDouble(roughness, NoH, NoV, NoL) * norm * NoL * I *
                         window / (d2 + 1.0)
                   : 0.0;
}

// The representative-point sphere light (the default) equals Karis's formula evaluated in double
// precision within 1% wherever it is not negligible (> 1e-6 of its peak over the view set), over
// roughness 0.045-1, r/d 0.01-0.98, elevations 5-90 degrees and views at and around the mirror
// direction (rings of 0.05-20 degrees) plus 200 views over the hemisphere. This is what D_GGX's
// |N x H|^2 form (brdf.glsl) buys: with (1 - NoH)(1 + NoH) from a float N.H the peak at
// roughness 0.045-0.1 was up to 6% low. Measured worst: printed.
TEST(Lights, RepresentativePointEqualsKarisInDouble) {
  double worst = 0.0;
  std::string worst_at;
  int compared = 0;
  for (float roughness : {0.045f, 0.05f, 0.1f, 0.2f, 0.35f, 0.5f, 0.75f, 1.0f})
    for (float rd : {0.01f, 0.05f, 0.1f, 0.25f, 0.5f, 0.98f})
      for (float elev_deg : {5.0f, 15.0f, 30.0f, 45.0f, 60.0f, 90.0f}) {
        const g::Surface s = g::makeSurface({0, 0, 1}, glm::vec3(1.0f), 1.0f, roughness, 1.0f);
        const double e = elev_deg * kPi / 180.0;
        const glm::dvec3 c(std::cos(e), 0.0, std::sin(e));  // distance 1
        hv::Light l;
        l.type = hv::LightType::Sphere;
        l.position = glm::vec3(c);
        l.radius = rd;
        l.intensity = 1.0f;
        l.range = 100.0f;
        std::vector<glm::dvec3> views;
        const glm::dvec3 mirror(-c.x, -c.y, c.z);  // view whose reflection ray hits the center
        views.push_back(mirror);
        const glm::dvec3 t1 = glm::normalize(glm::cross(mirror, glm::dvec3(0, 1, 0)));
        const glm::dvec3 t2 = glm::cross(mirror, t1);
        for (double ring_deg : {0.05, 0.2, 1.0, 5.0, 20.0})
          for (int k = 0; k < 8; ++k) {
            const double phi = 2.0 * kPi * k / 8, a = ring_deg * kPi / 180.0;
            views.push_back(std::cos(a) * mirror +
                            std::sin(a) * (std::cos(phi) * t1 + std::sin(phi) * t2));
          }
        const double golden = kPi * (3.0 - std::sqrt(5.0));
        for (int i = 0; i < 200; ++i) {  // Fibonacci points on the upper hemisphere
          const double z = 1.0 - (i + 0.5) / 200.0, r = std::sqrt(1.0 - z * z);
          views.push_back({std::cos(golden * i) * r, std::sin(golden * i) * r, z});
        }
        std::vector<double> ref, eng;
        double peak = 0.0;
        for (const glm::dvec3& v : views) {
          if (v.z <= 0.0) continue;
          ref.push_back(karisSphereSpecularDouble(roughness, c, rd, v, 1.0, 100.0));
          eng.push_back(shade(l, s, glm::vec3(0.0f), glm::vec3(v)).x);
          peak = std::max(peak, ref.back());
        }
        for (size_t i = 0; i < ref.size(); ++i) {
          if (ref[i] <= 1e-6 * peak) continue;
          ++compared;
          const double rel = std::abs(eng[i] / ref[i] - 1.0);
          if (rel > worst) {
            worst = rel;
            worst_at = "roughness " + std::to_string(roughness) + " r/d " + std::to_string(rd) +
                       " elevation " + std::to_string(elev_deg) + " view " + std::to_string(i);
          }
        }
      }
  std::printf("representative point vs Karis in double: %d values, worst %.4f%% (%s)\n", compared,
              100.0 * worst, worst_at.c_str());
  EXPECT_GT(compared, 40000);
  EXPECT_LT(worst, 0.01) << worst_at;
}

// Finite and non-negative everywhere: roughness 0 and 1, NoV = NoL = 0, V below the surface,
// shading point at the light center / inside the sphere or on the tube segment, radius and
// length 0, distances 1e-6 to 1e6, intensity 1e6, base color 0/1, metallic 0/1.
// The directional light is the sphere light at distance 1 (default methods: representative point,
// Karis point diffuse); 1e-5 relative: the two compute the same terms, the sphere's falloff
// rounding once more.
TEST(Lights, DirectionalIsTheSphereAtInfinity) {
  std::string where;
  EXPECT_LT(g::directionalVsSphereWorst(&where), 1e-5) << where;
}

TEST(Lights, StabilitySweepDefaults) {
  int cases = hv::glsl::runStabilitySweep();
  EXPECT_GT(cases, 100000);
}

}  // namespace
