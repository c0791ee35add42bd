#include "halfvec/reference/emitters.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "halfvec/shading/shading.hpp"

namespace hv::reference_detail {

namespace {

constexpr float kPi = 3.14159265358979f;

uint64_t splitmix64(uint64_t x) {
  x += 0x9E3779B97F4A7C15ull;
  x = (x ^ (x >> 30u)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27u)) * 0x94D049BB133111EBull;
  return x ^ (x >> 31u);
}

// Karis 2013 eq. 9 window, the engine's own function (lights.glsl falloffWindow).
float window(float d2, float range) {
  return glsl::falloffWindow(d2, 1.0f / range);
}

// Radiance arriving from any visible point of a sphere or capsule light at a shading point whose
// window distance is d (sphere: to the center; tube: to the closest point of the segment), exactly
// as docs/lights.md ("What a Monte Carlo reference must integrate") defines it:
//   L_e * W_R(d) * (falloff_plus_one ? d^2 / (d^2 + 1) : 1),  d^2 clamped below at r^2 in the +1
// factor (inside the emitter = on its surface; the window takes the unclamped d, as the engine),
// with the Lambertian emitter radiance L_e = I / (pi r^2) (sphere) and I / (pi r^2 + pi r len / 2)
// (capsule: the same power 4 pi I as the sphere and the point light).
glm::vec3 emitterRadiance(const Light& light, const RenderSettings& settings, float d2) {
  const float r = std::max(light.radius, 0.0f);
  const float len = light.type == LightType::Tube ? std::max(light.length, 0.0f) : 0.0f;
  const float emitting = kPi * r * r + 0.5f * kPi * r * len;
  if (emitting <= 0.0f) return glm::vec3(0.0f);
  const float d2c = std::max(d2, r * r);
  const float plus_one = settings.falloff_plus_one ? d2c / (d2c + 1.0f) : 1.0f;
  return light.color * (light.intensity / emitting * window(d2, light.range) * plus_one);
}

// Distance along the unit L from P to the sphere (center P + Lc, |Lc|^2 = d2, radius^2 r2): the
// front hit from outside (a direction of the subtended cone; rounding just outside it gives the
// tangent point), the exit from inside.
float sphereDistance(const glm::vec3& Lc, float d2, float r2, const glm::vec3& L) {
  const float b = glm::dot(L, Lc);
  const float h = std::sqrt(std::max(b * b - (d2 - r2), 0.0f));
  return d2 <= r2 ? b + h : std::max(b - h, 0.0f);
}

LightSample sampleSphere(const Light& light, const RenderSettings& settings, const glm::vec3& P,
                         glm::vec2 u) {
  LightSample ls;
  const glm::vec3 Lc = light.position - P;
  const float d2 = glm::dot(Lc, Lc);
  const float r2 = light.radius * light.radius;
  if (r2 <= 0.0f) return ls;
  float cos_max, one_minus_cos;
  glm::vec3 axis;
  if (d2 <= r2) {  // inside: every direction sees the emitter
    cos_max = -1.0f;
    one_minus_cos = 2.0f;
    axis = glm::vec3(0.0f, 0.0f, 1.0f);
  } else {
    // 1 - cos = (r^2/d^2) / (1 + cos): no cancellation for tiny, far spheres.
    const float sin2 = r2 / d2;
    cos_max = std::sqrt(std::max(0.0f, 1.0f - sin2));
    one_minus_cos = sin2 / (1.0f + cos_max);
    axis = Lc / std::sqrt(d2);
  }
  const float cos_t = 1.0f - u.x * one_minus_cos;
  const float sin_t = std::sqrt(std::max(0.0f, 1.0f - cos_t * cos_t));
  const float phi = 2.0f * kPi * u.y;
  glm::vec3 T, B;
  glsl::tangentFrame(axis, T, B);
  ls.L = glm::normalize(T * (sin_t * std::cos(phi)) + B * (sin_t * std::sin(phi)) + axis * cos_t);
  ls.pdf = 1.0f / (2.0f * kPi * one_minus_cos);
  ls.radiance = emitterRadiance(light, settings, d2);
  ls.distance = sphereDistance(Lc, d2, r2, ls.L);
  return ls;
}

// A directional light's disk (docs/lights.md, "Directional lights"): the cone of half-angle
// sigma around the unit direction toward it, of uniform radiance L_e = E / (pi sin^2 sigma), so
// that the irradiance at normal incidence, pi L_e sin^2 sigma, is E. 1 - cos sigma from
// sin^2 sigma / (1 + cos sigma): no cancellation for the sun's 4.65 mrad.
struct DirectionalCone {
  glm::vec3 axis{0.0f};
  float cos_max = 1.0f, one_minus_cos = 0.0f, sin2 = 0.0f;
  // The solid-angle pdf of a uniform sample of the cone at L: 0 outside it (and for a single
  // direction, which is not sampled).
  float uniformPdf() const { return 1.0f / (2.0f * kPi * one_minus_cos); }
  float pdf(const glm::vec3& L) const {
    return sin2 <= 0.0f || glm::dot(L, axis) < cos_max ? 0.0f : uniformPdf();
  }
};
DirectionalCone directionalCone(const Light& light) {
  DirectionalCone c;
  c.axis = -glm::normalize(light.direction);
  const float half = 0.5f * std::clamp(light.angular_diameter, 0.0f, kMaxAngularDiameter);
  const float sn = std::sin(half);
  c.sin2 = sn * sn;
  c.cos_max = std::cos(half);
  c.one_minus_cos = c.sin2 / (1.0f + c.cos_max);
  return c;
}
glm::vec3 directionalRadiance(const Light& light, const DirectionalCone& c) {
  return c.sin2 > 0.0f ? light.color * (light.intensity / (kPi * c.sin2)) : glm::vec3(0.0f);
}

LightSample sampleDirectional(const Light& light, glm::vec2 u) {
  LightSample ls;
  const DirectionalCone c = directionalCone(light);
  if (c.sin2 <= 0.0f) return ls;  // a single direction: exact, not sampled (pixel.cpp)
  const float cos_t = 1.0f - u.x * c.one_minus_cos;
  const float sin_t = std::sqrt(std::max(0.0f, 1.0f - cos_t * cos_t));
  const float phi = 2.0f * kPi * u.y;
  glm::vec3 T, B;
  glsl::tangentFrame(c.axis, T, B);
  ls.L = glm::normalize(T * (sin_t * std::cos(phi)) + B * (sin_t * std::sin(phi)) + c.axis * cos_t);
  ls.pdf = c.uniformPdf();
  ls.radiance = directionalRadiance(light, c);
  ls.distance = std::numeric_limits<float>::infinity();
  return ls;
}

// Inside a capsule light (the closest point of its segment within its radius) every direction
// sees the emitter, as inside a sphere: the shading point is taken as on its surface (L_e at
// the window distance; docs/lights.md). The engine's `ltc` modes shade it so
// (ltcCapsuleIntegral); before, a ray from inside met only back faces and the point was dark.
bool insideCapsule(const Light& light, const glm::vec3& P) {
  return light.radius > 0.0f && windowDistance2(light, P) <= light.radius * light.radius;
}

// Where the ray P + t L (L unit) from inside the capsule leaves it: the capsule is convex and
// the distance from the ray's point to the segment convex in t, so the exit is the one root of
// distance = r beyond P, found by bisection in double (for visibility rays, whose occluders
// inside the light count).
float capsuleExitDistance(const Light& light, const glm::vec3& P, const glm::vec3& L) {
  const double len = std::max(light.length, 0.0f), r = light.radius;
  const glm::dvec3 axis = glm::normalize(glm::dvec3(light.axis));
  const glm::dvec3 pa = glm::dvec3(light.position) - axis * (0.5 * len);
  auto dist = [&](double t) {
    const glm::dvec3 x = glm::dvec3(P) + glm::dvec3(L) * t;
    const double s = std::clamp(glm::dot(x - pa, axis), 0.0, len);
    return glm::length(x - (pa + axis * s));
  };
  double lo = 0.0, hi = len + 2.0 * r;  // the capsule's diameter bounds the chord
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    (dist(mid) <= r ? lo : hi) = mid;
  }
  return float(lo);
}

// A uniform direction of the whole sphere (inside an emitter), pdf 1 / (4 pi).
glm::vec3 uniformSphereDirection(glm::vec2 u) {
  const float z = 1.0f - 2.0f * u.x;
  const float s = std::sqrt(std::max(0.0f, 1.0f - z * z));
  const float phi = 2.0f * kPi * u.y;
  return {s * std::cos(phi), s * std::sin(phi), z};
}

LightSample sampleTube(const Light& light, const RenderSettings& settings, const glm::vec3& P,
                       glm::vec2 u) {
  LightSample ls;
  const float r = light.radius;
  const float len = std::max(light.length, 0.0f);
  if (r <= 0.0f) return ls;
  if (insideCapsule(light, P)) {
    ls.L = uniformSphereDirection(u);
    ls.pdf = 1.0f / (4.0f * kPi);
    ls.radiance = emitterRadiance(light, settings, windowDistance2(light, P));
    ls.distance = capsuleExitDistance(light, P, ls.L);
    return ls;
  }
  const glm::vec3 axis = glm::normalize(light.axis);
  const float a_cyl = 2.0f * kPi * r * len;
  const float a_caps = 4.0f * kPi * r * r;
  const float area = a_cyl + a_caps;
  const float p_cyl = a_cyl / area;
  glm::vec3 x, n;
  if (u.x < p_cyl) {  // cylinder side: t uniform along the axis, phi uniform
    const float t = u.x / p_cyl;
    const float phi = 2.0f * kPi * u.y;
    glm::vec3 T, B;
    glsl::tangentFrame(axis, T, B);
    n = T * std::cos(phi) + B * std::sin(phi);
    x = light.position + axis * ((t - 0.5f) * len) + r * n;
  } else {  // the two hemispherical caps form one sphere: uniform direction, cap by side
    const float v = std::min((u.x - p_cyl) / (1.0f - p_cyl), 1.0f);
    const float z = 1.0f - 2.0f * v;
    const float s = std::sqrt(std::max(0.0f, 1.0f - z * z));
    const float phi = 2.0f * kPi * u.y;
    n = glm::vec3(s * std::cos(phi), s * std::sin(phi), z);
    const float side = glm::dot(n, axis) >= 0.0f ? 0.5f : -0.5f;
    x = light.position + axis * (side * len) + r * n;
  }
  const glm::vec3 d = x - P;
  const float dist2 = glm::dot(d, d);
  if (dist2 <= 0.0f) return ls;
  ls.distance = std::sqrt(dist2);
  ls.L = d / ls.distance;
  const float cos_e = -glm::dot(n, ls.L);
  if (cos_e <= 0.0f) return ls;  // back face: hidden behind the capsule's front
  ls.pdf = dist2 / (area * cos_e);
  // Falloff distance: closest point of the segment to P (as the engine's window).
  const glm::vec3 L0 = light.position - axis * (0.5f * len) - P;
  const float tp = len > 0.0f ? glsl::saturate(-glm::dot(L0, axis) / len) : 0.0f;
  const glm::vec3 Lp = L0 + axis * (tp * len);
  ls.radiance = emitterRadiance(light, settings, glm::dot(Lp, Lp));
  return ls;
}

// Nearest t > 0 where the ray P + t L (L unit) enters the sphere (center c, radius r), or -1.
// Double precision: near-tangent rays lose half the digits in b^2 - c.
double raySphere(const glm::dvec3& P, const glm::dvec3& L, const glm::dvec3& c, double r) {
  const glm::dvec3 oc = P - c;
  const double b = glm::dot(L, oc);
  const double h = b * b - (glm::dot(oc, oc) - r * r);
  if (h < 0.0) return -1.0;
  const double t = -b - std::sqrt(h);
  return t > 0.0 ? t : -1.0;
}

float capsulePdf(const Light& light, const glm::vec3& Pf, const glm::vec3& Lf) {
  const double r = light.radius;
  const double len = std::max(light.length, 0.0f);
  if (r <= 0.0) return 0.0f;
  if (insideCapsule(light, Pf)) return 1.0f / (4.0f * kPi);  // sampleTube's uniform directions
  const glm::dvec3 P(Pf), L(glm::normalize(glm::dvec3(Lf)));
  const glm::dvec3 axis = glm::normalize(glm::dvec3(light.axis));
  const glm::dvec3 A = glm::dvec3(light.position) - axis * (0.5 * len);
  const glm::dvec3 Bp = glm::dvec3(light.position) + axis * (0.5 * len);
  // The capsule is the union of the two end spheres and the finite cylinder between them; the
  // first hit of a ray from outside is the smallest first hit over the three (a hit on a
  // cylinder end disk lies inside an end sphere, so only the curved side is needed).
  double t = -1.0;
  for (const glm::dvec3& c : {A, Bp}) {
    const double ts = raySphere(P, L, c, r);
    if (ts > 0.0 && (t < 0.0 || ts < t)) t = ts;
  }
  if (len > 0.0) {
    const glm::dvec3 oa = P - A;
    const double bard = glm::dot(axis, L), baoa = glm::dot(axis, oa);
    const double a = 1.0 - bard * bard;
    if (a > 1e-12) {  // not parallel to the axis: the infinite cylinder |x - axis line| = r
      const double b = glm::dot(L, oa) - baoa * bard;
      const double c = glm::dot(oa, oa) - baoa * baoa - r * r;
      const double h = b * b - a * c;
      if (h >= 0.0) {
        const double tc = (-b - std::sqrt(h)) / a;
        const double y = baoa + tc * bard;
        if (tc > 0.0 && y > 0.0 && y < len && (t < 0.0 || tc < t)) t = tc;
      }
    }
  }
  if (t <= 0.0) return 0.0f;
  const glm::dvec3 x = P + L * t;
  const double y = std::clamp(glm::dot(x - A, axis), 0.0, len);
  const glm::dvec3 n = glm::normalize(x - (A + axis * y));
  const double cos_e = -glm::dot(n, L);
  if (cos_e <= 0.0) return 0.0f;
  const double area = 2.0 * double(kPi) * r * len + 4.0 * double(kPi) * r * r;
  return float(t * t / (area * cos_e));
}

}  // namespace

glm::vec3 emitterRadianceAt(const Light& light, const RenderSettings& settings,
                            const glm::vec3& P) {
  if (light.type == LightType::Directional)
    return directionalRadiance(light, directionalCone(light));
  if (light.type == LightType::Sphere) {
    const glm::vec3 Lc = light.position - P;
    return emitterRadiance(light, settings, glm::dot(Lc, Lc));
  }
  if (light.type == LightType::Tube) {
    const float len = std::max(light.length, 0.0f);
    const glm::vec3 axis = glm::normalize(light.axis);
    const glm::vec3 L0 = light.position - axis * (0.5f * len) - P;
    const float tp = len > 0.0f ? glsl::saturate(-glm::dot(L0, axis) / len) : 0.0f;
    const glm::vec3 Lp = L0 + axis * (tp * len);
    return emitterRadiance(light, settings, glm::dot(Lp, Lp));
  }
  return glm::vec3(0.0f);
}

float lightPdf(const Light& light, const glm::vec3& P, const glm::vec3& L) {
  if (light.type == LightType::Directional) return directionalCone(light).pdf(L);
  if (light.type == LightType::Sphere) {
    const glm::vec3 Lc = light.position - P;
    const float d2 = glm::dot(Lc, Lc);
    const float r2 = light.radius * light.radius;
    if (r2 <= 0.0f) return 0.0f;
    if (d2 <= r2) return 1.0f / (4.0f * kPi);
    const float sin2 = r2 / d2;
    const float cos_max = std::sqrt(std::max(0.0f, 1.0f - sin2));
    if (glm::dot(L, Lc) < cos_max * std::sqrt(d2)) return 0.0f;  // outside the cone
    return 1.0f / (2.0f * kPi * (sin2 / (1.0f + cos_max)));
  }
  if (light.type == LightType::Tube) return capsulePdf(light, P, L);
  return 0.0f;
}

Rng::Rng(uint64_t seed, uint64_t stream) {
  inc_ = (splitmix64(stream ^ 0xDA3E39CB94B95BDBull) << 1u) | 1u;
  state_ = 0;
  next();
  state_ += splitmix64(seed);
  next();
}

uint32_t Rng::next() {
  const uint64_t old = state_;
  state_ = old * 6364136223846793005ull + inc_;
  const auto xorshifted = uint32_t(((old >> 18u) ^ old) >> 27u);
  const auto rot = uint32_t(old >> 59u);
  return (xorshifted >> rot) | (xorshifted << ((32u - rot) & 31u));
}

float windowDistance2(const Light& light, const glm::vec3& P) {
  if (light.type == LightType::Directional) return 0.0f;  // no range: never beyond it
  if (light.type != LightType::Tube) {
    const glm::vec3 d = light.position - P;
    return glm::dot(d, d);
  }
  const float len = std::max(light.length, 0.0f);
  const glm::vec3 axis = glm::normalize(light.axis);
  const glm::vec3 L0 = light.position - axis * (0.5f * len) - P;
  const float tp = len > 0.0f ? glsl::saturate(-glm::dot(L0, axis) / len) : 0.0f;
  const glm::vec3 Lp = L0 + axis * (tp * len);
  return glm::dot(Lp, Lp);
}

LightSample evalLight(const Light& light, const RenderSettings& settings, const glm::vec3& P,
                      const glm::vec3& L) {
  LightSample ls;
  ls.L = L;
  if (light.type == LightType::Directional) {
    // L sees the disk iff it lies in the cone sampleDirectional draws from.
    const DirectionalCone c = directionalCone(light);
    ls.pdf = c.pdf(L);
    if (ls.pdf <= 0.0f) return ls;
    ls.radiance = directionalRadiance(light, c);
    ls.distance = std::numeric_limits<float>::infinity();
    return ls;
  }
  const float r = light.radius;
  if (r <= 0.0f) return ls;
  if (light.type == LightType::Sphere) {
    const glm::vec3 Lc = light.position - P;
    const float d2 = glm::dot(Lc, Lc), r2 = r * r;
    if (d2 <= r2) {
      ls.pdf = 1.0f / (4.0f * kPi);
    } else {  // L sees the sphere iff it lies in the cone sampleSphere draws from
      const float sin2 = r2 / d2;
      const float cos_max = std::sqrt(std::max(0.0f, 1.0f - sin2));
      if (glm::dot(L, Lc) < cos_max * std::sqrt(d2)) return ls;
      ls.pdf = 1.0f / (2.0f * kPi * (sin2 / (1.0f + cos_max)));
    }
    ls.radiance = emitterRadiance(light, settings, d2);
    ls.distance = sphereDistance(Lc, d2, r2, L);
    return ls;
  }
  if (light.type != LightType::Tube) return ls;
  if (insideCapsule(light, P)) {  // every direction (sampleTube)
    ls.pdf = 1.0f / (4.0f * kPi);
    ls.radiance = emitterRadiance(light, settings, windowDistance2(light, P));
    ls.distance = capsuleExitDistance(light, P, L);
    return ls;
  }
  // Front hit of the ray P + t L on the capsule (segment pa-pb, radius r): the cylinder's body,
  // else the cap sphere on the side the infinite cylinder's hit falls (Quilez's capsule test), in
  // double: the quadratic cancels badly near the silhouette, where cos_e is small.
  const double len = std::max(light.length, 0.0f), rr = double(r) * r;
  const glm::dvec3 axis = glm::normalize(glm::dvec3(light.axis)), Pd(P), Ld(L);
  const glm::dvec3 pa = glm::dvec3(light.position) - axis * (0.5 * len), pb = pa + axis * len;
  auto sphereHit = [&](const glm::dvec3& c) {
    const glm::dvec3 oc = Pd - c;
    const double b = glm::dot(Ld, oc), cc = glm::dot(oc, oc) - rr, h = b * b - cc;
    return h > 0.0 ? -b - std::sqrt(h) : -1.0;
  };
  double t = -1.0;
  const glm::dvec3 ba = pb - pa, oa = Pd - pa;
  const double baba = glm::dot(ba, ba), bard = glm::dot(ba, Ld), baoa = glm::dot(ba, oa);
  const double a = baba - bard * bard;
  if (baba <= 1e-18) {
    t = sphereHit(glm::dvec3(light.position));
  } else if (a > 1e-12 * baba) {
    const double b = baba * glm::dot(Ld, oa) - baoa * bard;
    const double c = baba * glm::dot(oa, oa) - baoa * baoa - rr * baba;
    const double h = b * b - a * c;
    if (h >= 0.0) {
      t = (-b - std::sqrt(h)) / a;
      const double y = baoa + t * bard;
      if (!(y > 0.0 && y < baba)) t = sphereHit(y <= 0.0 ? pa : pb);
    }
  } else {  // ray parallel to the axis: the nearer cap
    t = sphereHit(bard > 0.0 ? pa : pb);
  }
  if (!(t > 0.0)) return ls;
  const glm::dvec3 x = Pd + t * Ld;
  const double sx = std::clamp(glm::dot(x - pa, axis) / std::max(len, 1e-12), 0.0, 1.0);
  const glm::dvec3 n = glm::normalize(x - (pa + axis * (sx * len)));
  const float cos_e = float(-glm::dot(n, Ld));
  if (cos_e <= 0.0f) return ls;
  const float lenf = float(len);
  const float area = 2.0f * kPi * r * lenf + 4.0f * kPi * r * r;
  ls.pdf = float(t * t) / (area * cos_e);
  ls.distance = float(t);
  ls.radiance = emitterRadiance(light, settings, windowDistance2(light, P));
  return ls;
}

float falloff(const RenderSettings& settings, float d2, float radius, float range) {
  const float d2c = std::max(d2, std::max(radius * radius, glsl::HV_MIN_LIGHT_DIST2));
  return window(d2, range) / (d2c + (settings.falloff_plus_one ? 1.0f : 0.0f));
}

LightSample sampleLight(const Light& light, const RenderSettings& settings, const glm::vec3& P,
                        glm::vec2 u) {
  switch (light.type) {
    case LightType::Sphere:
      return sampleSphere(light, settings, P, u);
    case LightType::Tube:
      return sampleTube(light, settings, P, u);
    case LightType::Directional:
      return sampleDirectional(light, u);
    case LightType::Point:
    case LightType::Spot:  // the reference samples a spot as its shape (reference.cpp)
      break;
  }
  return {};
}

}  // namespace hv::reference_detail
