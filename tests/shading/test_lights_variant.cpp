// The same light code compiled with every non-default option (its own compilation of the shared
// headers, in its own namespace; this file does not include shading.hpp): physical 1/d^2 falloff,
// horizon-correct sphere diffuse, eq. 18 tube specular, no normalizations, Heitz V, exact Fresnel,
// Burley diffuse. HV_REMAP_ROUGHNESS stays 1 here: with Heitz V it must have no effect (the Disney
// remap is for Schlick-GGX only, Karis 2013 eq. 4), which RemapIgnoredForSmithV checks.
#include <gtest/gtest.h>

#include <cmath>

// The default compilation (hv::glsl, via light_gpu.hpp) comes first; then the include guards
// and option defines are reset and the headers are compiled again into namespace variant.
#include "halfvec/shading/light_gpu.hpp"

#undef HV_MATH_GLSL
#undef HV_BRDF_GLSL
#undef HV_LIGHTS_GLSL
#undef HV_SPOT_GLSL
#undef HV_LTC_GLSL
#undef HV_LTC_LIGHTS_GLSL
#undef HV_LTC_INTEGRALS_GLSL
#undef HV_SAMPLING_GLSL
#undef HV_BRDF_D
#undef HV_BRDF_V
#undef HV_BRDF_F
#undef HV_BRDF_FD
#undef HV_REMAP_ROUGHNESS
#undef HV_FALLOFF_PLUS_ONE
#undef HV_SPHERE_DIFFUSE
#undef HV_SPHERE_NORMALIZATION
#undef HV_TUBE_SPECULAR
#undef HV_TUBE_NORMALIZATION

#define HV_FALLOFF_PLUS_ONE 0
#define HV_SPHERE_DIFFUSE 1
#define HV_TUBE_SPECULAR 1
#define HV_SPHERE_NORMALIZATION 0
#define HV_TUBE_NORMALIZATION 0
#define HV_BRDF_V 1
#define HV_BRDF_F 2
#define HV_BRDF_FD 1
#define HV_REMAP_ROUGHNESS 1

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wunused-parameter"
namespace variant {
using namespace glm;
using hv::GpuLight;  // gpu_records.glsl, declared once outside the variants
using uint = unsigned int;
namespace {
#include "halfvec/shaders/common/math.glsl"
#include "halfvec/shaders/common/brdf.glsl"
#include "halfvec/shaders/common/lights.glsl"
#include "light_sweep.inc"
}  // namespace
}  // namespace variant
#pragma GCC diagnostic pop

static_assert(HV_FALLOFF_PLUS_ONE == 0 && HV_SPHERE_DIFFUSE == 1, "variant defines not in effect");

namespace {

constexpr double kPi = 3.14159265358979323846;

TEST(LightsVariant, StabilitySweepAllOptions) {
  EXPECT_GT(variant::runStabilitySweep(), 100000);
}

// HV_REMAP_ROUGHNESS = 1 with HV_BRDF_V = Heitz correlated Smith: visibility() uses alpha itself,
// not the Disney-remapped alpha (Karis 2013 eq. 4 remaps Schlick-GGX only). Exact equality: the
// dispatcher must call the term with the same argument.
TEST(LightsVariant, RemapIgnoredForSmithV) {
  const float roughness = 0.3f, alpha = roughness * roughness;
  EXPECT_EQ(variant::visibility(roughness, alpha, 0.6f, 0.4f, 0.9f, 0.7f),
            variant::V_SmithGGXCorrelated(alpha, 0.6f, 0.4f));
  EXPECT_NE(variant::visibility(roughness, alpha, 0.6f, 0.4f, 0.9f, 0.7f),
            variant::V_SmithGGXCorrelated(variant::remappedVisibilityAlpha(roughness), 0.6f, 0.4f));
}

// variant::GpuLight is hv::GpuLight (declared once, outside the variants).
variant::GpuLight toVariant(const hv::GpuLight& p) {
  return p;
}

// With HV_FALLOFF_PLUS_ONE = 0 and the horizon-correct sphere, the diffuse radiance of a sphere
// light is exactly that of the emitter of docs/lights.md: a sphere of uniform radiance
// I / (pi r^2) (times the window). Brute-force check: integrate that radiance times max(cos, 0)
// over the sphere's visible cap, times diffuse_color / pi (Lambert has no Burley term here:
// compare with base color 1 vs 0 to isolate the diffuse part). Tolerance 3e-3 relative.
TEST(LightsVariant, SphereDiffuseMatchesEmitter) {
  const float I = 5.0f, r = 0.4f, range = 1000.0f;
  for (float theta_deg : {0.0f, 45.0f, 80.0f, 95.0f}) {
    double theta = theta_deg * kPi / 180.0;
    const double d = 1.0;
    hv::Light l;
    l.type = hv::LightType::Sphere;
    l.position = glm::vec3(float(d * std::sin(theta)), 0.0f, float(d * std::cos(theta)));
    l.radius = r;
    l.intensity = I;
    l.range = range;
    variant::GpuLight gl = toVariant(hv::packLight(l));
    // Burley diffuse at NoV = 1 with roughness 1 depends on NoL, so use V = N and compare
    // against the integral of the Burley lobe itself over the cap.
    glm::vec3 N(0, 0, 1), V(0, 0, 1);
    variant::Surface white = variant::makeSurface(N, glm::vec3(1.0f), 0.0f, 1.0f, 1.0f);
    variant::Surface black = variant::makeSurface(N, glm::vec3(0.0f), 0.0f, 1.0f, 1.0f);
    double diffuse = double(variant::evaluateLight(gl, white, glm::vec3(0.0f), V).x) -
                     double(variant::evaluateLight(gl, black, glm::vec3(0.0f), V).x);
    // Reference with the Lambert lobe: radiance L_e = I / (pi r^2), windowed at the center.
    double Le = I / (kPi * r * r) * variant::falloffWindow(float(d * d), 1.0f / range);
    double sin_sigma = r / d, cos_sigma = std::sqrt(1.0 - sin_sigma * sin_sigma);
    glm::dvec3 axis(std::sin(theta), 0.0, std::cos(theta));
    glm::dvec3 t1(std::cos(theta), 0.0, -std::sin(theta)), t2(0.0, 1.0, 0.0);
    const int nu = 300, nphi = 300;
    double sum = 0.0;
    for (int i = 0; i < nu; ++i) {
      double u = cos_sigma + (1.0 - cos_sigma) * (i + 0.5) / nu;
      double su = std::sqrt(1.0 - u * u);
      for (int j = 0; j < nphi; ++j) {
        double phi = 2.0 * kPi * (j + 0.5) / nphi;
        glm::dvec3 w = axis * u + t1 * (su * std::cos(phi)) + t2 * (su * std::sin(phi));
        sum += std::max(w.z, 0.0);
      }
    }
    double E = Le * sum * (1.0 - cos_sigma) * 2.0 * kPi / (double(nu) * nphi);
    // The engine evaluates Burley once for the center direction; at V = N, roughness 1 its factor
    // is F(1, f90, NoL) * F(1, f90, 1) = 1 + (f90 - 1)(1 - NoL)^5, evaluated for the center.
    glm::vec3 Lc = glm::normalize(l.position);
    glm::vec3 H = glm::normalize(V + Lc);
    double burley = variant::Fd_Burley(1.0f, 1.0f, std::max(Lc.z, 0.0f), glm::dot(Lc, H)) * kPi;
    EXPECT_NEAR(diffuse, E / kPi * burley, 3e-3 * E / kPi * burley + 1e-7) << theta_deg;
  }
}

// With HV_FALLOFF_PLUS_ONE = 0, Karis eq. 16 is the exact irradiance of a segment of isotropic
// emitters of total intensity I when both ends are above the horizon. Brute force: sum of point
// lights I/n along the segment. Tolerance 1e-3 relative.
TEST(LightsVariant, TubeDiffuseMatchesLineIntegral) {
  const float I = 3.0f, len = 2.0f;
  glm::vec3 N(0, 0, 1);
  glm::vec3 c(0.3f, -0.2f, 1.2f), axis = glm::normalize(glm::vec3(1.0f, 0.3f, 0.1f));
  hv::Light l;
  l.type = hv::LightType::Tube;
  l.position = c;
  l.axis = axis;
  l.length = len;
  l.radius = 0.0f;
  l.intensity = I;
  l.range = 1e4f;
  variant::GpuLight gl = toVariant(hv::packLight(l));
  // Diffuse part of evaluateLight: with V = N and roughness 1 Burley is evaluated for the
  // direction to the closest segment point; divide it out, leaving E / pi.
  glm::vec3 V(0, 0, 1);
  variant::Surface white = variant::makeSurface(N, glm::vec3(1.0f), 0.0f, 1.0f, 1.0f);
  variant::Surface black = variant::makeSurface(N, glm::vec3(0.0f), 0.0f, 1.0f, 1.0f);
  double diffuse = double(variant::evaluateLight(gl, white, glm::vec3(0.0f), V).x) -
                   double(variant::evaluateLight(gl, black, glm::vec3(0.0f), V).x);
  glm::vec3 L0 = c - 0.5f * len * axis, Ld = len * axis;
  float tp = glm::clamp(-glm::dot(L0, Ld) / glm::dot(Ld, Ld), 0.0f, 1.0f);
  glm::vec3 Lp = glm::normalize(L0 + tp * Ld), H = glm::normalize(V + Lp);
  double burley = variant::Fd_Burley(1.0f, 1.0f, Lp.z, glm::dot(Lp, H)) * kPi;
  double window = variant::falloffWindow(glm::dot(L0 + tp * Ld, L0 + tp * Ld), 1e-4f);
  const int n = 20000;
  double E = 0.0;
  for (int i = 0; i < n; ++i) {
    glm::dvec3 p = glm::dvec3(L0) + glm::dvec3(Ld) * ((i + 0.5) / n);
    double d2 = glm::dot(p, p);
    E += (I / n) * std::max(p.z, 0.0) / (d2 * std::sqrt(d2));
  }
  double expected = E * window / kPi * burley;
  EXPECT_NEAR(diffuse, expected, 1e-3 * expected);
}

}  // namespace
