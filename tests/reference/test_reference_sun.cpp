// The reference's sun-sampling strategy for EnvironmentKind::Sky: a white Lambert surface under
// the procedural sky gets E / pi, E the sky's irradiance (dome by quadrature + the sun's cone),
// within 3 standard errors, with a standard error small enough that the sun is sampled rather
// than hit by chance; rotating the environment rotates the sampled sun with it.
#include <gtest/gtest.h>

#include <cmath>

#include "ibl/ibl.hpp"
#include "reference/reference.hpp"
#include "shading/shading.hpp"

namespace {

constexpr double kPi = 3.14159265358979323846;

// Camera at (0, 3, 3) looking at the origin; the single pixel of a 1x1 G-buffer sees the origin.
hv::Scene skyScene(float rotation_deg) {
  hv::Scene s;
  s.camera.position = {0.0f, 3.0f, 3.0f};
  s.camera.target = {0.0f, 0.0f, 0.0f};
  s.camera.near_plane = 0.05f;
  s.environment.kind = hv::EnvironmentKind::Sky;
  s.environment.rotation_deg = rotation_deg;
  return s;
}

hv::render::GBufferReadback whiteLambertAt(glm::vec3 normal, const hv::Scene& scene) {
  hv::render::GBufferReadback gb;
  gb.width = gb.height = 1;
  gb.base_color = {glm::vec3(1.0f)};
  gb.metallic = {0.0f};
  gb.roughness = {1.0f};
  gb.cavity = {1.0f};
  gb.normal = {normal};
  gb.model = {uint32_t(hv::ShadingModel::DefaultLit)};
  gb.depth = {scene.camera.near_plane / std::sqrt(18.0f)};
  return gb;
}

hv::ReferenceResult run(const hv::Scene& scene, glm::vec3 normal, int samples) {
  hv::ReferenceOptions o;
  o.samples = samples;
  o.threads = 2;
  return hv::renderReference(scene, whiteLambertAt(normal, scene), o);
}

TEST(ReferenceSun, LambertUnderSkyIsIrradianceOverPi) {
  const hv::SkyParams sky;
  // Dome: it depends only on the elevation; integrate along the azimuth opposite the sun (which
  // never meets the sun's cone). Sun: radiance x cone solid angle x cos of the sun's elevation.
  const glm::vec3 sun = hv::skySunDirection(sky);
  const glm::vec3 away = glm::normalize(glm::vec3(-sun.x, 0.0f, -sun.z));
  glm::dvec3 e_dome(0.0);
  const int n = 20000;
  for (int i = 0; i < n; ++i) {
    const double mu = (i + 0.5) / n, s = std::sqrt(1.0 - mu * mu);
    const glm::vec3 d(float(away.x * s), float(mu), float(away.z * s));
    e_dome += glm::dvec3(hv::skyRadiance(sky, d)) * (2.0 * kPi * mu / n);
  }
  const double cos_r = std::cos(double(sky.sun_angular_radius_deg) * kPi / 180.0);
  const glm::dvec3 e_sun =
      glm::dvec3(hv::skyRadiance(sky, sun)) * (2.0 * kPi * (1.0 - cos_r) * double(sun.y));
  const glm::dvec3 expected = (e_dome + e_sun) / kPi;  // Lambert: albedo 1, f = 1 / pi
  ASSERT_GT(e_sun.y, 2.0 * e_dome.y);                  // the sun dominates this sky

  const hv::ReferenceResult r = run(skyScene(0.0f), glm::vec3(0.0f, 1.0f, 0.0f), 4096);
  const glm::vec3 got = r[hv::ReferenceAov::AmbientDiffuse].px[0];
  const glm::vec3 se = r.stdError(hv::ReferenceAov::AmbientDiffuse).px[0];
  for (int k = 0; k < 3; ++k) {
    EXPECT_LT(se[k], 0.01 * expected[k]) << "channel " << k;
    // 3 SE plus 0.2% for the dome under the sun's cone and float rounding of the cone's edge.
    EXPECT_NEAR(got[k], expected[k], 3.0 * se[k] + 2e-3 * expected[k]) << "channel " << k;
  }
}

TEST(ReferenceSun, RotatedSkyRotatesTheSampledSun) {
  // A surface facing the sun of a sky rotated by 90 degrees about +Y sees what a surface facing
  // the unrotated sun sees in the unrotated sky.
  const glm::vec3 sun = hv::skySunDirection(hv::SkyParams{});
  const float a = glm::radians(90.0f);
  const glm::vec3 rotated(std::cos(a) * sun.x + std::sin(a) * sun.z, sun.y,
                          -std::sin(a) * sun.x + std::cos(a) * sun.z);
  const hv::ReferenceResult r0 = run(skyScene(0.0f), sun, 2048);
  const hv::ReferenceResult r1 = run(skyScene(90.0f), rotated, 2048);
  const glm::vec3 v0 = r0[hv::ReferenceAov::AmbientDiffuse].px[0];
  const glm::vec3 v1 = r1[hv::ReferenceAov::AmbientDiffuse].px[0];
  const glm::vec3 s0 = r0.stdError(hv::ReferenceAov::AmbientDiffuse).px[0];
  const glm::vec3 s1 = r1.stdError(hv::ReferenceAov::AmbientDiffuse).px[0];
  // Facing the sun, its cone alone gives L_sun omega / pi: a missed sun falls below this.
  const hv::SkyParams sky;
  const double cos_r = std::cos(double(sky.sun_angular_radius_deg) * kPi / 180.0);
  const glm::dvec3 sun_only = glm::dvec3(hv::skyRadiance(sky, sun)) * (2.0 * (1.0 - cos_r));
  for (int k = 0; k < 3; ++k) {
    EXPECT_GT(v1[k], sun_only[k]) << "channel " << k;
    EXPECT_LT(s1[k], 0.02f * v1[k]);
    EXPECT_NEAR(v0[k], v1[k], 3.0f * std::sqrt(s0[k] * s0[k] + s1[k] * s1[k]));
  }
}

}  // namespace
