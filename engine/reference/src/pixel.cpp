#include "pixel.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "halfvec/ibl/ibl_math.hpp"
#include "halfvec/reference/emitters.hpp"
#include "halfvec/reference/lobes.hpp"
#include "halfvec/reference/moments.hpp"
#include "halfvec/shading/shading.hpp"

namespace hv::reference_detail {

namespace {

constexpr int kDD = static_cast<int>(ReferenceAov::DirectDiffuse);
constexpr int kDS = static_cast<int>(ReferenceAov::DirectSpecular);
constexpr int kAD = static_cast<int>(ReferenceAov::AmbientDiffuse);
constexpr int kAS = static_cast<int>(ReferenceAov::AmbientSpecular);

// The ambient occlusion's random numbers come from a stream of their own (pixel streams are the
// pixel indices, far below 2^63), so the light and environment samples draw the same numbers
// with and without visibility.
constexpr uint64_t kAoStream = uint64_t(1) << 63u;

struct ScalarMoments {
  double sum = 0.0, sum2 = 0.0;
  void add(double x) {
    sum += x;
    sum2 += x * x;
  }
  double stdError(int n) const {
    if (n < 2) return 0.0;
    double m = sum / double(n);
    return std::sqrt(std::max((sum2 - double(n) * m * m) / double(n - 1), 0.0) / double(n));
  }
};

// The shading point and what every sample of it shares: the surface, the tangent frame (T, B,
// N), the view in it lifted above the horizon for VNDF sampling (Vs), the ambient specular's
// factors, and the origin of its visibility rays.
struct ShadingPoint {
  const Context& ctx;
  glsl::Surface s;
  glm::vec3 P, V, N, O;
  glm::vec3 T{0.0f}, B{0.0f}, Vs{0.0f}, ambient_spec_scale{0.0f};
  // The clear coat (clear_coat.glsl): weight (0: none), its lobe as a Surface, the base's scale
  // under it, and its own frame, lifted view and ambient factors, as the base's.
  float coat = 0.0f, base_scale = 1.0f;
  glsl::Surface cs{};
  glm::vec3 Tc{0.0f}, Bc{0.0f}, Vsc{0.0f}, coat_ambient_scale{0.0f};
  uint64_t rays = 0;
  bool visibility() const { return ctx.vis != nullptr; }
  bool occluded(const glm::vec3& L, float tfar) {
    ++rays;
    return ctx.vis->occluded(O, L, tfar);
  }
};

// f(v, l) times its cosine for direction L, in the parts the AOVs and the ambient factors need:
// the base's diffuse and specular (each times N.L, scaled by the coat's base_scale) and the coat's
// lobe times its weight and Nc.L (clear_coat.glsl: f_base (1 - c F_c) + c f_coat). Without a coat,
// brdfLobes times N.L.
struct CosLobes {
  glm::vec3 diffuse{0.0f}, specular{0.0f}, coat{0.0f};
  bool zero() const {
    return diffuse == glm::vec3(0.0f) && specular == glm::vec3(0.0f) && coat == glm::vec3(0.0f);
  }
};
CosLobes cosLobes(const ShadingPoint& p, const glm::vec3& L, bool analytic) {
  const Lobes f = brdfLobes(p.ctx.brdf, p.s, p.V, L, analytic);
  const float k = glsl::saturate(glm::dot(p.N, L)) * p.base_scale;
  CosLobes r{f.diffuse * k, f.specular * k, glm::vec3(0.0f)};
  if (p.coat > 0.0f) {
    const float c = glsl::saturate(glm::dot(p.cs.N, L)) * p.coat;
    if (c > 0.0f) r.coat = brdfLobes(p.ctx.brdf, p.cs, p.V, L, analytic).specular * c;
  }
  return r;
}
// Whether direction L is above the horizon of a lobe of the pixel (the base's or the coat's).
bool aboveSomeHorizon(const ShadingPoint& p, const glm::vec3& L) {
  return glm::dot(p.N, L) > 0.0f || (p.coat > 0.0f && glm::dot(p.cs.N, L) > 0.0f);
}
// The GGX-VNDF pdf of direction L (world) for the lobe of frame (T, B, N), lifted view Vs.
float vndfPdf(const glm::vec3& T, const glm::vec3& B, const glm::vec3& N, const glm::vec3& Vs,
              float alpha, const glm::vec3& L) {
  const glm::vec3 lt(glm::dot(L, T), glm::dot(L, B), glm::dot(L, N));
  if (lt.z <= 0.0f) return 0.0f;
  const glm::vec3 h = glsl::safeNormalize(Vs + lt);
  const float VoH = glm::dot(Vs, h);
  return VoH > 0.0f ? glsl::pdfGGXVNDF(Vs, h, alpha) / (4.0f * VoH) : 0.0f;
}
// A GGX-VNDF direction (world) for the lobe of frame (T, B, N); false below its horizon.
bool vndfSample(const glm::vec3& T, const glm::vec3& B, const glm::vec3& N, const glm::vec3& Vs,
                float alpha, glm::vec2 u, glm::vec3& L) {
  const glm::vec3 Ht = glsl::sampleGGXVNDF(Vs, alpha, u);
  const glm::vec3 lt = glm::reflect(-Vs, Ht);
  L = T * lt.x + B * lt.y + N * lt.z;
  return lt.z > 0.0f;
}

// Point lights and single-direction directional lights: exact, as the light pass (cavity on all
// direct light).
void pointLights(ShadingPoint& p, PixelOut& out) {
  const RenderSettings& settings = p.ctx.scene->settings;
  const glsl::Surface& s = p.s;
  for (size_t i = 0; i < p.ctx.point_lights.size(); ++i) {
    const Light* l = p.ctx.point_lights[i];
    glm::vec3 L;
    float scale, tfar;
    if (l->type == LightType::Directional) {
      // A single direction (angular diameter 0): its illuminance E, no falloff, a ray to infinity.
      L = -glm::normalize(l->direction);
      scale = s.cavity;
      tfar = std::numeric_limits<float>::infinity();
    } else {
      glm::vec3 Lc = l->position - p.P;
      float d2 = glm::dot(Lc, Lc);
      L = glsl::safeNormalize(Lc);
      scale = falloff(settings, d2, 0.0f, l->range) * s.cavity *
              glsl::spotAttenuation(L, p.ctx.point_cones[i]);
      tfar = glm::length(l->position - p.O);
    }
    const CosLobes f = cosLobes(p, L, true);
    // One ray to the light's position: a point light's shadow is hard.
    if (p.visibility() && scale > 0.0f && !f.zero() && p.occluded(L, tfar)) continue;
    glm::vec3 radiant = l->color * l->intensity;
    out.aov[kDD] += glm::dvec3(radiant * f.diffuse * scale);
    out.aov[kDS] += glm::dvec3(radiant * (f.specular + f.coat) * scale);
  }
}

// Area lights: per light one sample of the emitter's sampler and one GGX-VNDF direction (shared
// by the lights), balance heuristic: each contributes f L NoL / (p_light + p_vndf). Without the
// VNDF strategy a glossy surface's highlight of a small emitter is found by few emitter samples
// (rare huge values, an underestimate in between).
void areaLightSample(ShadingPoint& p, Rng& rng, glm::dvec3* xs) {
  const RenderSettings& settings = p.ctx.scene->settings;
  const glsl::Surface& s = p.s;
  // The BRDF strategies: the base's VNDF and, with a coat, the coat's (its sharp highlight is
  // what the base's lobe and the emitter's sampler rarely find).
  glm::vec3 Lv[2] = {glm::vec3(0.0f), glm::vec3(0.0f)};
  bool lv_ok[2] = {false, false};
  const int strategies = p.coat > 0.0f ? 2 : 1;
  lv_ok[0] =
      vndfSample(p.T, p.B, p.N, p.Vs, s.alpha, glm::vec2(rng.uniform(), rng.uniform()), Lv[0]);
  if (strategies == 2) {
    lv_ok[1] = vndfSample(p.Tc, p.Bc, p.cs.N, p.Vsc, p.cs.alpha,
                          glm::vec2(rng.uniform(), rng.uniform()), Lv[1]);
  }
  auto pdfBrdf = [&](const glm::vec3& L) {
    float pdf = vndfPdf(p.T, p.B, p.N, p.Vs, s.alpha, L);
    if (strategies == 2) pdf += vndfPdf(p.Tc, p.Bc, p.cs.N, p.Vsc, p.cs.alpha, L);
    return pdf;
  };
  float cone = 1.0f;  // the light's spot attenuation at P, set per light below
  auto add = [&](const LightSample& ls, float p_brdf) {
    float pdf = ls.pdf + p_brdf;
    if (!aboveSomeHorizon(p, ls.L) || !(pdf > 0.0f) || !std::isfinite(pdf)) return;
    // The ray stops at the sampled emitter point: what lies behind the light does not shadow it
    // (and emitters are not triangles: the light itself never occludes).
    if (p.visibility() && p.occluded(ls.L, ls.distance)) return;
    const CosLobes f = cosLobes(p, ls.L, true);
    glm::vec3 w = ls.radiance * (s.cavity * cone / pdf);
    xs[kDD] += glm::dvec3(f.diffuse * w);
    xs[kDS] += glm::dvec3((f.specular + f.coat) * w);
  };
  for (size_t i = 0; i < p.ctx.area_lights.size(); ++i) {
    const Light* l = p.ctx.area_lights[i];
    cone = glsl::spotAttenuation(glsl::safeNormalize(l->position - p.P), p.ctx.area_cones[i]);
    const glm::vec2 u(rng.uniform(), rng.uniform());
    // Beyond the range window the light contributes exactly 0.
    if (windowDistance2(*l, p.P) >= l->range * l->range) continue;
    LightSample ls = sampleLight(*l, settings, p.P, u);
    if (ls.pdf > 0.0f) add(ls, pdfBrdf(ls.L));
    for (int k = 0; k < strategies; ++k) {
      if (!lv_ok[k]) continue;
      LightSample lv = evalLight(*l, settings, p.P, Lv[k]);
      if (lv.pdf > 0.0f) add(lv, pdfBrdf(Lv[k]));
    }
  }
}

// Environment: one cosine, one VNDF, (non-uniform environments) one luminance-sampled and (sky)
// one sun-cone direction; balance heuristic with one sample per strategy: each contributes
// f L NoL / (p_cos + p_vndf + p_env + p_sun).
void environmentSample(ShadingPoint& p, Rng& rng, glm::dvec3* xs) {
  const Context& ctx = p.ctx;
  const glsl::Surface& s = p.s;
  const glm::vec3 &T = p.T, &B = p.B, &N = p.N;
  glm::vec2 u1(rng.uniform(), rng.uniform());
  glm::vec2 u2(rng.uniform(), rng.uniform());
  glm::vec3 Lw[5];
  int count = 2;
  glm::vec3 lt0 = glsl::sampleCosineHemisphere(u1);
  Lw[0] = T * lt0.x + B * lt0.y + N * lt0.z;
  vndfSample(T, B, N, p.Vs, s.alpha, u2, Lw[1]);
  if (ctx.env_dist) {
    float unused_pdf = 0.0f;
    Lw[count++] = ctx.env_dist->sample(glm::vec2(rng.uniform(), rng.uniform()), unused_pdf);
  }
  if (ctx.has_sun) {  // uniform in the cone: cos theta uniform in [sun_cos, 1]
    glm::vec2 u3(rng.uniform(), rng.uniform());
    float ct = 1.0f - u3.x * (1.0f - ctx.sun_cos);
    float st = std::sqrt(std::max(1.0f - ct * ct, 0.0f)), phi = 6.2831853f * u3.y;
    glm::vec3 sT, sB;
    glsl::tangentFrame(ctx.sun_dir, sT, sB);
    Lw[count++] = sT * (st * std::cos(phi)) + sB * (st * std::sin(phi)) + ctx.sun_dir * ct;
  }
  // The coat's VNDF (clear coat): its own strategy, drawn after the others so that a pixel
  // without a coat draws the same numbers as before.
  const bool coated = p.coat > 0.0f;
  if (coated) {
    vndfSample(p.Tc, p.Bc, p.cs.N, p.Vsc, p.cs.alpha, glm::vec2(rng.uniform(), rng.uniform()),
               Lw[count++]);
  }
  for (int k = 0; k < count; ++k) {
    const glm::vec3 L = glm::normalize(Lw[k]);
    if (!aboveSomeHorizon(p, L)) continue;
    const float NoL = glm::dot(L, N);
    float p_cos = NoL > 0.0f ? glsl::pdfCosineHemisphere(NoL) : 0.0f;
    float p_spec = vndfPdf(T, B, N, p.Vs, s.alpha, L);
    float p_env = ctx.env_dist ? ctx.env_dist->pdf(L) : 0.0f;
    const bool in_sun = ctx.has_sun && glm::dot(L, ctx.sun_dir) >= ctx.sun_cos;
    float p_sun = in_sun ? ctx.sun_pdf : 0.0f;
    float p_coat = coated ? vndfPdf(p.Tc, p.Bc, p.cs.N, p.Vsc, p.cs.alpha, L) : 0.0f;
    float pdf = p_cos + p_spec + p_env + p_sun + p_coat;
    if (!(pdf > 0.0f) || !std::isfinite(pdf)) continue;
    if (p.visibility() && p.occluded(L, std::numeric_limits<float>::infinity())) continue;
    const CosLobes f = cosLobes(p, L, false);
    glm::vec3 w = ctx.env.radiance(L) * (1.0f / pdf);
    const bool direct = in_sun && ctx.sun_is_direct;
    const glm::vec3 spec = f.specular * p.ambient_spec_scale + f.coat * p.coat_ambient_scale;
    if (ctx.hdr_sun_split) {
      const glm::vec3 w_ambient = ctx.env_without_sun.radiance(L) * (1.0f / pdf);
      xs[kAD] += glm::dvec3(f.diffuse * w_ambient * s.cavity);
      xs[kAS] += glm::dvec3(spec * w_ambient);
      xs[kDD] += glm::dvec3(f.diffuse * (w - w_ambient) * s.cavity);
      xs[kDS] += glm::dvec3(spec * (w - w_ambient));
      continue;
    }
    xs[direct ? kDD : kAD] += glm::dvec3(f.diffuse * w * s.cavity);
    xs[direct ? kDS : kAS] += glm::dvec3(spec * w);
  }
}

// Ambient occlusion: a cosine-distributed direction, whose estimator (1/pi) V NoL / pdf is the
// visibility V itself.
double aoSample(ShadingPoint& p, Rng& ao_rng) {
  const glm::vec3 lt = glsl::sampleCosineHemisphere(glm::vec2(ao_rng.uniform(), ao_rng.uniform()));
  const glm::vec3 L = glm::normalize(p.T * lt.x + p.B * lt.y + p.N * lt.z);
  return p.occluded(L, p.ctx.opt->ao_distance) ? 0.0 : 1.0;
}

// The clear coat of G-buffer pixel `index` (clear_coat.glsl), where its model has one.
void setCoat(ShadingPoint& p, const GBufferReadback& gb, size_t index) {
  if (!gb.hasCoat() || gb.model[index] != uint32_t(ShadingModel::ClearCoat)) return;
  const glm::vec3 Nc = glsl::viewFacingNormal(glm::normalize(gb.coat_normal[index]), p.V);
  p.coat = gb.clearcoat[index];
  p.cs = glsl::makeCoatSurface(Nc, gb.clearcoat_roughness[index], gb.cavity[index]);
  p.base_scale = glsl::coatBaseScale(p.coat, Nc, p.V);
}

// The tangent frame, the lifted view and the ambient specular's factors of p.
void prepareSampling(ShadingPoint& p) {
  const RenderSettings& settings = p.ctx.scene->settings;
  const glsl::Surface& s = p.s;
  const glm::vec3 &V = p.V, &N = p.N;
  glsl::tangentFrame(N, p.T, p.B);
  glm::vec3 Vt(glm::dot(V, p.T), glm::dot(V, p.B), glm::dot(V, N));
  // VNDF sampling needs V above the surface; a normal facing away (NoV <= 0, which the BRDF
  // clamps to HV_MIN_NOV) samples with V lifted to NoV = 1e-4. Any sampler is unbiased here
  // since the cosine strategy covers the hemisphere and pdfs are evaluated consistently.
  p.Vs = glm::normalize(glm::vec3(Vt.x, Vt.y, std::max(Vt.z, 1e-4f)));
  float NoV = glm::clamp(glm::dot(N, V), 1e-4f, 1.0f);  // as the ambient pass
  // The ambient specular's factors as the engine applies them (ambientSpecularScale, ibl.glsl),
  // with the energy compensation's E(NoV, roughness) integrated here rather than looked up in the
  // 128^2 table; see docs/reference.md.
  glm::vec2 ab(0.0f);
  if (settings.energy_compensation) ab = integrateEnvBrdfAt(NoV, s.roughness, 1024, p.ctx.brdf);
  p.ambient_spec_scale = glsl::ambientSpecularScale(s, ab, NoV, settings.energy_compensation,
                                                    settings.specular_occlusion);
  if (p.coat > 0.0f) {
    const glm::vec3 Nc = p.cs.N;
    glsl::tangentFrame(Nc, p.Tc, p.Bc);
    glm::vec3 Vc(glm::dot(V, p.Tc), glm::dot(V, p.Bc), glm::dot(V, Nc));
    p.Vsc = glm::normalize(glm::vec3(Vc.x, Vc.y, std::max(Vc.z, 1e-4f)));
    const float NoVc = glm::clamp(glm::dot(Nc, V), 1e-4f, 1.0f);
    glm::vec2 abc(0.0f);
    if (settings.energy_compensation) {
      abc = integrateEnvBrdfAt(NoVc, p.cs.roughness, 1024, p.ctx.brdf);
    }
    p.coat_ambient_scale = glsl::ambientSpecularScale(p.cs, abc, NoVc, settings.energy_compensation,
                                                      settings.specular_occlusion);
  }
}

}  // namespace

PixelOut shadePixel(const Context& ctx, size_t index, int x, int y) {
  const auto& gb = *ctx.gb;
  const ReferenceOptions& opt = *ctx.opt;
  PixelOut out{};
  for (auto& a : out.aov) a = glm::dvec3(0.0);
  for (auto& a : out.aov_se) a = glm::dvec3(0.0);
  out.se = glm::dvec3(0.0);

  glm::vec2 uv((float(x) + 0.5f) / float(gb.width), 1.0f - (float(y) + 0.5f) / float(gb.height));
  const glm::vec3 P = glsl::reconstructWorldPosition(uv, gb.depth[index], ctx.inv_view_proj);
  const glm::vec3 V = glm::normalize(ctx.scene->camera.position - P);
  // The engine's G-buffer holds view-facing normals already; a normal facing away (a G-buffer
  // from elsewhere) is reflected as the G-buffer pass does (gbuffer.glsl, viewFacingNormal).
  const glm::vec3 N = glsl::viewFacingNormal(glm::normalize(gb.normal[index]), V);
  // Visibility rays leave from just above the surface (visibility.hpp: rayOrigin says why).
  ShadingPoint p{ctx,
                 glsl::makeSurface(N, gb.base_color[index], gb.metallic[index], gb.roughness[index],
                                   gb.cavity[index]),
                 P,
                 V,
                 N,
                 ctx.vis ? rayOrigin(P, N, ctx.scene->camera.position) : P};
  setCoat(p, gb, index);
  pointLights(p, out);

  // ---- Monte Carlo part: area lights, the environment and (visibility) the ambient occlusion.
  const bool stochastic = ctx.has_env || !ctx.area_lights.empty() || p.visibility();
  if (!stochastic) {
    out.rays = p.rays;
    return out;
  }

  Rng rng(opt.seed, index);
  prepareSampling(p);

  Moments m[kReferenceAovCount];
  Moments total_m;  // of the per-sample sum of the AOVs
  ScalarMoments lum, ao_m;
  Rng ao_rng(opt.seed, kAoStream | uint64_t(index));
  const glm::dvec3 exact = out.aov[kDD] + out.aov[kDS];
  const double exact_lum = luminance(exact);
  int n = 0;
  const int max_samples = std::max(opt.samples, 1);
  const int batch = std::max(opt.batch, 1);
  while (n < max_samples) {
    const int end = std::min(n + batch, max_samples);
    for (; n < end; ++n) {
      glm::dvec3 xs[kReferenceAovCount] = {glm::dvec3(0.0), glm::dvec3(0.0), glm::dvec3(0.0),
                                           glm::dvec3(0.0)};
      if (!ctx.area_lights.empty()) areaLightSample(p, rng, xs);
      if (ctx.has_env) environmentSample(p, rng, xs);
      if (p.visibility()) ao_m.add(aoSample(p, ao_rng));
      glm::dvec3 total(0.0);
      for (int a = 0; a < kReferenceAovCount; ++a) {
        m[a].add(xs[a]);
        total += xs[a];
      }
      total_m.add(total);
      lum.add(luminance(total));
    }
    if (opt.target_rel_error > 0.0f && n >= opt.min_samples) {
      double y_mean = exact_lum + lum.sum / double(n);
      if (lum.stdError(n) <= double(opt.target_rel_error) * std::abs(y_mean)) break;
    }
  }
  out.samples = n;
  for (int a = 0; a < kReferenceAovCount; ++a) {
    out.aov[a] += m[a].mean(n);
    out.aov_se[a] = m[a].stdError(n);
  }
  out.se = total_m.stdError(n);
  if (p.visibility()) {
    out.ao = n > 0 ? ao_m.sum / double(n) : 1.0;
    out.ao_se = ao_m.stdError(n);
  }
  double y_mean = exact_lum + lum.sum / double(std::max(n, 1));
  out.rel_error = y_mean > 0.0 ? lum.stdError(n) / y_mean : 0.0;
  out.rays = p.rays;
  return out;
}

}  // namespace hv::reference_detail
