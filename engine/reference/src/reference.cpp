#include "halfvec/reference/reference.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

#include "halfvec/ibl/ibl_math.hpp"
#include "halfvec/core/parallel.hpp"
#include "halfvec/reference/emitters.hpp"
#include "halfvec/reference/moments.hpp"
#include "halfvec/reference/env_sampling.hpp"
#include "halfvec/reference/lobes.hpp"
#include "halfvec/reference/visibility.hpp"
#include "halfvec/shading/brdf.hpp"
#include "halfvec/shading/shading.hpp"

namespace hv {

const char* toString(ReferenceAov aov) {
  switch (aov) {
    case ReferenceAov::DirectDiffuse:
      return "direct_diffuse";
    case ReferenceAov::DirectSpecular:
      return "direct_specular";
    case ReferenceAov::AmbientDiffuse:
      return "ambient_diffuse";
    case ReferenceAov::AmbientSpecular:
      return "ambient_specular";
  }
  return "?";
}

glm::mat4 referenceInvViewProj(const Camera& c, int width, int height) {
  // Same matrices as render::makeFrameBlock / reversedInfinitePerspective (frame_data.cpp);
  // tests/reference checks the two agree.
  const glm::mat4 view = glm::lookAt(c.position, c.target, c.up);
  const float f = 1.0f / std::tan(glm::radians(c.fov_y_deg) * 0.5f);
  glm::mat4 proj(0.0f);
  proj[0][0] = f / (float(width) / float(height));
  proj[1][1] = f;
  proj[2][3] = -1.0f;         // w_clip = -z_view
  proj[3][2] = c.near_plane;  // depth = near / -z_view
  return glm::inverse(proj * view);
}

namespace {

using reference_detail::Rng;

constexpr int kDD = static_cast<int>(ReferenceAov::DirectDiffuse);
constexpr int kDS = static_cast<int>(ReferenceAov::DirectSpecular);
constexpr int kAD = static_cast<int>(ReferenceAov::AmbientDiffuse);
constexpr int kAS = static_cast<int>(ReferenceAov::AmbientSpecular);

double luminance(const glm::dvec3& c) {
  return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z;
}

using reference_detail::Moments;

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

// Everything constant over the image.
struct Context {
  const Scene* scene;
  const GBufferReadback* gb;
  const ReferenceOptions* opt;
  BrdfConfig brdf;
  glm::mat4 inv_view_proj;
  bool has_env = false;
  EnvSource env;
  // Luminance sampling of a non-uniform environment (null for uniform: cosine + VNDF suffice).
  std::unique_ptr<reference_detail::EnvDistribution> env_dist;
  // EnvironmentKind::Sky: the sun's cone (world direction, cos of its angular radius, 1/omega)
  // for a third, sun-sampling strategy; the other two almost never hit a 0.27 degree sun.
  bool has_sun = false;
  glm::vec3 sun_dir{0.0f, 1.0f, 0.0f};
  float sun_cos = 1.0f, sun_pdf = 0.0f;
  std::vector<const Light*> point_lights, area_lights;
  // ReferenceOptions::visibility: the scene's triangles (null without visibility).
  std::unique_ptr<reference_detail::SceneVisibility> vis;
};

// The ambient occlusion's random numbers come from a stream of their own (pixel streams are the
// pixel indices, far below 2^63), so the light and environment samples draw the same numbers
// with and without visibility.
constexpr uint64_t kAoStream = uint64_t(1) << 63u;

using reference_detail::brdfLobes;
using reference_detail::Lobes;

struct PixelOut {
  glm::dvec3 aov[kReferenceAovCount];
  glm::dvec3 aov_se[kReferenceAovCount];
  glm::dvec3 se;
  double rel_error = 0.0;
  int samples = 0;
  double ao = 1.0, ao_se = 0.0;
  uint64_t rays = 0;
};

PixelOut shadePixel(const Context& ctx, size_t index, int x, int y) {
  const auto& gb = *ctx.gb;
  const ReferenceOptions& opt = *ctx.opt;
  const RenderSettings& settings = ctx.scene->settings;
  PixelOut out{};
  for (auto& a : out.aov) a = glm::dvec3(0.0);
  for (auto& a : out.aov_se) a = glm::dvec3(0.0);
  out.se = glm::dvec3(0.0);

  glm::vec2 uv((float(x) + 0.5f) / float(gb.width), 1.0f - (float(y) + 0.5f) / float(gb.height));
  glm::vec3 P = glsl::reconstructWorldPosition(uv, gb.depth[index], ctx.inv_view_proj);
  glm::vec3 V = glm::normalize(ctx.scene->camera.position - P);
  glm::vec3 N = glm::normalize(gb.normal[index]);
  glsl::Surface s = glsl::makeSurface(N, gb.base_color[index], gb.metallic[index],
                                      gb.roughness[index], gb.cavity[index]);
  // Visibility rays leave from just above the surface (visibility.hpp: rayOrigin says why).
  const reference_detail::SceneVisibility* vis = ctx.vis.get();
  const glm::vec3 O = vis ? reference_detail::rayOrigin(P, N, ctx.scene->camera.position) : P;
  auto occluded = [&](const glm::vec3& L, float tfar) {
    ++out.rays;
    return vis->occluded(O, L, tfar);
  };

  // ---- Point lights: exact, as the light pass (cavity on all direct light). ----
  for (const Light* l : ctx.point_lights) {
    glm::vec3 Lc = l->position - P;
    float d2 = glm::dot(Lc, Lc);
    glm::vec3 L = glsl::safeNormalize(Lc);
    float NoL = glsl::saturate(glm::dot(N, L));
    float scale = reference_detail::falloff(settings, d2, 0.0f, l->range) * NoL * s.cavity;
    // One ray to the light's position: a point light's shadow is hard.
    if (vis && scale > 0.0f && occluded(L, glm::length(l->position - O))) continue;
    Lobes f = brdfLobes(ctx.brdf, s, V, L, true);
    glm::vec3 radiant = l->color * l->intensity;
    out.aov[kDD] += glm::dvec3(radiant * f.diffuse * scale);
    out.aov[kDS] += glm::dvec3(radiant * f.specular * scale);
  }

  // ---- Monte Carlo part: area lights and the environment. ----
  // With visibility the ambient occlusion is a Monte Carlo estimate of its own.
  const bool stochastic = ctx.has_env || !ctx.area_lights.empty() || vis;
  if (!stochastic) return out;

  Rng rng(opt.seed, index);
  glm::vec3 T, B;
  glsl::tangentFrame(N, T, B);
  glm::vec3 Vt(glm::dot(V, T), glm::dot(V, B), glm::dot(V, N));
  // VNDF sampling needs V above the surface; a normal facing away (NoV <= 0, which the BRDF
  // clamps to HV_MIN_NOV) samples with V lifted to NoV = 1e-4. Any sampler is unbiased here
  // since the cosine strategy covers the hemisphere and pdfs are evaluated consistently.
  glm::vec3 Vs = glm::normalize(glm::vec3(Vt.x, Vt.y, std::max(Vt.z, 1e-4f)));
  float NoV = glm::clamp(glm::dot(N, V), 1e-4f, 1.0f);  // as the ambient pass
  // The ambient specular's factors as the engine applies them (ambientSpecularScale, ibl.glsl),
  // with the energy compensation's E(NoV, roughness) integrated here rather than looked up in the
  // 128^2 table; see docs/reference.md.
  glm::vec2 ab(0.0f);
  if (settings.energy_compensation) ab = integrateEnvBrdfAt(NoV, s.roughness, 1024, ctx.brdf);
  const glm::vec3 ambient_spec_scale = glsl::ambientSpecularScale(
      s, ab, NoV, settings.energy_compensation, settings.specular_occlusion);

  Moments m[kReferenceAovCount];
  Moments total_m;  // of the per-sample sum of the AOVs
  ScalarMoments lum;
  ScalarMoments ao_m;
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
      // Area lights: per light one sample of the emitter's sampler and one GGX-VNDF direction
      // (shared by the lights), balance heuristic: each contributes f L NoL / (p_light + p_vndf).
      // Without the VNDF strategy a glossy surface's highlight of a small emitter is found by
      // few emitter samples (rare huge values, an underestimate in between).
      if (!ctx.area_lights.empty()) {
        glm::vec3 Lv(0.0f);
        bool vndf_ok = false;
        {
          glm::vec3 Ht = glsl::sampleGGXVNDF(Vs, s.alpha, glm::vec2(rng.uniform(), rng.uniform()));
          glm::vec3 lt = glm::reflect(-Vs, Ht);
          vndf_ok = lt.z > 0.0f;
          Lv = T * lt.x + B * lt.y + N * lt.z;
        }
        auto pdfVndf = [&](const glm::vec3& L) {
          glm::vec3 lt(glm::dot(L, T), glm::dot(L, B), glm::dot(L, N));
          if (lt.z <= 0.0f) return 0.0f;
          glm::vec3 h = glsl::safeNormalize(Vs + lt);
          float VoH = glm::dot(Vs, h);
          return VoH > 0.0f ? glsl::pdfGGXVNDF(Vs, h, s.alpha) / (4.0f * VoH) : 0.0f;
        };
        auto add = [&](const reference_detail::LightSample& ls, float p_vndf) {
          float NoL = glsl::saturate(glm::dot(N, ls.L));
          float p = ls.pdf + p_vndf;
          if (NoL <= 0.0f || !(p > 0.0f) || !std::isfinite(p)) return;  // below the horizon
          // The ray stops at the sampled emitter point: what lies behind the light does not
          // shadow it (and emitters are not triangles: the light itself never occludes).
          if (vis && occluded(ls.L, ls.distance)) return;
          Lobes f = brdfLobes(ctx.brdf, s, V, ls.L, true);
          glm::vec3 w = ls.radiance * (NoL * s.cavity / p);
          xs[kDD] += glm::dvec3(f.diffuse * w);
          xs[kDS] += glm::dvec3(f.specular * w);
        };
        for (const Light* l : ctx.area_lights) {
          const glm::vec2 u(rng.uniform(), rng.uniform());
          // Beyond the range window the light contributes exactly 0.
          if (reference_detail::windowDistance2(*l, P) >= l->range * l->range) continue;
          reference_detail::LightSample ls = reference_detail::sampleLight(*l, settings, P, u);
          if (ls.pdf > 0.0f) add(ls, pdfVndf(ls.L));
          if (vndf_ok) {
            reference_detail::LightSample lv = reference_detail::evalLight(*l, settings, P, Lv);
            if (lv.pdf > 0.0f) add(lv, pdfVndf(Lv));
          }
        }
      }
      // Environment: one cosine, one VNDF, (non-uniform environments) one luminance-sampled and
      // (sky) one sun-cone direction; balance heuristic with one sample per strategy: each
      // contributes f L NoL / (p_cos + p_vndf + p_env + p_sun).
      if (ctx.has_env) {
        glm::vec2 u1(rng.uniform(), rng.uniform());
        glm::vec2 u2(rng.uniform(), rng.uniform());
        glm::vec3 Lw[4];
        int count = 2;
        glm::vec3 lt0 = glsl::sampleCosineHemisphere(u1);
        Lw[0] = T * lt0.x + B * lt0.y + N * lt0.z;
        glm::vec3 Ht = glsl::sampleGGXVNDF(Vs, s.alpha, u2);
        glm::vec3 lt1 = glm::reflect(-Vs, Ht);
        Lw[1] = T * lt1.x + B * lt1.y + N * lt1.z;
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
        for (int k = 0; k < count; ++k) {
          const glm::vec3 L = glm::normalize(Lw[k]);
          const glm::vec3 lt(glm::dot(L, T), glm::dot(L, B), glm::dot(L, N));
          if (lt.z <= 0.0f) continue;
          glm::vec3 h = glsl::safeNormalize(Vs + lt);
          float VoH = glm::dot(Vs, h);
          float p_cos = glsl::pdfCosineHemisphere(lt.z);
          float p_spec = VoH > 0.0f ? glsl::pdfGGXVNDF(Vs, h, s.alpha) / (4.0f * VoH) : 0.0f;
          float p_env = ctx.env_dist ? ctx.env_dist->pdf(L) : 0.0f;
          float p_sun = ctx.has_sun && glm::dot(L, ctx.sun_dir) >= ctx.sun_cos ? ctx.sun_pdf : 0.0f;
          float p = p_cos + p_spec + p_env + p_sun;
          if (!(p > 0.0f) || !std::isfinite(p)) continue;
          if (vis && occluded(L, std::numeric_limits<float>::infinity())) continue;
          Lobes f = brdfLobes(ctx.brdf, s, V, L, false);
          glm::vec3 w = ctx.env.radiance(L) * (lt.z / p);
          xs[kAD] += glm::dvec3(f.diffuse * w * s.cavity);
          xs[kAS] += glm::dvec3(f.specular * w * ambient_spec_scale);
        }
      }
      // Ambient occlusion: a cosine-distributed direction, whose estimator (1/pi) V NoL / pdf is
      // the visibility V itself.
      if (vis) {
        const glm::vec3 lt =
            glsl::sampleCosineHemisphere(glm::vec2(ao_rng.uniform(), ao_rng.uniform()));
        const glm::vec3 L = glm::normalize(T * lt.x + B * lt.y + N * lt.z);
        ao_m.add(occluded(L, opt.ao_distance) ? 0.0 : 1.0);
      }
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
  if (vis) {
    out.ao = n > 0 ? ao_m.sum / double(n) : 1.0;
    out.ao_se = ao_m.stdError(n);
  }
  double y_mean = exact_lum + lum.sum / double(std::max(n, 1));
  out.rel_error = y_mean > 0.0 ? lum.stdError(n) / y_mean : 0.0;
  return out;
}

}  // namespace

ReferenceResult renderReference(const Scene& scene, const GBufferReadback& gb,
                                const ReferenceOptions& opt) {
  const auto t0 = std::chrono::steady_clock::now();
  const size_t count = size_t(std::max(gb.width, 0)) * size_t(std::max(gb.height, 0));
  if (gb.width <= 0 || gb.height <= 0 || gb.base_color.size() != count ||
      gb.metallic.size() != count || gb.roughness.size() != count || gb.cavity.size() != count ||
      gb.depth.size() != count || gb.normal.size() != count || gb.model.size() != count) {
    throw std::invalid_argument("renderReference: G-buffer readback of " +
                                std::to_string(gb.width) + "x" + std::to_string(gb.height) +
                                " has arrays of the wrong size");
  }

  Context ctx{};
  ctx.scene = &scene;
  ctx.gb = &gb;
  ctx.opt = &opt;
  ctx.brdf = BrdfConfig::fromSettings(scene.settings);
  ctx.inv_view_proj = referenceInvViewProj(scene.camera, gb.width, gb.height);
  if (scene.environment.kind != EnvironmentKind::None) {
    ctx.env = makeEnvSource(scene.environment, opt.sky);
    ctx.has_env = true;
    if (scene.environment.kind != EnvironmentKind::Uniform) {
      ctx.env_dist = std::make_unique<reference_detail::EnvDistribution>(ctx.env);
    }
    if (scene.environment.kind == EnvironmentKind::Sky) {
      // EnvSource::radiance looks up the unrotated sky at R(-rotation) dir: rotate the sun by +.
      const glm::vec3 d = skySunDirection(opt.sky);
      const float a = glm::radians(scene.environment.rotation_deg), c = std::cos(a),
                  sn = std::sin(a);
      ctx.sun_dir = glm::normalize(glm::vec3(c * d.x + sn * d.z, d.y, -sn * d.x + c * d.z));
      ctx.sun_cos = std::cos(glm::radians(opt.sky.sun_angular_radius_deg));
      ctx.sun_pdf = 1.0f / (6.2831853f * (1.0f - ctx.sun_cos));
      ctx.has_sun = std::isfinite(ctx.sun_pdf);
    }
  }
  if (opt.visibility) ctx.vis = std::make_unique<reference_detail::SceneVisibility>(scene);
  for (const Light& l : scene.lights) {
    if (l.type == LightType::Point)
      ctx.point_lights.push_back(&l);
    else
      ctx.area_lights.push_back(&l);
  }

  ReferenceResult r;
  r.image = makeImageRGBf(gb.width, gb.height);
  r.std_error = makeImageRGBf(gb.width, gb.height);
  for (int a = 0; a < kReferenceAovCount; ++a) {
    r.aov[a] = makeImageRGBf(gb.width, gb.height);
    r.aov_std_error[a] = makeImageRGBf(gb.width, gb.height);
  }
  r.ao = makeImageRGBf(gb.width, gb.height);
  r.ao_std_error = makeImageRGBf(gb.width, gb.height);
  r.samples.assign(count, 0);
  std::vector<double> rel_error(count, -1.0);
  std::atomic<uint64_t> rays{0};

  std::mutex progress_mutex;
  std::atomic<int> rows_done{0};
  int last_reported = -1;
  detail::parallelFor(gb.height, opt.threads, [&](int y) {
    uint64_t row_rays = 0;
    for (int x = 0; x < gb.width; ++x) {
      const size_t i = size_t(y) * size_t(gb.width) + size_t(x);
      const auto model = static_cast<ShadingModel>(gb.model[i]);
      if (model == ShadingModel::Background) {
        if (!ctx.has_env) continue;
        glm::vec2 uv((float(x) + 0.5f) / float(gb.width),
                     1.0f - (float(y) + 0.5f) / float(gb.height));
        // As the ambient pass: a point at small depth along the pixel's ray.
        glm::vec3 far_point = glsl::reconstructWorldPosition(uv, 1e-3f, ctx.inv_view_proj);
        r.image.px[i] = ctx.env.radiance(glm::normalize(far_point - scene.camera.position));
        continue;
      }
      if (model != ShadingModel::DefaultLit) continue;
      PixelOut p = shadePixel(ctx, i, x, y);
      glm::dvec3 total(0.0);
      for (int a = 0; a < kReferenceAovCount; ++a) {
        r.aov[a].px[i] = glm::vec3(p.aov[a]);
        r.aov_std_error[a].px[i] = glm::vec3(p.aov_se[a]);
        total += p.aov[a];
      }
      r.image.px[i] = glm::vec3(total);
      r.std_error.px[i] = glm::vec3(p.se);
      r.ao.px[i] = glm::vec3(float(p.ao));
      r.ao_std_error.px[i] = glm::vec3(float(p.ao_se));
      r.samples[i] = p.samples;
      row_rays += p.rays;
      if (luminance(total) > 0.0) rel_error[i] = p.rel_error;
    }
    rays += row_rays;
    const int done = ++rows_done;
    if (opt.progress) {
      std::lock_guard<std::mutex> lock(progress_mutex);
      const int pct = int(100.0 * done / gb.height);
      if (pct / 10 > last_reported / 10 || done == gb.height) {
        last_reported = pct;
        // Time left from the rows so far (rows cost alike on average).
        const double elapsed =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        std::fprintf(stderr,
                     "reference: %3d%% (%d of %d rows), %.0f s elapsed, about %.0f s left\n", pct,
                     done, gb.height, elapsed, elapsed * double(gb.height - done) / done);
      }
    }
  });

  ReferenceStats& st = r.stats;
  double rel_sum = 0.0;
  size_t rel_count = 0;
  st.min_samples = -1;
  for (size_t i = 0; i < count; ++i) {
    const auto model = static_cast<ShadingModel>(gb.model[i]);
    if (model == ShadingModel::Background) {
      ++st.background_pixels;
    } else if (model != ShadingModel::DefaultLit) {
      ++st.unlit_pixels;
    } else {
      ++st.lit_pixels;
      st.total_samples += uint64_t(r.samples[i]);
      st.min_samples = st.min_samples < 0 ? r.samples[i] : std::min(st.min_samples, r.samples[i]);
      st.max_samples = std::max(st.max_samples, r.samples[i]);
      if (rel_error[i] >= 0.0) {
        rel_sum += rel_error[i];
        ++rel_count;
        st.max_rel_error = std::max(st.max_rel_error, rel_error[i]);
      }
    }
  }
  if (st.min_samples < 0) st.min_samples = 0;
  st.visibility = opt.visibility;
  st.rays = rays.load();
  st.triangles = ctx.vis ? ctx.vis->triangles() : 0;
  st.mean_rel_error = rel_count ? rel_sum / double(rel_count) : 0.0;
  st.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (opt.progress && ctx.vis) {
    std::fprintf(stderr, "reference: visibility: %llu rays against %zu triangles\n",
                 static_cast<unsigned long long>(st.rays), st.triangles);
  }
  if (opt.progress) {
    std::fprintf(stderr,
                 "reference: %zu lit pixels, %llu samples (%d..%d per pixel), relative standard "
                 "error mean %.3g max %.3g, %.2f s\n",
                 st.lit_pixels, static_cast<unsigned long long>(st.total_samples), st.min_samples,
                 st.max_samples, st.mean_rel_error, st.max_rel_error, st.seconds);
  }
  return r;
}

}  // namespace hv
