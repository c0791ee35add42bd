#include "halfvec/eval/shadow_accuracy.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "halfvec/eval/engine_aov.hpp"
#include "halfvec/reference/reference.hpp"
#include "halfvec/render/renderer.hpp"
#include "halfvec/scene/primitives.hpp"

namespace hv::eval {

namespace {

constexpr float kFloorAlbedo = 1.0f, kOccluderAlbedo = 0.3f;
// Umbra: below this fraction of the unshadowed value; penumbra: between it and 1 - it.
constexpr double kUmbra = 0.02;
// The profile's half-angle about +x, degrees: wide enough for tens of pixels per bin, narrow
// enough that a capsule's penumbra (which varies with the direction) is the one along +x.
constexpr float kSectorDeg = 25.0f;

// Outer edge of the penumbra on the floor (similar triangles through the occluder's silhouette,
// the light's half-extent along +x): the frame covers it with a margin of lit floor.
float outerPenumbra(const ShadowCase& c) {
  const float H = kShadowLightHeight, h = c.occluder_height, a = kShadowOccluderRadius;
  const float ext = c.light_radius + 0.5f * c.light_length * std::abs(c.axis.x);
  if (c.light_offset <= 0.0f) return (a * H + ext * h) / (H - h);
  // A light off to -x: the line from the emitter's far end (x = -offset - ext) over the top of
  // the occluder, tangent to it, meets the floor at the shadow's far tip.
  const glm::vec2 L(-c.light_offset - ext, H), C(0.0f, h);
  const glm::vec2 v = C - L;
  const float beta = std::asin(std::min(a / glm::length(v), 1.0f));
  const float angle = std::atan2(v.y, v.x) + beta;     // rotated up: above the occluder
  const float dy = std::min(std::sin(angle), -0.05f);  // a grazing line: a long, finite frame
  return L.x - H * std::cos(angle) / dy;
}

glm::vec3 floorPoint(const glm::mat4& inv_view_proj, int w, int h, int x, int y) {
  const glm::vec2 ndc(2.0f * (float(x) + 0.5f) / float(w) - 1.0f,
                      1.0f - 2.0f * (float(y) + 0.5f) / float(h));
  const glm::vec4 a = inv_view_proj * glm::vec4(ndc, 1.0f, 1.0f);  // reversed Z: near plane
  const glm::vec4 b = inv_view_proj * glm::vec4(ndc, 0.5f, 1.0f);
  const glm::vec3 p0 = glm::vec3(a) / a.w, p1 = glm::vec3(b) / b.w;
  const float t = -p0.y / (p1.y - p0.y);
  return p0 + t * (p1 - p0);
}

float sum3(const glm::vec3& v) {
  return v.x + v.y + v.z;
}

ShadowProfile makeProfile(const std::vector<glm::vec3>& floor, const std::vector<bool>& use,
                          const ImageRGBf& shadowed, const ImageRGBf& unlit, float bin,
                          float rho_max) {
  ShadowProfile p;
  const size_t bins = size_t(std::ceil(rho_max / bin)) + 1;
  p.shadowed.assign(bins, 0.0);
  p.unlit.assign(bins, 0.0);
  p.pixels.assign(bins, 0);
  const float tan_sector = std::tan(glm::radians(kSectorDeg));
  for (size_t i = 0; i < floor.size(); ++i) {
    const glm::vec3 q = floor[i];
    if (!use[i] || q.x <= 0.0f || std::abs(q.z) > tan_sector * q.x) continue;
    const size_t k = size_t(std::sqrt(q.x * q.x + q.z * q.z) / bin);
    if (k >= bins) continue;
    p.shadowed[k] += sum3(shadowed.px[i]);
    p.unlit[k] += sum3(unlit.px[i]);
    ++p.pixels[k];
  }
  for (size_t k = 0; k < bins; ++k) {
    p.rho.push_back((float(k) + 0.5f) * bin);
    if (p.pixels[k] == 0) continue;
    p.shadowed[k] /= double(p.pixels[k]);
    p.unlit[k] /= double(p.pixels[k]);
  }
  return p;
}

}  // namespace

Scene shadowCaseScene(const ShadowCase& c, ShadowFilter filter, int map_size) {
  Scene s;
  float S = 1.35f * outerPenumbra(c) + 0.1f;  // the frame's side on the floor
  // With the light off to the side the camera stays above the occluder (a resting occluder
  // reaches 2 a; the frame's camera is at height S / 2).
  if (c.light_offset > 0.0f)
    S = std::max(S, 2.0f * (c.occluder_height + kShadowOccluderRadius) + 0.4f);
  // Straight down from S/2 over x = S/2 with a 90-degree field: the floor from x = 0 to S, the
  // occluder projected away from the measured +x half (or behind the camera).
  s.camera.position = {0.5f * S, 0.5f * S, 0.0f};
  s.camera.target = {0.5f * S, 0.0f, 0.0f};
  s.camera.up = {0.0f, 0.0f, -1.0f};
  s.camera.fov_y_deg = 90.0f;
  Material floor;
  floor.base_color = glm::vec3(kFloorAlbedo);
  floor.roughness = 1.0f;
  addMeshObject(s, makePlane(40.0f, 40.0f), floor, glm::vec3(0.0f));
  Material occluder = floor;
  occluder.base_color = glm::vec3(kOccluderAlbedo);
  addMeshObject(s, makeSphere(kShadowOccluderRadius), occluder, {0.0f, c.occluder_height, 0.0f});
  Light l;
  l.type = c.light_radius <= 0.0f  ? LightType::Point
           : c.light_length > 0.0f ? LightType::Tube
                                   : LightType::Sphere;
  l.position = {-c.light_offset, kShadowLightHeight, 0.0f};
  l.radius = c.light_radius;
  l.length = c.light_length;
  l.axis = glm::normalize(c.axis);
  l.intensity = 10.0f;
  l.range = 30.0f;
  l.shadows = true;
  s.lights.push_back(l);
  s.environment.kind = EnvironmentKind::None;
  s.settings.falloff_plus_one = false;
  // The most accurate diffuse methods (docs/accuracy.md), so that what differs is the shadow.
  s.settings.sphere_diffuse = SphereDiffuse::HorizonCorrect;
  s.settings.tube_diffuse = TubeDiffuse::Ltc;
  s.settings.shadow_filter = filter;
  s.settings.shadow_map_size = map_size;
  return s;
}

double penumbraWidth(const ShadowProfile& p) {
  auto ratio = [&](size_t k) { return p.unlit[k] > 0.0 ? p.shadowed[k] / p.unlit[k] : -1.0; };
  // Interpolated distance where the ratio passes `level` between bins a and b.
  auto cross = [&](size_t a, size_t b, double level) {
    const double ra = ratio(a), rb = ratio(b);
    const double t = rb != ra ? (level - ra) / (rb - ra) : 0.0;
    return double(p.rho[a]) + t * (double(p.rho[b]) - double(p.rho[a]));
  };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  size_t prev = p.rho.size();  // the last bin with pixels before k
  for (size_t k = 0; k < p.rho.size(); ++k) {
    if (p.pixels[k] == 0) continue;
    if (ratio(k) >= 0.9) {
      if (prev == p.rho.size()) return nan;  // lit from the first bin seen
      const double r90 = cross(prev, k, 0.9);
      // Inward from k: the first bin at or below 10%, and the bin outside it.
      size_t outer = k;
      for (size_t j = k; j-- > 0;) {
        if (p.pixels[j] == 0) continue;
        if (ratio(j) <= 0.1) return r90 - cross(j, outer, 0.1);
        outer = j;
      }
      return nan;
    }
    prev = k;
  }
  return nan;
}

namespace {

// The reference's direct diffuse with and without visibility, from the same G-buffer and seed:
// the unshadowed value shares the samples' noise.
struct ReferenceDiffuse {
  GBufferReadback g;
  ImageRGBf shadowed, unshadowed, shadowed_se;
};

ReferenceDiffuse referenceDiffuse(const Scene& scene, const ShadowCase& c,
                                  const ShadowCaseOptions& o) {
  ReferenceDiffuse d;
  {
    render::Renderer r;
    r.setScene(scene);
    r.render(o.size, o.size);
    d.g = r.readGBuffer();
  }
  ReferenceOptions ro;
  // A capsule's reference converges slower (its samples spread along the segment): 4x.
  ro.samples = c.light_length > 0.0f ? 4 * o.samples : o.samples;
  ro.threads = o.threads;
  ro.visibility = true;
  const ReferenceResult on = renderReference(scene, d.g, ro);
  ro.visibility = false;
  const ReferenceResult off = renderReference(scene, d.g, ro);
  d.shadowed = on[ReferenceAov::DirectDiffuse];
  d.unshadowed = off[ReferenceAov::DirectDiffuse];
  d.shadowed_se = on.stdError(ReferenceAov::DirectDiffuse);
  return d;
}

// Each pixel's point on the floor plane, and whether it is measured: the floor (not the
// occluder, told apart by its albedo), lit when nothing shadows it.
struct FloorPixels {
  std::vector<glm::vec3> point;
  std::vector<bool> use;
};

FloorPixels floorPixels(const Scene& scene, const ReferenceDiffuse& ref, int n) {
  const glm::mat4 inv = referenceInvViewProj(scene.camera, n, n);
  FloorPixels fp;
  fp.point.resize(size_t(n) * size_t(n));
  fp.use.resize(fp.point.size());
  for (int y = 0; y < n; ++y) {
    for (int x = 0; x < n; ++x) {
      const size_t i = size_t(y) * size_t(n) + size_t(x);
      fp.point[i] = floorPoint(inv, n, n, x, y);
      fp.use[i] = isLit(ShadingModel(ref.g.model[i])) &&
                  ref.g.base_color[i].x > 0.5f * (kFloorAlbedo + kOccluderAlbedo) &&
                  sum3(ref.unshadowed.px[i]) > 0.0f;
    }
  }
  return fp;
}

ImageRGBf engineDiffuse(const Scene& scene, int n) {
  render::Renderer r;
  r.setScene(scene);
  return renderEngineAovs(r, n, n)[size_t(ReferenceAov::DirectDiffuse)];
}

// sum |E - R| / sum R over the measured floor pixels.
double meanRelError(const ImageRGBf& e, const ImageRGBf& ref, const std::vector<bool>& use) {
  double abs_sum = 0.0, ref_sum = 0.0;
  for (size_t i = 0; i < use.size(); ++i) {
    if (!use[i]) continue;
    abs_sum += std::abs(double(sum3(e.px[i])) - sum3(ref.px[i]));
    ref_sum += sum3(ref.px[i]);
  }
  return ref_sum > 0.0 ? abs_sum / ref_sum : 0.0;
}

// A shadowed frame's sums over the pixels that are lit or in a penumbra (by the engine's ratio
// to its own unshadowed frame or by the reference's); the umbra of both is left out.
struct ShadowSums {
  double abs = 0.0, ref = 0.0, pen_abs = 0.0, pen_ref = 0.0, se = 0.0;
  size_t pixels = 0, pen_pixels = 0;
};

ShadowSums shadowSums(const ImageRGBf& E, const ImageRGBf& EU, const ReferenceDiffuse& ref,
                      const std::vector<bool>& use) {
  ShadowSums s;
  for (size_t i = 0; i < use.size(); ++i) {
    if (!use[i]) continue;
    const double e = sum3(E.px[i]), rv = sum3(ref.shadowed.px[i]), u = sum3(ref.unshadowed.px[i]);
    const double re = e / std::max(double(sum3(EU.px[i])), 1e-30), rr = rv / u;
    if (std::max(re, rr) < kUmbra) continue;
    ++s.pixels;
    s.abs += std::abs(e - rv);
    s.ref += rv;
    s.se += sum3(ref.shadowed_se.px[i]);
    const bool pen = (re > kUmbra && re < 1.0 - kUmbra) || (rr > kUmbra && rr < 1.0 - kUmbra);
    if (!pen) continue;
    ++s.pen_pixels;
    s.pen_abs += std::abs(e - rv);
    s.pen_ref += rv;
  }
  return s;
}

// Per bin: the engine's shadowed mean against the reference's (the engine's unshadowed profile
// is its denominator in fe.profile; the error is of the shadowed values).
void worstBin(ShadowFilterError& fe, const ShadowProfile& rp) {
  for (size_t k = 0; k < rp.rho.size(); ++k) {
    if (rp.pixels[k] == 0 || rp.shadowed[k] < 0.1 * rp.unlit[k]) continue;
    const double err = std::abs(fe.profile.shadowed[k] - rp.shadowed[k]) / rp.shadowed[k];
    if (err > fe.worst_rel) {
      fe.worst_rel = err;
      fe.worst_rho = rp.rho[k];
    }
  }
}

}  // namespace

ShadowCaseResult measureShadowCase(const ShadowCase& c, const ShadowCaseOptions& o) {
  ShadowCaseResult res;
  res.c = c;
  const int n = o.size;
  Scene scene = shadowCaseScene(c, ShadowFilter::Pcss, o.map_size);
  const ReferenceDiffuse ref = referenceDiffuse(scene, c, o);
  const FloorPixels floor = floorPixels(scene, ref, n);
  // A pixel's footprint: the floor straight under the camera, 90-degree field.
  const float S = 2.0f * scene.camera.position.y;
  res.pixel_metres = double(S) / double(n);
  const float bin = float(res.pixel_metres), rho_max = 1.2f * S;
  res.reference_profile =
      makeProfile(floor.point, floor.use, ref.shadowed, ref.unshadowed, bin, rho_max);
  res.reference_width = penumbraWidth(res.reference_profile);

  // The engine without shadows: the shading's own error, and the shadowed frames' denominator.
  Scene unshadowed = scene;
  unshadowed.lights[0].shadows = false;
  const ImageRGBf EU = engineDiffuse(unshadowed, n);
  res.unshadowed_mean_rel = meanRelError(EU, ref.unshadowed, floor.use);

  struct Config {
    ShadowFilter filter;
    ShadowResolution resolution;
    ShadowQuality quality;
  };
  const Config configs[] = {{ShadowFilter::Hard, ShadowResolution::Full, ShadowQuality::Medium},
                            {ShadowFilter::Pcf, ShadowResolution::Full, ShadowQuality::Medium},
                            {ShadowFilter::Pcss, ShadowResolution::Full, ShadowQuality::Medium},
                            {ShadowFilter::Pcss, ShadowResolution::Full, ShadowQuality::High},
                            {ShadowFilter::Pcss, ShadowResolution::Half, ShadowQuality::Medium}};
  for (const auto& [f, resolution, quality] : configs) {
    scene.settings.shadow_filter = f;
    scene.settings.shadow_resolution = resolution;
    scene.settings.shadow_quality = quality;
    const ImageRGBf E = engineDiffuse(scene, n);
    const ShadowSums s = shadowSums(E, EU, ref, floor.use);
    ShadowFilterError fe;
    fe.filter = f;
    fe.resolution = resolution;
    fe.quality = quality;
    fe.mean_rel = s.ref > 0.0 ? s.abs / s.ref : 0.0;
    fe.penumbra_mean_rel = s.pen_ref > 0.0 ? s.pen_abs / s.pen_ref : 0.0;
    if (f == ShadowFilter::Pcss && resolution == ShadowResolution::Full &&
        quality == ShadowQuality::Medium) {
      res.pixels = s.pixels;
      res.penumbra_pixels = s.pen_pixels;
      res.reference_noise = s.ref > 0.0 ? s.se / s.ref : 0.0;
    }
    fe.profile = makeProfile(floor.point, floor.use, E, EU, bin, rho_max);
    fe.width = penumbraWidth(fe.profile);
    worstBin(fe, res.reference_profile);
    res.filters.push_back(std::move(fe));
  }
  return res;
}

ShadowAccuracy measureShadows(const AccuracyOptions& o) {
  const auto t0 = std::chrono::steady_clock::now();
  ShadowAccuracy a;
  a.options.size = o.quick ? 64 : 128;
  a.options.samples = o.quick ? 16 : 64;
  a.options.map_size = 1024;
  a.options.threads = o.threads;
  const std::vector<float> radii =
      o.quick ? std::vector<float>{0.1f, 0.25f} : std::vector<float>{0.05f, 0.15f, 0.25f};
  const std::vector<float> heights =
      o.quick ? std::vector<float>{0.5f, 1.2f} : std::vector<float>{0.5f, 1.0f, 1.5f};
  std::vector<ShadowCase> cases;
  for (float h : heights) {
    for (float r : radii) cases.push_back({r, 0.0f, {1.0f, 0.0f, 0.0f}, h});
  }
  // A capsule (radius 0.05 m, segment 0.6 m) along the measured direction and across it.
  for (float h : o.quick ? std::vector<float>{1.0f} : std::vector<float>{0.5f, 1.0f}) {
    cases.push_back({0.05f, 0.6f, {1.0f, 0.0f, 0.0f}, h});
    cases.push_back({0.05f, 0.6f, {0.0f, 0.0f, 1.0f}, h});
  }
  // Contact shadows: the occluder resting on the floor, the light 1.5 m off to -x (a sphere
  // light; a capsule of shadows.json's tube, radius 0.08 m and segment 1.2 m, along and across
  // the shadow's direction). The search then sees the occluder's side down to the floor,
  // blockers at every distance from the light.
  const float rest = kShadowOccluderRadius;
  cases.push_back({0.15f, 0.0f, {1.0f, 0.0f, 0.0f}, rest, 1.5f});
  if (!o.quick) {
    cases.push_back({0.08f, 1.2f, {1.0f, 0.0f, 0.0f}, rest, 1.5f});
    cases.push_back({0.08f, 1.2f, {0.0f, 0.0f, 1.0f}, rest, 1.5f});
  }
  for (const ShadowCase& c : cases) a.rows.push_back(measureShadowCase(c, a.options));
  a.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return a;
}

}  // namespace hv::eval
