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

#include "halfvec/core/parallel.hpp"
#include "halfvec/ibl/sky_sun.hpp"
#include "halfvec/shading/light_gpu.hpp"
#include "halfvec/shading/shading.hpp"
#include "pixel.hpp"

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

using reference_detail::Context;
using reference_detail::luminance;
using reference_detail::PixelOut;

namespace {

// What the pixels share: the BRDF, the camera, the environment and its samplers, the lights by
// kind, and (visibility) the scene's triangles.
Context makeContext(const Scene& scene, const GBufferReadback& gb, const ReferenceOptions& opt) {
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
      ctx.sun_dir = skySunWorldDirection(scene.environment, opt.sky);
      ctx.sun_cos = std::cos(glm::radians(opt.sky.sun_angular_radius_deg));
      ctx.sun_pdf = 1.0f / (6.2831853f * (1.0f - ctx.sun_cos));
      ctx.has_sun = opt.sky.sun_disk && std::isfinite(ctx.sun_pdf);
      ctx.sun_is_direct = ctx.has_sun && skySunIsLight(scene);
    }
    if (scene.environment.kind == EnvironmentKind::HdrFile && skySunIsLight(scene)) {
      SkyParams without = opt.sky;
      without.sun_disk = false;
      ctx.env_without_sun = makeEnvSource(scene.environment, without);
      ctx.hdr_sun_split = true;
    }
  }
  if (opt.visibility) ctx.vis = std::make_unique<reference_detail::SceneVisibility>(scene);
  // A spot is its point or sphere light times its cone, which scales what arrives at the shading
  // point from the whole emitter by the attenuation of the direction from the light's center
  // (docs/lights.md, "Spot lights"): exact for a point spot, the engine's definition for a sphere.
  ctx.spot_shapes.reserve(scene.lights.size());  // the lists point into it: no reallocation
  for (const Light& l : scene.lights) {
    const Light* shape = &l;
    glm::vec4 cone(0.0f, 0.0f, 0.0f, 1.0f);
    if (l.type == LightType::Spot) {
      ctx.spot_shapes.push_back(l);
      ctx.spot_shapes.back().type = lightShape(l);
      shape = &ctx.spot_shapes.back();
      cone = packLight(l).axis_length;
    }
    // A directional light of angular diameter 0 is one direction, exact as a point light; a
    // disk is sampled as an area light (emitters.cpp, sampleDirectional).
    const bool point = shape->type == LightType::Point ||
                       (shape->type == LightType::Directional && !(shape->angular_diameter > 0.0f));
    (point ? ctx.point_lights : ctx.area_lights).push_back(shape);
    (point ? ctx.point_cones : ctx.area_cones).push_back(cone);
  }
  return ctx;
}

// Pixel counts, samples and relative errors over the lit pixels (rel_error < 0: not counted).
void summarize(const GBufferReadback& gb, const std::vector<int>& samples,
               const std::vector<double>& rel_error, ReferenceStats& st) {
  double rel_sum = 0.0;
  size_t rel_count = 0;
  st.min_samples = -1;
  for (size_t i = 0; i < gb.model.size(); ++i) {
    const auto model = static_cast<ShadingModel>(gb.model[i]);
    if (model == ShadingModel::Background) {
      ++st.background_pixels;
    } else if (!isLit(model)) {
      ++st.unlit_pixels;
    } else {
      ++st.lit_pixels;
      st.total_samples += uint64_t(samples[i]);
      st.min_samples = st.min_samples < 0 ? samples[i] : std::min(st.min_samples, samples[i]);
      st.max_samples = std::max(st.max_samples, samples[i]);
      if (rel_error[i] >= 0.0) {
        rel_sum += rel_error[i];
        ++rel_count;
        st.max_rel_error = std::max(st.max_rel_error, rel_error[i]);
      }
    }
  }
  if (st.min_samples < 0) st.min_samples = 0;
  st.mean_rel_error = rel_count ? rel_sum / double(rel_count) : 0.0;
}

// Pixel i's estimates into the result's images (rel_error: of pixels with some light).
void store(const PixelOut& p, size_t i, ReferenceResult& r, std::vector<double>& rel_error) {
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
  if (luminance(total) > 0.0) rel_error[i] = p.rel_error;
}

void checkReadback(const GBufferReadback& gb, size_t count) {
  if (gb.width <= 0 || gb.height <= 0 || gb.base_color.size() != count ||
      gb.metallic.size() != count || gb.roughness.size() != count || gb.cavity.size() != count ||
      gb.depth.size() != count || gb.normal.size() != count || gb.model.size() != count) {
    throw std::invalid_argument("renderReference: G-buffer readback of " +
                                std::to_string(gb.width) + "x" + std::to_string(gb.height) +
                                " has arrays of the wrong size");
  }
}

// Every image of the result at the G-buffer's size, black.
ReferenceResult blankResult(int width, int height) {
  ReferenceResult r;
  r.image = makeImageRGBf(width, height);
  r.std_error = makeImageRGBf(width, height);
  for (int a = 0; a < kReferenceAovCount; ++a) {
    r.aov[a] = makeImageRGBf(width, height);
    r.aov_std_error[a] = makeImageRGBf(width, height);
  }
  r.ao = makeImageRGBf(width, height);
  r.ao_std_error = makeImageRGBf(width, height);
  r.samples.assign(size_t(width) * size_t(height), 0);
  return r;
}

// A background pixel shows the environment along its ray, found as the ambient pass finds it:
// through a point at small depth on the pixel.
glm::vec3 backgroundRadiance(const Context& ctx, int x, int y) {
  const GBufferReadback& gb = *ctx.gb;
  glm::vec2 uv((float(x) + 0.5f) / float(gb.width), 1.0f - (float(y) + 0.5f) / float(gb.height));
  glm::vec3 far_point = glsl::reconstructWorldPosition(uv, 1e-3f, ctx.inv_view_proj);
  return ctx.env.radiance(glm::normalize(far_point - ctx.scene->camera.position));
}

// A line on stderr at every 10% of the rows done, with the time left estimated from the rows so
// far (rows cost alike on average). Called from the worker threads.
class RowProgress {
 public:
  RowProgress(int rows, bool on, std::chrono::steady_clock::time_point t0)
      : rows_(rows), on_(on), t0_(t0) {}
  void rowDone() {
    const int done = ++done_;
    if (!on_) return;
    std::lock_guard<std::mutex> lock(mutex_);
    const int pct = int(100.0 * done / rows_);
    if (pct / 10 > last_reported_ / 10 || done == rows_) {
      last_reported_ = pct;
      const double elapsed =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count();
      std::fprintf(stderr, "reference: %3d%% (%d of %d rows), %.0f s elapsed, about %.0f s left\n",
                   pct, done, rows_, elapsed, elapsed * double(rows_ - done) / done);
    }
  }

 private:
  const int rows_;
  const bool on_;
  const std::chrono::steady_clock::time_point t0_;
  std::mutex mutex_;
  std::atomic<int> done_{0};
  int last_reported_ = -1;
};

void printSummary(const ReferenceStats& st, bool visibility) {
  if (visibility) {
    std::fprintf(stderr, "reference: visibility: %llu rays against %zu triangles\n",
                 static_cast<unsigned long long>(st.rays), st.triangles);
  }
  std::fprintf(stderr,
               "reference: %zu lit pixels, %llu samples (%d..%d per pixel), relative standard "
               "error mean %.3g max %.3g, %.2f s\n",
               st.lit_pixels, static_cast<unsigned long long>(st.total_samples), st.min_samples,
               st.max_samples, st.mean_rel_error, st.max_rel_error, st.seconds);
}

}  // namespace

ReferenceResult renderReference(const Scene& scene, const GBufferReadback& gb,
                                const ReferenceOptions& opt) {
  const auto t0 = std::chrono::steady_clock::now();
  const size_t count = size_t(std::max(gb.width, 0)) * size_t(std::max(gb.height, 0));
  checkReadback(gb, count);
  const Context ctx = makeContext(scene, gb, opt);
  ReferenceResult r = blankResult(gb.width, gb.height);
  std::vector<double> rel_error(count, -1.0);
  std::atomic<uint64_t> rays{0};
  RowProgress progress(gb.height, opt.progress, t0);
  detail::parallelFor(gb.height, opt.threads, [&](int y) {
    uint64_t row_rays = 0;
    for (int x = 0; x < gb.width; ++x) {
      const size_t i = size_t(y) * size_t(gb.width) + size_t(x);
      const auto model = static_cast<ShadingModel>(gb.model[i]);
      if (model == ShadingModel::Background) {
        if (ctx.has_env) r.image.px[i] = backgroundRadiance(ctx, x, y);
        continue;
      }
      if (!isLit(model)) continue;
      const PixelOut p = reference_detail::shadePixel(ctx, i, x, y);
      store(p, i, r, rel_error);
      row_rays += p.rays;
    }
    rays += row_rays;
    progress.rowDone();
  });

  ReferenceStats& st = r.stats;
  summarize(gb, r.samples, rel_error, st);
  st.visibility = opt.visibility;
  st.rays = rays.load();
  st.triangles = ctx.vis ? ctx.vis->triangles() : 0;
  st.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (opt.progress) printSummary(st, ctx.vis != nullptr);
  return r;
}

}  // namespace hv
