// The reference's visibility (ReferenceOptions::visibility, Embree): a flat open plane does not
// shadow itself and has ambient occlusion 1; a point light's shadow of a sphere ends where the
// geometry says (within one pixel); a sphere light's penumbra is fully lit / fully dark where the
// two spheres' cones say and widens with the light's radius and the occluder's height; the floor
// beside a resting sphere under a uniform environment has ambient diffuse and occlusion
// 1 - (R / sqrt(x^2 + R^2))^3 (the sphere's projected solid angle over pi); rays stop at the
// emitter; alpha-masked and back-facing occluders; visibility off ignores the geometry bit for bit.
// Every G-buffer is built by hand (the floor y = 0 seen by the scene's camera): no GL context.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "halfvec/reference/reference.hpp"
#include "halfvec/reference/visibility.hpp"
#include "halfvec/scene/gltf_loader.hpp"
#include "halfvec/scene/primitives.hpp"
#include "halfvec/shading/shading.hpp"
#include "shared_assets.hpp"

namespace {

namespace g = hv::glsl;
constexpr float kPi = 3.14159265358979f;

// Camera at `eye` looking at `target` (up +Z when looking straight down), no environment, no
// lights, a 40 x 40 m floor plane at y = 0 among the scene's triangles.
hv::Scene floorScene(glm::vec3 eye, glm::vec3 target, float fov_y_deg = 45.0f,
                     glm::vec3 floor_at = glm::vec3(0.0f)) {
  hv::Scene s;
  s.camera.position = eye;
  s.camera.target = target;
  const glm::vec3 fwd = glm::normalize(target - eye);
  s.camera.up = std::abs(fwd.y) > 0.99f ? glm::vec3(0.0f, 0.0f, -1.0f) : glm::vec3(0, 1, 0);
  s.camera.fov_y_deg = fov_y_deg;
  s.camera.near_plane = 0.05f;
  s.environment.kind = hv::EnvironmentKind::None;
  hv::Material floor;
  floor.base_color = glm::vec3(0.5f);
  floor.roughness = 1.0f;
  hv::addMeshObject(s, hv::makePlane(40.0f, 40.0f), floor, floor_at);
  return s;
}

hv::Material grey() {
  hv::Material m;
  m.base_color = glm::vec3(0.5f);
  return m;
}

// A w x h G-buffer of the floor y = 0 (albedo 0.5, roughness 1, normal +Y) at every pixel whose
// ray meets it, background elsewhere; whatever else is in the scene is invisible to the camera
// (it only occludes).
hv::GBufferReadback floorGBuffer(const hv::Scene& scene, int w, int h) {
  hv::GBufferReadback gb;
  gb.width = w;
  gb.height = h;
  const size_t n = size_t(w) * size_t(h);
  gb.base_color.assign(n, glm::vec3(0.5f));
  gb.metallic.assign(n, 0.0f);
  gb.roughness.assign(n, 1.0f);
  gb.cavity.assign(n, 1.0f);
  gb.normal.assign(n, glm::vec3(0.0f, 1.0f, 0.0f));
  gb.model.assign(n, uint32_t(hv::ShadingModel::DefaultLit));
  gb.depth.assign(n, 0.0f);
  const glm::mat4 view = glm::lookAt(scene.camera.position, scene.camera.target, scene.camera.up);
  const glm::mat4 inv = hv::referenceInvViewProj(scene.camera, w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const size_t i = size_t(y) * size_t(w) + size_t(x);
      const glm::vec2 uv((x + 0.5f) / float(w), 1.0f - (y + 0.5f) / float(h));
      const glm::vec3 dir =
          glm::normalize(g::reconstructWorldPosition(uv, 1e-3f, inv) - scene.camera.position);
      if (dir.y >= -1e-6f) {
        gb.model[i] = uint32_t(hv::ShadingModel::Background);
        continue;
      }
      const glm::vec3 P = scene.camera.position + (-scene.camera.position.y / dir.y) * dir;
      gb.depth[i] = scene.camera.near_plane / -(view * glm::vec4(P, 1.0f)).z;
    }
  return gb;
}

// World position of pixel i as the reference reconstructs it.
glm::vec3 pixelPosition(const hv::Scene& scene, const hv::GBufferReadback& gb, size_t i) {
  const int x = int(i % size_t(gb.width)), y = int(i / size_t(gb.width));
  const glm::vec2 uv((x + 0.5f) / float(gb.width), 1.0f - (y + 0.5f) / float(gb.height));
  return g::reconstructWorldPosition(uv, gb.depth[i],
                                     hv::referenceInvViewProj(scene.camera, gb.width, gb.height));
}

// A camera straight down from height `height` over (cx, 0, cz) whose 1-pixel-high image of width
// w covers x in [cx - half, cx + half] along z = cz (a line on the floor).
hv::Scene lineScene(int w, float half, float height = 6.0f) {
  const float fov = 2.0f * std::atan(half / (height * float(w)));
  return floorScene({0.0f, height, 0.0f}, {0.0f, 0.0f, 0.0f}, glm::degrees(fov));
}

hv::ReferenceOptions options(int samples, bool visibility) {
  hv::ReferenceOptions o;
  o.samples = samples;
  o.threads = 2;
  o.visibility = visibility;
  return o;
}

bool bitEqual(const hv::ImageRGBf& a, const hv::ImageRGBf& b) {
  return a.width == b.width && a.height == b.height &&
         std::equal(a.px.begin(), a.px.end(), b.px.begin(),
                    [](const glm::vec3& p, const glm::vec3& q) {
                      return p.x == q.x && p.y == q.y && p.z == q.z;
                    });
}

// An open plane lit at 85 degrees from its normal by a point light and a uniform environment,
// seen at grazing angles, near the origin and 1 km from it: no visibility ray meets the plane
// (the image with visibility is the one without, bit for bit) and the ambient occlusion is 1.
TEST(ReferenceVisibility, FlatOpenPlaneHasNoSelfShadowing) {
  for (const glm::vec3 at : {glm::vec3(0.0f), glm::vec3(1000.0f, 0.0f, -700.0f)}) {
    hv::Scene s =
        floorScene(at + glm::vec3(0.0f, 0.6f, 9.0f), at + glm::vec3(0.0f, 0.0f, -3.0f), 45.0f, at);
    s.environment.kind = hv::EnvironmentKind::Uniform;
    hv::Light l;
    l.position = at + glm::vec3(6.0f * std::sin(glm::radians(85.0f)),
                                6.0f * std::cos(glm::radians(85.0f)), 0.0f);
    l.intensity = 50.0f;
    l.range = 100.0f;
    s.lights.push_back(l);
    hv::Light sphere = l;
    sphere.type = hv::LightType::Sphere;
    sphere.radius = 0.2f;
    sphere.position = at + glm::vec3(-5.0f, 0.5f, 1.0f);  // 84 degrees from the normal
    s.lights.push_back(sphere);
    const hv::GBufferReadback gb = floorGBuffer(s, 48, 32);
    const hv::ReferenceResult off = hv::renderReference(s, gb, options(16, false));
    const hv::ReferenceResult on = hv::renderReference(s, gb, options(16, true));
    EXPECT_GT(on.stats.rays, 48u * 16u * 16u) << "rays were traced";
    EXPECT_TRUE(bitEqual(on.image, off.image)) << "at " << at.x;
    for (int a = 0; a < hv::kReferenceAovCount; ++a)
      EXPECT_TRUE(bitEqual(on.aov[size_t(a)], off.aov[size_t(a)]))
          << hv::toString(hv::ReferenceAov(a));
    size_t lit = 0;
    for (size_t i = 0; i < gb.model.size(); ++i) {
      if (gb.model[i] != uint32_t(hv::ShadingModel::DefaultLit)) continue;
      ++lit;
      ASSERT_EQ(on.ao.px[i].x, 1.0f) << "pixel " << i;
      ASSERT_EQ(on.ao_std_error.px[i].x, 0.0f);
    }
    EXPECT_GT(lit, 800u);
  }
}

// Visibility off ignores the scene's triangles: a sphere over the floor changes nothing, and the
// images equal those with visibility on in a scene where nothing can occlude.
TEST(ReferenceVisibility, OffIgnoresGeometry) {
  hv::Scene open = floorScene({0.0f, 5.0f, 3.0f}, {0.0f, 0.0f, 0.0f});
  open.environment.kind = hv::EnvironmentKind::Sky;
  hv::Light l;
  l.type = hv::LightType::Tube;
  l.position = {0.3f, 2.5f, 0.0f};
  l.radius = 0.1f;
  l.length = 0.8f;
  l.intensity = 20.0f;
  open.lights.push_back(l);
  hv::Scene occluded = open;
  hv::addMeshObject(occluded, hv::makeSphere(0.5f), grey(), {0.0f, 1.0f, 0.0f});
  const hv::GBufferReadback gb = floorGBuffer(open, 32, 24);
  const hv::ReferenceResult a = hv::renderReference(occluded, gb, options(8, false));
  const hv::ReferenceResult b = hv::renderReference(open, gb, options(8, true));
  const hv::ReferenceResult c = hv::renderReference(occluded, gb, options(8, true));
  EXPECT_EQ(a.stats.rays, 0u);
  EXPECT_TRUE(bitEqual(a.image, b.image));
  EXPECT_TRUE(bitEqual(a.std_error, b.std_error));
  EXPECT_FALSE(bitEqual(a.image, c.image)) << "the sphere shadows the floor with visibility";
}

// Whether the segment from X to the point light at Lp passes within r of the center C.
bool segmentMeetsSphere(glm::dvec3 X, glm::dvec3 Lp, glm::dvec3 C, double r) {
  const glm::dvec3 d = Lp - X;
  const double t = std::clamp(glm::dot(C - X, d) / glm::dot(d, d), 0.0, 1.0);
  return glm::length(X + t * d - C) < r;
}

// A point light's shadow of a sphere (0.5 m, 1 m above the floor) on the floor: every pixel the
// reference shadows (direct light exactly 0) is shadowed by the analytic sphere and every pixel it
// lights is lit, except pixels next to the analytic boundary (one pixel = 2.5 cm).
TEST(ReferenceVisibility, PointLightShadowBoundaryWithinOnePixel) {
  hv::Scene s = floorScene({0.0f, 6.0f, 0.0f}, {0.0f, 0.0f, 0.0f},
                           2.0f * glm::degrees(std::atan(2.0f / 6.0f)));
  const glm::vec3 C(0.1f, 1.5f, -0.2f);
  const float R = 0.5f;
  hv::addMeshObject(s, hv::makeSphere(R, 128, 64), grey(), C);
  hv::Light l;
  l.position = {0.9f, 4.0f, 0.5f};
  l.intensity = 20.0f;
  l.range = 50.0f;
  s.lights.push_back(l);
  const int w = 160;  // 4 m wide: 2.5 cm per pixel
  const hv::GBufferReadback gb = floorGBuffer(s, w, w);
  const hv::ReferenceResult r = hv::renderReference(s, gb, options(1, true));
  std::vector<int> analytic(gb.model.size());
  for (size_t i = 0; i < gb.model.size(); ++i)
    analytic[i] = segmentMeetsSphere(glm::dvec3(pixelPosition(s, gb, i)), glm::dvec3(l.position),
                                     glm::dvec3(C), R);
  size_t shadowed = 0, mismatched = 0;
  for (int y = 0; y < w; ++y)
    for (int x = 0; x < w; ++x) {
      const size_t i = size_t(y) * size_t(w) + size_t(x);
      const bool ref_shadow = r[hv::ReferenceAov::DirectDiffuse].px[i].x == 0.0f;
      shadowed += ref_shadow;
      if (ref_shadow == bool(analytic[i])) continue;
      ++mismatched;
      bool near_boundary = false;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int xx = std::clamp(x + dx, 0, w - 1), yy = std::clamp(y + dy, 0, w - 1);
          near_boundary |= analytic[size_t(yy) * size_t(w) + size_t(xx)] != analytic[i];
        }
      EXPECT_TRUE(near_boundary) << "pixel (" << x << ", " << y << ") is "
                                 << (ref_shadow ? "shadowed" : "lit") << " away from the boundary";
    }
  // The shadow is an ellipse of about 0.5 m^2 (800 pixels); its boundary about 150 pixels.
  EXPECT_GT(shadowed, 500u);
  EXPECT_LT(mismatched, 60u);
  for (const glm::vec3& e : r.stdError(hv::ReferenceAov::DirectDiffuse).px) ASSERT_EQ(e.x, 0.0f);
}

// ---- Sphere light penumbra ----

// First t > 0 where the ray X + t d (d unit) meets the sphere (C, r), or -1.
double raySphere(glm::dvec3 X, glm::dvec3 d, glm::dvec3 C, double r) {
  const glm::dvec3 oc = X - C;
  const double b = glm::dot(d, oc), h = b * b - (glm::dot(oc, oc) - r * r);
  if (h < 0.0) return -1.0;
  const double t = -b - std::sqrt(h);
  return t > 0.0 ? t : -1.0;
}

// The visible fraction of the sphere light (center Lc, radius rl) as the floor point X's direct
// diffuse sees it: a 256 x 256 midpoint quadrature over the light's cone (uniform in solid angle,
// as its radiance is) of NoL, with and without the occluder sphere (C, ro) in the way.
double visibleFraction(glm::dvec3 X, glm::dvec3 Lc, double rl, glm::dvec3 C, double ro) {
  const glm::dvec3 to = Lc - X;
  const double d = glm::length(to);
  const glm::dvec3 axis = to / d;
  const double cos_max = std::sqrt(1.0 - rl * rl / (d * d));
  const glm::dvec3 t = glm::normalize(glm::cross(axis, glm::dvec3(1, 0, 0)));
  const glm::dvec3 b = glm::cross(axis, t);
  double all = 0.0, seen = 0.0;
  const int n = 256;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double ct = 1.0 - (i + 0.5) / n * (1.0 - cos_max), st = std::sqrt(1.0 - ct * ct);
      const double phi = 2.0 * kPi * (j + 0.5) / n;
      const glm::dvec3 L = t * (st * std::cos(phi)) + b * (st * std::sin(phi)) + axis * ct;
      const double nol = std::max(L.y, 0.0);
      all += nol;
      const double hit = raySphere(X, L, C, ro);
      if (!(hit > 0.0 && hit < d)) seen += nol;
    }
  return seen / all;
}

struct Penumbra {
  double width_ref = 0.0, width_quad = 0.0;  // 10%..90% of the unshadowed value, m
  double max_diff = 0.0;                     // largest |fraction_ref - fraction_quad|
  size_t fully_lit_checked = 0, umbra_checked = 0;
};

// Distance between where `f` first reaches 0.1 and 0.9 going out from the center of the line
// (index c) towards +x, linearly interpolated between pixels (`x` their positions).
double width1090(const std::vector<double>& f, const std::vector<double>& x, size_t c) {
  auto cross = [&](double level) {
    for (size_t i = c + 1; i < f.size(); ++i)
      if (f[i] >= level)
        return x[i - 1] + (level - f[i - 1]) / (f[i] - f[i - 1]) * (x[i] - x[i - 1]);
    return x.back();
  };
  return cross(0.9) - cross(0.1);
}

// A sphere light of radius rl 4 m above the floor over an occluder of radius 0.4 m whose center
// is `height` above the floor, along the line z = 0 through the shadow's center (1 cm pixels).
Penumbra penumbra(float rl, float height) {
  const int w = 301;
  hv::Scene s = lineScene(w, 1.5f);
  const glm::vec3 C(0.0f, height, 0.0f), Lc(0.0f, 4.0f, 0.0f);
  const float ro = 0.4f;
  hv::addMeshObject(s, hv::makeSphere(ro, 128, 64), grey(), C);
  hv::Light l;
  l.type = hv::LightType::Sphere;
  l.position = Lc;
  l.radius = rl;
  l.intensity = 20.0f;
  l.range = 50.0f;
  s.lights.push_back(l);
  const hv::GBufferReadback gb = floorGBuffer(s, w, 1);
  const hv::ReferenceResult off = hv::renderReference(s, gb, options(1024, false));
  const hv::ReferenceResult on = hv::renderReference(s, gb, options(1024, true));
  // The tessellated occluder lies between the spheres of radius ro cos(delta) and ro, delta the
  // angular diagonal of a 128 x 64 UV sphere's quad (its triangles' planes are at least that far
  // from the center).
  const double delta = std::hypot(kPi / 64.0, 2.0 * kPi / 128.0), ro_in = ro * std::cos(delta);
  Penumbra p;
  std::vector<double> f_ref, f_quad, xs;
  for (int i = 0; i < w; ++i) {
    const glm::dvec3 X(pixelPosition(s, gb, size_t(i)));
    const glm::dvec3 to_l = glm::dvec3(Lc) - X, to_o = glm::dvec3(C) - X;
    const double theta = std::acos(glm::dot(to_l, to_o) / (glm::length(to_l) * glm::length(to_o)));
    const double a_l = std::asin(rl / glm::length(to_l));
    const float v_on = on[hv::ReferenceAov::DirectDiffuse].px[size_t(i)].x;
    const float v_off = off[hv::ReferenceAov::DirectDiffuse].px[size_t(i)].x;
    // Fully lit: the light's cone misses the (circumscribed) occluder's cone; every sample the
    // reference draws toward the light is unoccluded, so the pixel equals the one without
    // visibility bit for bit. Umbra: the light's cone inside the inscribed occluder's cone.
    if (theta >= a_l + std::asin(ro / glm::length(to_o))) {
      EXPECT_EQ(v_on, v_off) << "fully lit at x = " << X.x;
      ++p.fully_lit_checked;
    }
    if (std::asin(ro_in / glm::length(to_o)) >= a_l + theta) {
      EXPECT_EQ(v_on, 0.0f) << "umbra at x = " << X.x;
      ++p.umbra_checked;
    }
    f_ref.push_back(double(v_on) / double(v_off));
    f_quad.push_back(visibleFraction(X, glm::dvec3(Lc), rl, glm::dvec3(C), ro));
    xs.push_back(X.x);
    p.max_diff = std::max(p.max_diff, std::abs(f_ref.back() - f_quad.back()));
  }
  // The line's center pixel is at x = 0 (odd width): widths on the +x side.
  const size_t c = size_t(w / 2);
  p.width_ref = width1090(f_ref, xs, c);
  p.width_quad = width1090(f_quad, xs, c);
  return p;
}

// The 10%..90% penumbra width agrees with a quadrature over the light's cone within 1 cm (one
// pixel) and the visible fraction within 0.05 everywhere (1024 samples: its standard error is
// at most 0.016); the width grows with the light's radius and with the occluder's height.
TEST(ReferenceVisibility, SphereLightPenumbraGrowsWithRadiusAndHeight) {
  double width[2][2];
  const float radii[2] = {0.1f, 0.3f}, heights[2] = {0.8f, 1.6f};
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b) {
      const Penumbra p = penumbra(radii[a], heights[b]);
      SCOPED_TRACE("light radius " + std::to_string(radii[a]) + ", occluder height " +
                   std::to_string(heights[b]));
      EXPECT_NEAR(p.width_ref, p.width_quad, 0.01);
      EXPECT_LT(p.max_diff, 0.05);
      EXPECT_GT(p.fully_lit_checked, 100u);
      width[a][b] = p.width_ref;
      std::printf(
          "penumbra: light radius %.2f m, occluder center %.2f m: width %.4f m (quadrature "
          "%.4f), max |fraction diff| %.4f, umbra pixels %zu\n",
          radii[a], heights[b], p.width_ref, p.width_quad, p.max_diff, p.umbra_checked);
    }
  for (int b = 0; b < 2; ++b) EXPECT_GT(width[1][b], 1.5 * width[0][b]) << "with the radius";
  for (int a = 0; a < 2; ++a) EXPECT_GT(width[a][1], 1.5 * width[a][0]) << "with the height";
}

// ---- Environment visibility ----

// The floor beside a sphere of radius R resting on it, under a uniform environment of radiance
// L: ambient diffuse L albedo (1 - (R / D)^3) and ambient occlusion 1 - (R / D)^3, D the distance
// from the floor point to the sphere's center (the sphere covers pi (R / D)^3 of the floor's
// projected solid angle; no interreflection). The tessellated sphere lies between the spheres of
// radius R cos(delta) and R: the values lie between the two analytic ones, within 4 standard
// errors (4096 samples).
TEST(ReferenceVisibility, RestingSphereUnderUniformEnvironment) {
  const int w = 61;
  hv::Scene s = lineScene(w, 3.0f);
  const float R = 0.5f, L = 1.5f, albedo = 0.5f;
  hv::addMeshObject(s, hv::makeSphere(R, 256, 128), grey(), {0.0f, R, 0.0f});
  s.environment.kind = hv::EnvironmentKind::Uniform;
  s.environment.color = glm::vec3(L);
  const hv::GBufferReadback gb = floorGBuffer(s, w, 1);
  const hv::ReferenceResult r = hv::renderReference(s, gb, options(4096, true));
  const double delta = std::hypot(kPi / 128.0, 2.0 * kPi / 256.0);
  const double r_in = R * std::cos(delta);
  int checked = 0;
  double worst = 0.0;
  for (int i = 0; i < w; ++i) {
    const glm::vec3 X = pixelPosition(s, gb, size_t(i));
    const double D = std::sqrt(double(X.x) * X.x + double(X.z) * X.z + double(R) * R);
    const double blocked_out = std::pow(R / D, 3.0);                  // the sphere of radius R
    const double blocked_in = r_in * r_in * double(R) / (D * D * D);  // radius r_in, center at R
    const double ad = r[hv::ReferenceAov::AmbientDiffuse].px[size_t(i)].x;
    const double ad_se = r.stdError(hv::ReferenceAov::AmbientDiffuse).px[size_t(i)].x;
    const double lo = L * albedo * (1.0 - blocked_out), hi = L * albedo * (1.0 - blocked_in);
    EXPECT_GE(ad, lo - 4.0 * ad_se - 1e-6) << "x = " << X.x;
    EXPECT_LE(ad, hi + 4.0 * ad_se + 1e-6) << "x = " << X.x;
    EXPECT_LT(ad_se, 0.01 * L * albedo);
    const double ao = r.ao.px[size_t(i)].x, ao_se = r.ao_std_error.px[size_t(i)].x;
    EXPECT_GE(ao, 1.0 - blocked_out - 4.0 * ao_se - 1e-6) << "x = " << X.x;
    EXPECT_LE(ao, 1.0 - blocked_in + 4.0 * ao_se + 1e-6) << "x = " << X.x;
    worst = std::max(worst, std::abs(ad / (L * albedo * (1.0 - blocked_out)) - 1.0));
    ++checked;
  }
  EXPECT_EQ(checked, w);
  std::printf("resting sphere: worst |ambient diffuse / analytic - 1| = %.4f over %d pixels\n",
              worst, checked);
  // ao_distance: occluders beyond it do not count. Every ray from a floor point at horizontal
  // distance x meets the sphere, if at all, beyond D - R (0.039 m at x = 0.2 m): with a distance
  // of 0.01 m nothing occludes there.
  hv::ReferenceOptions near = options(256, true);
  near.ao_distance = 0.01f;
  const hv::ReferenceResult rn = hv::renderReference(s, gb, near);
  for (int i = 0; i < w; ++i) {
    const glm::vec3 X = pixelPosition(s, gb, size_t(i));
    if (std::abs(X.x) > 0.2f) {
      EXPECT_EQ(rn.ao.px[size_t(i)].x, 1.0f) << "x = " << X.x;
    }
  }
}

// ---- Rays and occluders ----

// Rays to an emitter stop at the sampled point on it: a ceiling just above a sphere light and a
// tube light (closer to them than the floor is) does not shadow the floor they light.
TEST(ReferenceVisibility, RaysStopAtTheEmitter) {
  hv::Scene s = floorScene({0.0f, 6.0f, 0.0f}, {0.0f, 0.0f, 0.0f});
  hv::Mesh ceiling = hv::makePlane(6.0f, 6.0f);
  hv::addMeshObject(s, std::move(ceiling), grey(), {0.0f, 2.45f, 0.0f});
  hv::Light sphere;
  sphere.type = hv::LightType::Sphere;
  sphere.position = {-0.5f, 2.0f, 0.0f};
  sphere.radius = 0.4f;
  sphere.intensity = 10.0f;
  s.lights.push_back(sphere);
  hv::Light tube = sphere;
  tube.type = hv::LightType::Tube;
  tube.position = {0.8f, 2.2f, 0.0f};
  tube.radius = 0.2f;
  tube.length = 1.0f;
  tube.axis = {0.0f, 0.0f, 1.0f};
  s.lights.push_back(tube);
  const hv::GBufferReadback gb = floorGBuffer(s, 24, 24);
  const hv::ReferenceResult off = hv::renderReference(s, gb, options(16, false));
  const hv::ReferenceResult on = hv::renderReference(s, gb, options(16, true));
  EXPECT_TRUE(bitEqual(on[hv::ReferenceAov::DirectDiffuse], off[hv::ReferenceAov::DirectDiffuse]));
  EXPECT_TRUE(
      bitEqual(on[hv::ReferenceAov::DirectSpecular], off[hv::ReferenceAov::DirectSpecular]));
}

// A 2 x 2 m square 1 m above the floor, 3 m under a point light: shadowed fraction of the floor
// pixels under its left half (x < 0) and its right half, for an occluder that is opaque and
// facing the light, opaque and facing away (single-sided: rays hit both faces), alpha-masked
// with the right half's texel cut out, and masked out everywhere by its base alpha.
struct Halves {
  double left = 0.0, right = 0.0, outside = 0.0;
};
// yaw_deg turns the square about +Y (by 90: its v axis, +Z, along world +X).
Halves squareShadow(const hv::Material& m, bool flip, const std::vector<hv::ImageData>& images,
                    float yaw_deg = 0.0f) {
  hv::Scene s = floorScene({0.0f, 6.0f, 0.0f}, {0.0f, 0.0f, 0.0f});
  s.images = images;
  hv::addMeshObject(s, hv::makePlane(2.0f, 2.0f), m, {0.0f, 1.0f, 0.0f});
  s.objects.back().transform =
      glm::rotate(s.objects.back().transform, glm::radians(yaw_deg), glm::vec3(0.0f, 1.0f, 0.0f));
  if (flip) {  // normal -Y: half a turn about +X
    s.objects.back().transform =
        glm::rotate(s.objects.back().transform, kPi, glm::vec3(1.0f, 0.0f, 0.0f));
  }
  hv::Light l;
  l.position = {0.0f, 4.0f, 0.0f};
  l.intensity = 20.0f;
  l.range = 50.0f;
  s.lights.push_back(l);
  const hv::GBufferReadback gb = floorGBuffer(s, 64, 64);
  const hv::ReferenceResult r = hv::renderReference(s, gb, options(1, true));
  // The square's shadow: |x|, |z| < 4/3 m. Pixels well inside each half, and well outside.
  Halves h;
  int n_left = 0, n_right = 0, n_out = 0;
  for (size_t i = 0; i < gb.model.size(); ++i) {
    const glm::vec3 X = pixelPosition(s, gb, i);
    const bool dark = r[hv::ReferenceAov::DirectDiffuse].px[i].x == 0.0f;
    if (std::abs(X.z) < 1.2f && X.x < -0.1f && X.x > -1.2f) h.left += dark, ++n_left;
    if (std::abs(X.z) < 1.2f && X.x > 0.1f && X.x < 1.2f) h.right += dark, ++n_right;
    if (std::max(std::abs(X.x), std::abs(X.z)) > 1.45f) h.outside += dark, ++n_out;
  }
  EXPECT_GT(n_left, 100);
  EXPECT_GT(n_out, 100);
  h.left /= n_left, h.right /= n_right, h.outside /= n_out;
  return h;
}

TEST(ReferenceVisibility, AlphaMaskedAndBackFacingOccluders) {
  const hv::Material opaque = grey();
  for (bool flip : {false, true}) {
    const Halves h = squareShadow(opaque, flip, {});
    EXPECT_EQ(h.left, 1.0) << (flip ? "facing away" : "facing the light");
    EXPECT_EQ(h.right, 1.0);
    EXPECT_EQ(h.outside, 0.0);
  }
  // The plane's u runs along +x: a 2 x 1 texture whose right texel has alpha 0 cuts out x > 0.
  hv::ImageData img;
  img.width = 2;
  img.height = 1;
  img.rgba = {255, 255, 255, 255, 255, 255, 255, 0};
  hv::Material masked = grey();
  masked.alpha_mode = hv::AlphaMode::Mask;
  masked.alpha_cutoff = 0.5f;
  masked.base_color_tex.image = 0;
  masked.base_color_tex.sampler.mag = hv::Filter::Nearest;
  masked.base_color_tex.sampler.wrap_s = masked.base_color_tex.sampler.wrap_t =
      hv::Wrap::ClampToEdge;
  const Halves m = squareShadow(masked, false, {img});
  EXPECT_EQ(m.left, 1.0);
  EXPECT_EQ(m.right, 0.0);
  // Bilinear: alpha crosses the cutoff at u = 0.5 (between the texel centers 0.25 and 0.75).
  masked.base_color_tex.sampler.mag = hv::Filter::Linear;
  const Halves b = squareShadow(masked, false, {img});
  EXPECT_EQ(b.left, 1.0);
  EXPECT_EQ(b.right, 0.0);
  // Rows: a 1 x 2 texture whose bottom row has alpha 0; row 0 is the top of the image and v = 0
  // (glTF), at the square's -Z edge, which the quarter turn puts at -X.
  hv::ImageData rows = img;
  rows.width = 1;
  rows.height = 2;
  masked.base_color_tex.sampler.mag = hv::Filter::Nearest;
  const Halves v = squareShadow(masked, false, {rows}, 90.0f);
  EXPECT_EQ(v.left, 1.0);
  EXPECT_EQ(v.right, 0.0);
  // Base alpha below the cutoff, no texture: nothing occludes. The same alpha as a blended
  // material occludes (the engine draws blended surfaces opaque).
  hv::Material faint = grey();
  faint.alpha_mode = hv::AlphaMode::Mask;
  faint.base_alpha = 0.3f;
  const Halves f = squareShadow(faint, false, {});
  EXPECT_EQ(f.left + f.right, 0.0);
  faint.alpha_mode = hv::AlphaMode::Blend;
  EXPECT_EQ(squareShadow(faint, false, {}).left, 1.0);
}

// glTF-Asset-Generator's Material_AlphaMask planes (a 1 x 1 quad in z = 0 whose UVs cover its
// base-color texture): the fraction of a 200 x 200 grid of rays through the quad that it stops
// is the fraction of texels whose alpha is at least the cutoff (within 0.02: bilinear filtering
// moves the cut between texels); cutoff 1.1 (model 03) stops none, cutoff 0 (model 04) all.
TEST(ReferenceVisibility, GltfAlphaMaskCutoffs) {
  const auto dir = hv::test::assetsDir() / "gltf-asset-generator/Positive/Material_AlphaMask";
  if (hv::test::assetsDir().empty() || !std::filesystem::exists(dir))
    GTEST_SKIP() << "shared assets not found (" << dir << ")";
  for (int model : {0, 1, 2, 3, 4}) {
    hv::Scene s;
    hv::loadGltf((dir / ("Material_AlphaMask_0" + std::to_string(model) + ".gltf")).string(),
                 glm::mat4(1.0f), s);
    ASSERT_EQ(s.materials.size(), 1u);
    const hv::Material& m = s.materials[0];
    ASSERT_EQ(m.alpha_mode, hv::AlphaMode::Mask);
    ASSERT_TRUE(m.base_color_tex.valid());
    const hv::ImageData& img = s.images[size_t(m.base_color_tex.image)];
    size_t opaque = 0;
    for (size_t i = 3; i < img.rgba.size(); i += 4)
      opaque += m.base_alpha * (float(img.rgba[i]) / 255.0f) >= m.alpha_cutoff;
    const double expected = double(opaque) / double(size_t(img.width) * size_t(img.height));
    const hv::reference_detail::SceneVisibility vis(s);
    EXPECT_EQ(vis.maskedTriangles(), 2u);
    const int n = 200;
    size_t stopped = 0;
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        const glm::vec3 o(-0.5f + (x + 0.5f) / n, -0.5f + (y + 0.5f) / n, 1.0f);
        stopped += vis.occluded(o, glm::vec3(0.0f, 0.0f, -1.0f));
      }
    const double fraction = double(stopped) / double(n * n);
    EXPECT_NEAR(fraction, expected, 0.02) << "model " << model << ", cutoff " << m.alpha_cutoff;
    if (model == 3) {
      EXPECT_EQ(stopped, 0u);
    }
    if (model == 4) {
      EXPECT_EQ(stopped, size_t(n * n));
    }
    std::printf(
        "Material_AlphaMask_0%d: cutoff %.2f, %.4f of the rays stopped, %.4f of the texels "
        "opaque\n",
        model, m.alpha_cutoff, fraction, expected);
  }
}

// SceneVisibility directly: a unit triangle's two faces, the segment's open end, and the counts.
TEST(ReferenceVisibility, SceneVisibilityQueries) {
  hv::Scene s;
  hv::Mesh m;
  for (glm::vec3 p : {glm::vec3(-1, 0, -1), glm::vec3(1, 0, -1), glm::vec3(0, 0, 1)}) {
    hv::Vertex v;
    v.position = p;
    m.vertices.push_back(v);
  }
  m.indices = {0, 1, 2, 0, 1, 7};  // the second triangle's index is out of range: skipped
  hv::addMeshObject(s, m, grey(), {0.0f, 2.0f, 0.0f});
  const hv::reference_detail::SceneVisibility vis(s);
  EXPECT_EQ(vis.triangles(), 1u);
  EXPECT_EQ(vis.maskedTriangles(), 0u);
  const glm::vec3 up(0, 1, 0);
  EXPECT_TRUE(vis.occluded({0, 0, 0}, up));
  EXPECT_TRUE(vis.occluded({0, 4, 0}, -up));  // the back face
  EXPECT_FALSE(vis.occluded({0, 0, 0}, up, 1.99f));
  EXPECT_TRUE(vis.occluded({0, 0, 0}, up, 2.01f));
  EXPECT_FALSE(vis.occluded({3, 0, 0}, up));
  EXPECT_FALSE(vis.occluded({0, 0, 0}, -up));
  const hv::reference_detail::SceneVisibility empty{hv::Scene{}};
  EXPECT_FALSE(empty.occluded({0, 0, 0}, up));
  EXPECT_EQ(empty.triangles(), 0u);
}

}  // namespace
