#include "halfvec/eval/light_accuracy.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>

#include "halfvec/core/parallel.hpp"
#include "halfvec/reference/emitters.hpp"
#include "halfvec/reference/moments.hpp"
#include "halfvec/reference/lobes.hpp"
#include "halfvec/shading/brdf.hpp"
#include "halfvec/shading/shading.hpp"

namespace hv::eval {

namespace {

constexpr double kPi = 3.14159265358979323846;

using reference_detail::Moments;

// The GGX alpha the engine shades with (roughness clamped as makeSurface does), for sizing the
// view rings around the lobe.
float lobeAlpha(float roughness) {
  const float r = std::max(roughness, glsl::HV_MIN_ROUGHNESS);
  return r * r;
}

RenderSettings physicalSettings() {
  RenderSettings s;
  s.falloff_plus_one = false;
  return s;
}

glm::vec3 dirFromElevation(float elevation_rad, float azimuth_rad) {
  return {std::cos(elevation_rad) * std::cos(azimuth_rad),
          std::cos(elevation_rad) * std::sin(azimuth_rad), std::sin(elevation_rad)};
}

// Reference values (red channel) of one light over the views, per term, for one BRDF.
struct ViewValues {
  std::vector<double> ref_d, ref_d_se, ref_s, ref_s_se;
};

ViewValues referenceAtViews(const Light& light, const std::vector<glm::vec3>& views,
                            float roughness, int samples, uint64_t seed, DistributionTerm d,
                            VisibilityTerm v) {
  ViewValues r;
  const glm::vec3 P(0.0f), N(0.0f, 0.0f, 1.0f);
  for (size_t i = 0; i < views.size(); ++i) {
    const LightIntegral x = integrateLight(light, P, N, views[i], glm::vec3(1.0f), glm::vec3(1.0f),
                                           roughness, samples, seed + i, d, v);
    r.ref_d.push_back(x.diffuse.x);
    r.ref_d_se.push_back(x.diffuse_se.x);
    r.ref_s.push_back(x.specular.x);
    r.ref_s_se.push_back(x.specular_se.x);
  }
  return r;
}

std::vector<double> engineAtViews(CompiledLightVariant variant, const Light& light,
                                  const std::vector<glm::vec3>& views, float roughness) {
  const glm::vec3 P(0.0f), N(0.0f, 0.0f, 1.0f);
  // White diffuse (metallic 0) for the diffuse term, white specular (metallic 1, f0 = 1) for the
  // specular term: the surface the reference integrates.
  const float metallic = variant.variant().term == LightTerm::Diffuse ? 0.0f : 1.0f;
  std::vector<double> e;
  for (const glm::vec3& V : views) {
    e.push_back(engineLightTerm(variant, light, P, N, V, glm::vec3(1.0f), metallic, roughness).x);
  }
  return e;
}

// The references one configuration needs: one per distinct BRDF (D, V) of the methods.
struct References {
  std::vector<std::pair<std::pair<DistributionTerm, VisibilityTerm>, ViewValues>> by_brdf;
  const ViewValues& at(const EngineLightOptions& o) const {
    for (const auto& [k, v] : by_brdf) {
      if (k.first == o.d && k.second == o.v) return v;
    }
    return by_brdf.front().second;
  }
};

References referencesAtViews(const Light& light, const std::vector<glm::vec3>& views,
                             float roughness, int samples, uint64_t seed,
                             const std::vector<LightMethod>& methods) {
  References r;
  for (const LightMethod& m : methods) {
    bool have = false;
    for (const auto& e : r.by_brdf)
      have = have || (e.first.first == m.o.d && e.first.second == m.o.v);
    if (have) continue;
    // The same seed for every BRDF: the references of two methods share their random numbers.
    r.by_brdf.push_back(
        {{m.o.d, m.o.v}, referenceAtViews(light, views, roughness, samples, seed, m.o.d, m.o.v)});
  }
  return r;
}

// A method as the lists below write it: its name and options, and the compiled variant that runs
// it for term T, found when this file compiles (options not in kEngineLightVariants do not).
template <LightTerm T>
struct MethodSpec {
  const char* name;
  EngineLightOptions o;
  CompiledLightVariant variant;
  consteval MethodSpec(const char* n, EngineLightOptions opts)
      : name(n), o(opts), variant(compiledLightVariant(T, opts)) {}
};
using DiffuseSpec = MethodSpec<LightTerm::Diffuse>;
using SpecularSpec = MethodSpec<LightTerm::Specular>;

template <LightTerm T, size_t N>
std::vector<LightMethod> methods(const MethodSpec<T> (&specs)[N]) {
  std::vector<LightMethod> m;
  for (const MethodSpec<T>& s : specs) m.push_back({s.name, s.o, s.variant});
  return m;
}

constexpr EngineLightOptions ltcOptions(VisibilityTerm v, bool ratio, DistributionTerm d) {
  EngineLightOptions o;
  o.sphere_specular = SphereSpecular::Ltc;
  o.tube_specular = TubeSpecular::Ltc;
  o.v = v;
  o.ltc_v_ratio = ratio;
  o.d = d;
  return o;
}

}  // namespace

LightIntegral integrateLight(const Light& light, const glm::vec3& P, const glm::vec3& N,
                             const glm::vec3& V, const glm::vec3& diffuse_color,
                             const glm::vec3& f0, float roughness, int samples, uint64_t seed,
                             DistributionTerm d, VisibilityTerm v) {
  using namespace reference_detail;
  const RenderSettings settings = physicalSettings();
  BrdfConfig brdf = BrdfConfig::fromSettings(settings);
  brdf.d = d;
  brdf.v = v;
  glsl::Surface s = glsl::makeSurface(N, glm::vec3(1.0f), 0.0f, roughness, 1.0f);
  s.diffuse_color = diffuse_color;
  s.f0 = f0;
  glm::vec3 T, B;
  glsl::tangentFrame(N, T, B);
  const glm::vec3 Vt(glm::dot(V, T), glm::dot(V, B), glm::dot(V, N));
  const glm::vec3 Vs = glm::normalize(glm::vec3(Vt.x, Vt.y, std::max(Vt.z, 1e-4f)));
  // Solid-angle pdf of the reflected GGX-VNDF direction lt (tangent space).
  auto pdf_vndf = [&](const glm::vec3& lt) {
    const glm::vec3 h = glsl::safeNormalize(Vs + lt);
    const float VoH = glm::dot(Vs, h);
    return VoH > 0.0f ? glsl::pdfGGXVNDF(Vs, h, s.alpha) / (4.0f * VoH) : 0.0f;
  };
  const glm::vec3 Le = emitterRadianceAt(light, settings, P);
  Rng rng(seed, 0x5EEDull);
  Moments md, ms;
  const int n = std::max(samples, 2);
  for (int i = 0; i < n; ++i) {
    glm::dvec3 xd(0.0), xs(0.0);
    // Strategy 1: the reference's emitter sampling (diffuse alone; specular with MIS).
    const LightSample ls = sampleLight(light, settings, P, glm::vec2(rng.uniform(), rng.uniform()));
    if (ls.pdf > 0.0f) {
      const float NoL = glsl::saturate(glm::dot(N, ls.L));
      if (NoL > 0.0f) {
        const Lobes f = brdfLobes(brdf, s, V, ls.L, true);
        const glm::vec3 lt(glm::dot(ls.L, T), glm::dot(ls.L, B), NoL);
        xd += glm::dvec3(f.diffuse * ls.radiance) * double(NoL / ls.pdf);
        xs += glm::dvec3(f.specular * ls.radiance) * double(NoL / (ls.pdf + pdf_vndf(lt)));
      }
    }
    // Strategy 2: a GGX visible-normal direction, traced against the emitter (specular, MIS).
    const glm::vec3 Ht = glsl::sampleGGXVNDF(Vs, s.alpha, glm::vec2(rng.uniform(), rng.uniform()));
    const glm::vec3 lt = glm::reflect(-Vs, Ht);
    if (lt.z > 0.0f) {
      const glm::vec3 L = glm::normalize(T * lt.x + B * lt.y + N * lt.z);
      const float p_light = lightPdf(light, P, L);
      const float p_vndf = pdf_vndf(lt);
      if (p_light > 0.0f && p_vndf > 0.0f) {
        const Lobes f = brdfLobes(brdf, s, V, L, true);
        xs += glm::dvec3(f.specular * Le) * double(lt.z / (p_light + p_vndf));
      }
    }
    md.add(xd);
    ms.add(xs);
  }
  LightIntegral r;
  r.diffuse = md.mean(n);
  r.diffuse_se = md.stdError(n);
  r.specular = ms.mean(n);
  r.specular_se = ms.stdError(n);
  return r;
}

Light sweepLight(LightType type) {
  Light l;
  l.type = type;
  l.color = glm::vec3(1.0f);
  l.intensity = 1.0f;
  l.range = 1.0e4f;  // window = 1 - 1e-16 at the distances swept: no window effect
  return l;
}

bool sphereAboveHorizon(float radius, float elevation_deg) {
  return double(elevation_deg) >= std::asin(std::min(double(radius), 1.0)) * 180.0 / kPi;
}

std::vector<glm::vec3> sphereSweepViews(const glm::vec3& dir, float roughness, float radius) {
  return sweepViews(dir, 2.0f * lobeAlpha(roughness) + std::asin(std::min(radius, 1.0f)));
}

TermError termError(const std::vector<double>& engine, const std::vector<double>& reference,
                    const std::vector<double>& reference_se) {
  TermError t;
  double abs_sum = 0.0, signed_sum = 0.0, var = 0.0;
  for (size_t i = 0; i < engine.size(); ++i) {
    t.engine_sum += engine[i];
    t.reference_sum += reference[i];
    abs_sum += std::abs(engine[i] - reference[i]);
    signed_sum += engine[i] - reference[i];
    var += reference_se[i] * reference_se[i];
  }
  t.valid = t.reference_sum > 1e-12;
  if (!t.valid) return t;
  t.rel_error = abs_sum / t.reference_sum;
  t.bias = signed_sum / t.reference_sum;
  t.noise = std::sqrt(var) / t.reference_sum;
  t.peak = reference[0] > 0.0 ? engine[0] / reference[0] : 0.0;
  return t;
}

std::vector<glm::vec3> sweepViews(const glm::vec3& light_dir, float footprint) {
  const float min_el = float(2.0 * kPi / 180.0);
  const float el = std::max(std::asin(glm::clamp(light_dir.z, -1.0f, 1.0f)), min_el);
  const float az = std::atan2(light_dir.y, light_dir.x) + float(kPi);
  const glm::vec3 m = dirFromElevation(el, az);
  std::vector<glm::vec3> views{m};
  glm::vec3 t1, t2;
  glsl::tangentFrame(m, t1, t2);
  const float fp = glm::clamp(footprint, 0.01f, 0.6f);
  const float horizon = std::sin(float(kPi / 180.0));
  for (float k : {1.0f, 2.0f}) {
    for (int j = 0; j < 8; ++j) {
      const float phi = float(2.0 * kPi * j / 8.0);
      const glm::vec3 v = glm::normalize(
          std::cos(k * fp) * m + std::sin(k * fp) * (std::cos(phi) * t1 + std::sin(phi) * t2));
      if (v.z > horizon) views.push_back(v);
    }
  }
  for (float e : {30.0f, 60.0f}) {
    for (int j = 0; j < 4; ++j) {
      views.push_back(dirFromElevation(float(e * kPi / 180.0), float(kPi * (0.25 + 0.5 * j))));
    }
  }
  return views;
}

namespace {

using VT = VisibilityTerm;
using DT = DistributionTerm;

constexpr DiffuseSpec kSphereDiffuse[] = {
    {"karis_point (default)", {}},
    {"horizon_correct", {.sphere_diffuse = SphereDiffuse::HorizonCorrect}},
};
constexpr SpecularSpec kSphereSpecular[] = {
    {"representative point + normalization (default)", {}},
    {"representative point, no normalization", {.sphere_normalization = false}},
    {"ltc", ltcOptions(VT::SmithGGXCorrelated, true, DT::GGX)},
    {"representative point + normalization, V smith_ggx_correlated", {.v = VT::SmithGGXCorrelated}},
    {"ltc, V schlick_ggx (V ratio)", ltcOptions(VT::SchlickGGX, true, DT::GGX)},
    {"ltc, V schlick_ggx (no V ratio)", ltcOptions(VT::SchlickGGX, false, DT::GGX)},
    {"ltc, D beckmann", ltcOptions(VT::SchlickGGX, true, DT::Beckmann)},
};
constexpr DiffuseSpec kTubeDiffuse[] = {
    {"karis_eq16 (default)", {}},
    {"ltc", {.tube_diffuse = TubeDiffuse::Ltc}},
};
constexpr SpecularSpec kTubeSpecular[] = {
    {"eq. 19 + normalization (default)", {}},
    {"eq. 19, no normalization", {.tube_normalization = false}},
    {"eq. 18 + normalization", {.tube_specular = TubeSpecular::SmallestAngleEq18}},
    {"eq. 18, no normalization",
     {.tube_specular = TubeSpecular::SmallestAngleEq18, .tube_normalization = false}},
    {"ltc", ltcOptions(VT::SmithGGXCorrelated, true, DT::GGX)},
    {"eq. 19 + normalization, V smith_ggx_correlated", {.v = VT::SmithGGXCorrelated}},
    {"ltc, V schlick_ggx (V ratio)", ltcOptions(VT::SchlickGGX, true, DT::GGX)},
    {"ltc, V schlick_ggx (no V ratio)", ltcOptions(VT::SchlickGGX, false, DT::GGX)},
    {"ltc, D beckmann", ltcOptions(VT::SchlickGGX, true, DT::Beckmann)},
};
static_assert(std::size(kSphereDiffuse) == kSphereDiffuseMethods &&
              std::size(kSphereSpecular) == kSphereSpecularMethods &&
              std::size(kTubeDiffuse) == kTubeDiffuseMethods &&
              std::size(kTubeSpecular) == kTubeSpecularMethods);

}  // namespace

const std::vector<LightMethod>& sphereDiffuseMethods() {
  static const std::vector<LightMethod> m = methods(kSphereDiffuse);
  return m;
}
const std::vector<LightMethod>& sphereSpecularMethods() {
  static const std::vector<LightMethod> m = methods(kSphereSpecular);
  return m;
}
const std::vector<LightMethod>& tubeDiffuseMethods() {
  static const std::vector<LightMethod> m = methods(kTubeDiffuse);
  return m;
}
const std::vector<LightMethod>& tubeSpecularMethods() {
  static const std::vector<LightMethod> m = methods(kTubeSpecular);
  return m;
}

bool SphereSweepRow::above() const {
  return sphereAboveHorizon(radius, elevation_deg);
}

namespace {

// The error of every diffuse method (`dm`) and specular method (`sm`) of the engine at `views`
// against the references of its own BRDF terms; appended to `diffuse` and `specular`.
void methodErrors(const std::vector<LightMethod>& dm, const std::vector<LightMethod>& sm,
                  const References& ref, const Light& light, const std::vector<glm::vec3>& views,
                  float roughness, std::vector<TermError>& diffuse,
                  std::vector<TermError>& specular) {
  for (const LightMethod& m : dm) {
    const ViewValues& r = ref.at(m.o);
    diffuse.push_back(
        termError(engineAtViews(m.variant, light, views, roughness), r.ref_d, r.ref_d_se));
  }
  for (const LightMethod& m : sm) {
    const ViewValues& r = ref.at(m.o);
    specular.push_back(
        termError(engineAtViews(m.variant, light, views, roughness), r.ref_s, r.ref_s_se));
  }
}

}  // namespace

namespace {

// A sphere straddling the horizon shows only the part of its disk above it, and the reference's
// emitter samples, spread over the whole disk, land there in proportion (a sliver of r/d 0.1 at
// elevation -5: 3% of them): the sweep gives those rows more samples, the inverse of the visible
// share of the disk (at most 32x), so their noise stays near that of the rows above the horizon.
int straddlingSampleScale(const SphereSweepRow& row) {
  if (row.above() || row.radius >= 1.0f) return 1;
  const double sin_s = row.radius, t = sin_s / std::sqrt(1.0 - sin_s * sin_s);
  const double e = row.elevation_deg * kPi / 180.0;
  // The disk of radius t on the tangent plane at unit distance, cut at y0 = -tan(e) (the
  // horizon's chord): the share of its area above.
  const double y0 = std::clamp(-std::tan(e), -t, t);
  const double above = t * t * std::acos(y0 / t) - y0 * std::sqrt(t * t - y0 * y0);
  const double share = above / (kPi * t * t);
  return int(std::clamp(std::ceil(1.0 / std::max(share, 1e-6)), 1.0, 32.0));
}

}  // namespace

std::vector<SphereSweepRow> sweepSphere(const SphereSweepGrid& g) {
  std::vector<SphereSweepRow> rows;
  for (float r : g.roughness)
    for (float rad : g.radius)
      for (float el : g.elevation_deg) {
        SphereSweepRow row;
        row.roughness = r;
        row.radius = rad;
        row.elevation_deg = el;
        rows.push_back(row);
      }
  const auto& dm = sphereDiffuseMethods();
  const auto& sm = sphereSpecularMethods();
  detail::parallelFor(int(rows.size()), g.threads, [&](int i) {
    SphereSweepRow& row = rows[size_t(i)];
    Light light = sweepLight(g.directional ? LightType::Directional : LightType::Sphere);
    const glm::vec3 dir = dirFromElevation(float(row.elevation_deg * kPi / 180.0), 0.0f);
    light.position = dir;  // distance 1
    light.radius = row.radius;
    light.direction = -dir;  // a directional light: travelling toward the shading point
    light.angular_diameter = 2.0f * std::asin(std::min(row.radius, 1.0f));
    const auto views = sphereSweepViews(dir, row.roughness, row.radius);
    const References ref =
        referencesAtViews(light, views, row.roughness, g.samples * straddlingSampleScale(row),
                          g.seed + uint64_t(i) * 1000003ull, sm);
    methodErrors(dm, sm, ref, light, views, row.roughness, row.diffuse, row.specular);
  });
  return rows;
}

std::vector<TubeSweepRow> sweepTube(const TubeSweepGrid& g) {
  std::vector<TubeSweepRow> rows;
  for (float r : g.roughness)
    for (float len : g.length)
      for (float rad : g.radius)
        for (bool along : {false, true}) {
          TubeSweepRow row;
          row.roughness = r;
          row.length = len;
          row.radius = rad;
          row.along = along;
          rows.push_back(row);
        }
  const auto& dm = tubeDiffuseMethods();
  const auto& sm = tubeSpecularMethods();
  detail::parallelFor(int(rows.size()), g.threads, [&](int i) {
    TubeSweepRow& row = rows[size_t(i)];
    const glm::vec3 dir = dirFromElevation(float(g.elevation_deg * kPi / 180.0), 0.0f);
    const float alpha = lobeAlpha(row.roughness);
    Light light = sweepLight(LightType::Tube);
    light.position = dir;
    light.radius = row.radius;
    light.length = row.length;
    // Horizontal axis: along (x) or across (y) the plane of incidence.
    light.axis = row.along ? glm::vec3(1.0f, 0.0f, 0.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
    const float half_extent = std::atan(0.5f * row.length) + std::asin(row.radius);
    const auto views = sweepViews(dir, 2.0f * alpha + half_extent);
    const References ref = referencesAtViews(light, views, row.roughness, g.samples,
                                             g.seed + uint64_t(i) * 1000003ull, sm);
    methodErrors(dm, sm, ref, light, views, row.roughness, row.diffuse, row.specular);
  });
  return rows;
}

}  // namespace hv::eval
