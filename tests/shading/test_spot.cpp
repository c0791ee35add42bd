// The spot's cone (shaders/common/spot.glsl): KHR_lights_punctual's smooth attenuation by hand,
// its packing into the light record, the point and sphere evaluations it multiplies, and the
// culling's bounding sphere of the cone's sector.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "halfvec/shading/light_gpu.hpp"
#include "halfvec/shading/shading.hpp"

namespace g = hv::glsl;

namespace {

hv::Light spot(float radius) {
  hv::Light l;
  l.type = hv::LightType::Spot;
  l.position = {0.0f, 2.0f, 0.0f};
  l.direction = {0.0f, -3.0f, 0.0f};  // normalized by packLight
  l.radius = radius;
  l.inner_cone_angle = 0.3f;
  l.outer_cone_angle = 0.6f;
  l.intensity = 4.0f;
  l.range = 8.0f;
  return l;
}

// The unit direction from a point at angle `theta` from the spot's axis toward the light.
glm::vec3 towardLight(float theta) {
  return -glm::vec3(std::sin(theta), -std::cos(theta), 0.0f);
}

}  // namespace

// t = saturate((cos - cos_outer) / (cos_inner - cos_outer)), squared (KHR_lights_punctual).
TEST(Spot, AttenuationIsTheSpecificationsSmoothProfile) {
  const hv::GpuLight gl = hv::packLight(spot(0.0f));
  EXPECT_EQ(gl.type, unsigned(HV_LIGHT_POINT) | HV_LIGHT_SPOT_FLAG);
  const float ci = std::cos(0.3f), co = std::cos(0.6f);
  for (float theta = 0.0f; theta < 1.2f; theta += 0.01f) {
    const float t = std::clamp((std::cos(theta) - co) / (ci - co), 0.0f, 1.0f);
    const float a = g::spotAttenuation(towardLight(theta), gl.axis_length);
    EXPECT_NEAR(a, t * t, 2e-5f) << theta;
    if (theta <= 0.29f) {
      EXPECT_EQ(a, 1.0f) << theta;  // inside the inner cone: the point light
    }
    if (theta >= 0.61f) {
      EXPECT_EQ(a, 0.0f) << theta;  // outside the outer cone: exactly 0
    }
  }
  // A light that is not a spot is never attenuated, whatever its axis holds.
  hv::Light point = spot(0.0f);
  point.type = hv::LightType::Point;
  EXPECT_EQ(g::lightCone(hv::packLight(point), towardLight(1.0f)), 1.0f);
}

// The cone multiplies the point and the sphere evaluation (both terms): a spot equals its shape
// times spotAttenuation of the direction to its center.
TEST(Spot, ScalesThePointAndTheSphereLight) {
  g::Surface s = g::makeSurface(glm::vec3(0, 1, 0), glm::vec3(0.7f), 0.3f, 0.4f, 1.0f);
  const glm::vec3 V = glm::normalize(glm::vec3(0.3f, 1.0f, 0.2f));
  for (float radius : {0.0f, 0.2f}) {
    hv::Light l = spot(radius);
    hv::Light shape = l;
    shape.type = radius > 0.0f ? hv::LightType::Sphere : hv::LightType::Point;
    const hv::GpuLight gs = hv::packLight(l), gp = hv::packLight(shape);
    EXPECT_EQ(gs.type & HV_LIGHT_TYPE_MASK, gp.type);
    for (float x = 0.0f; x < 2.5f; x += 0.05f) {
      const glm::vec3 P(x, 0.0f, 0.1f);
      const glm::vec3 L = glm::normalize(l.position - P);
      const glm::vec3 a = g::evaluateLight(gs, s, P, V), b = g::evaluateLight(gp, s, P, V);
      const float cone = g::spotAttenuation(L, gs.axis_length);
      for (int k = 0; k < 3; ++k)
        EXPECT_NEAR(a[k], b[k] * cone, 4e-6f * b[k]) << radius << " " << x;
    }
  }
}

// Every point the spot can light (within the outer cone and the range) lies in its culling
// sphere, and the sphere is smaller than the range sphere: R / (2 cos theta) for theta <= pi/4,
// R sin theta above.
TEST(Spot, CullSphereHoldsTheConesSector) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  for (float outer : {0.05f, 0.3f, 0.7853f, 0.79f, 1.2f, 1.5707963f}) {
    hv::Light l = spot(0.0f);
    l.direction = glm::normalize(glm::vec3(0.3f, -1.0f, 0.5f));
    l.inner_cone_angle = 0.5f * outer;
    l.outer_cone_angle = outer;
    const hv::GpuLight gl = hv::packLight(l);
    const glm::vec4 sphere = g::lightCullSphere(gl);
    const float expected =
        outer <= 0.7853982f ? l.range / (2.0f * std::cos(outer)) : l.range * std::sin(outer);
    EXPECT_NEAR(sphere.w, expected, 2e-4f * l.range) << outer;
    EXPECT_LE(sphere.w, l.range * 1.0001f) << outer;
    glm::vec3 t, b;
    g::tangentFrame(l.direction, t, b);
    int inside_cone = 0;
    for (int i = 0; i < 20000; ++i) {
      // Points of the sector, with its rim and cap (u = 1) and the apex (r = 0) weighted in.
      const float theta = outer * std::min(1.0f, 1.05f * u(rng)), phi = 6.2831853f * u(rng);
      const float r = l.range * std::min(1.0f, 1.1f * u(rng));
      const glm::vec3 dir =
          std::cos(theta) * l.direction + std::sin(theta) * (std::cos(phi) * t + std::sin(phi) * b);
      const glm::vec3 P = l.position + r * dir;
      if (g::spotAttenuation(-dir, gl.axis_length) <= 0.0f) continue;
      ++inside_cone;
      EXPECT_LE(glm::length(P - glm::vec3(sphere)), sphere.w) << outer << " " << theta;
    }
    EXPECT_GT(inside_cone, 10000) << outer;
  }
}

// The cone-versus-tile test (cull.glsl, sphereOutsideCone) never culls a sphere that meets the
// cone: for random cones (outer angle up to pi/2) and spheres, a sphere with a sampled point in
// the capped cone is never reported outside; and it culls most spheres that are outside (the
// conservative test keeps some near the apex and the cap's rim, whose fraction is bounded).
TEST(Spot, ConeTestNeverCullsASphereThatMeetsTheCone) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  auto inCone = [](glm::vec3 p, glm::vec3 apex, glm::vec3 axis, float cos_t, float range) {
    const glm::vec3 v = p - apex;
    const float d = glm::length(v);
    return d <= range && (d == 0.0f || glm::dot(v, axis) >= cos_t * d);
  };
  int met = 0, outside = 0, culled_outside = 0;
  for (int c = 0; c < 10000; ++c) {
    const glm::vec3 apex(4.0f * u(rng) - 2.0f, 4.0f * u(rng) - 2.0f, 4.0f * u(rng) - 2.0f);
    const glm::vec3 axis = glm::normalize(glm::vec3(u(rng) - 0.5f, u(rng) - 0.5f, u(rng) - 0.5f));
    const float theta = 1.5707963f * u(rng), cos_t = std::cos(theta), range = 0.5f + 3.0f * u(rng);
    const glm::vec3 center(6.0f * u(rng) - 3.0f, 6.0f * u(rng) - 3.0f, 6.0f * u(rng) - 3.0f);
    const float r = 0.05f + 0.6f * u(rng);
    bool meets = inCone(center, apex, axis, cos_t, range);
    for (int k = 0; k < 400 && !meets; ++k) {
      glm::vec3 d(u(rng) - 0.5f, u(rng) - 0.5f, u(rng) - 0.5f);
      if (glm::length(d) < 1e-3f) continue;
      meets =
          inCone(center + glm::normalize(d) * (r * std::cbrt(u(rng))), apex, axis, cos_t, range);
    }
    const bool culled = g::sphereOutsideCone(center, r, apex, axis, cos_t, range);
    if (meets) {
      ++met;
      ASSERT_FALSE(culled) << "case " << c;
    } else {
      ++outside;
      culled_outside += culled;
    }
  }
  std::printf("cone test: %d spheres meet a cone, %d do not, of which %d culled\n", met, outside,
              culled_outside);
  EXPECT_GT(met, 400);
  EXPECT_GT(culled_outside, outside * 8 / 10);
}
