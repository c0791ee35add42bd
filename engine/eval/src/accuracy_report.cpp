#include "halfvec/eval/accuracy_report.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>

#include "halfvec/eval/engine_aov.hpp"
#include "halfvec/ibl/ibl.hpp"
#include "halfvec/ibl/ibl_math.hpp"
#include "halfvec/image/metrics.hpp"
#include "halfvec/reference/reference.hpp"
#include "halfvec/render/renderer.hpp"
#include "halfvec/scene/primitives.hpp"
#include "halfvec/scene/scene_loader.hpp"
#include "lit_stats.hpp"

namespace hv::eval {

namespace fs = std::filesystem;

namespace {

using Mask = std::function<bool(size_t)>;

double secondsSince(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

std::string num(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%g", v);
  return b;
}

}  // namespace

// Images restricted to the pixels where `use` holds, packed into one row (for compareImages).
ErrorMetrics compareMasked(const ImageRGBf& e, const ImageRGBf& r, const Mask& use) {
  std::vector<glm::vec3> a, b;
  for (size_t i = 0; i < r.px.size(); ++i) {
    if (!use(i)) continue;
    a.push_back(e.px[i]);
    b.push_back(r.px[i]);
  }
  ImageRGBf ia = makeImageRGBf(int(std::max<size_t>(a.size(), 1)), 1);
  ImageRGBf ib = makeImageRGBf(int(std::max<size_t>(b.size(), 1)), 1);
  for (size_t i = 0; i < a.size(); ++i) {
    ia.px[i] = a[i];
    ib.px[i] = b[i];
  }
  return compareImages(ia, ib);
}

LitStats litStats(const ImageRGBf& e, const ImageRGBf& r, const ImageRGBf& se, const Mask& use) {
  LitStats s;
  double abs_sum = 0.0, signed_sum = 0.0, var = 0.0, se_sum = 0.0;
  for (size_t i = 0; i < r.px.size(); ++i) {
    if (!use(i)) continue;
    ++s.pixels;
    for (int c = 0; c < 3; ++c) {
      s.ref_sum += r.px[i][c];
      abs_sum += std::abs(double(e.px[i][c]) - r.px[i][c]);
      signed_sum += double(e.px[i][c]) - r.px[i][c];
      var += double(se.px[i][c]) * se.px[i][c];
      se_sum += se.px[i][c];
    }
  }
  if (s.ref_sum > 0.0) {
    s.pixel_noise = se_sum / s.ref_sum;
    s.rel_error = abs_sum / s.ref_sum;
    s.bias = signed_sum / s.ref_sum;
    s.noise = std::sqrt(var) / s.ref_sum;
    const ErrorMetrics m = compareMasked(e, r, use);
    s.rel_rmse = m.rel_rmse;
    s.p99_rel = m.p99_rel;
  }
  return s;
}

namespace {

Mask litMask(const GBufferReadback& g) {
  return [&g](size_t i) { return isLit(ShadingModel(g.model[i])); };
}

// A row of metallic spheres (f0 = 1: ambient specular alone) above a row of white dielectric
// spheres, one roughness per column, seen from the front, lit only by `env`.
Scene ambientScene(const Environment& env, const std::vector<float>& roughness) {
  Scene s;
  s.camera.position = {0.0f, 0.0f, 8.0f};
  s.camera.target = {0.0f, 0.0f, 0.0f};
  s.camera.fov_y_deg = 30.0f;
  const Mesh sphere = makeSphere(0.4f, 48, 24);
  const int n = int(roughness.size());
  for (int row = 0; row < 2; ++row) {
    for (int i = 0; i < n; ++i) {
      Material m;
      m.base_color = glm::vec3(1.0f);
      m.metallic = row == 0 ? 1.0f : 0.0f;
      m.roughness = roughness[size_t(i)];
      addMeshObject(s, sphere, m, {float(i) - 0.5f * float(n - 1), row == 0 ? 0.5f : -0.5f, 0.0f});
    }
  }
  s.environment = env;
  s.settings.falloff_plus_one = false;
  return s;
}

std::vector<AmbientAccuracy::Env> ambientEnvironments(const AccuracyOptions& o,
                                                      std::vector<Environment>& envs) {
  std::vector<AmbientAccuracy::Env> out(1);
  out[0].name = "uniform (radiance 1)";
  Environment uni;
  uni.kind = EnvironmentKind::Uniform;
  uni.color = glm::vec3(1.0f);
  envs.push_back(uni);
  const fs::path env_dir = fs::path(o.assets_dir) / "env";
  std::vector<fs::path> hdrs;
  std::error_code ec;
  if (!o.assets_dir.empty() && fs::is_directory(env_dir, ec)) {
    for (auto& e : fs::directory_iterator(env_dir, ec)) {
      if (e.path().extension() == ".hdr") hdrs.push_back(e.path());
    }
  }
  std::sort(hdrs.begin(), hdrs.end());
  if (hdrs.empty()) {
    AmbientAccuracy::Env sk;
    sk.name = "HDR environments";
    sk.skipped = "no .hdr in " + env_dir.string() + " (set HV_ASSETS_DIR)";
    out.push_back(sk);
    envs.push_back({});
  }
  if (o.quick && !hdrs.empty()) hdrs.resize(1);
  for (auto& p : hdrs) {
    AmbientAccuracy::Env e;
    e.name = p.filename().string();
    out.push_back(e);
    Environment env;
    env.kind = EnvironmentKind::HdrFile;
    env.path = p.string();
    envs.push_back(env);
  }
  return out;
}

void measureAmbientEnv(const AccuracyOptions& o, const Environment& env,
                       const std::vector<float>& roughness, AmbientAccuracy& a,
                       AmbientAccuracy::Env& out) {
  Scene s = ambientScene(env, roughness);
  if (o.quick) {
    s.environment.cube_size = 64;
    s.environment.prefilter_samples = 64;
  }
  render::Renderer r;
  r.setScene(s);
  const auto aov = renderEngineAovs(r, a.width, a.height);
  s.settings.env_brdf = EnvBrdf::Analytic;
  const auto aov_approx = renderEngineAovs(r, a.width, a.height);
  s.settings.env_brdf = EnvBrdf::Table;
  const auto g = r.readGBuffer();
  ReferenceOptions ro;
  ro.samples = a.samples;
  ro.threads = o.threads;
  const ReferenceResult ref = renderReference(s, g, ro);
  const auto AS = ReferenceAov::AmbientSpecular, AD = ReferenceAov::AmbientDiffuse;
  for (float rough : roughness) {
    auto group = [&](bool metal) -> Mask {
      return [&g, metal, rough](size_t i) {
        return isLit(ShadingModel(g.model[i])) && (g.metallic[i] > 0.5f) == metal &&
               std::abs(g.roughness[i] - rough) < 0.01f;
      };
    };
    AmbientAccuracy::Row row;
    row.roughness = rough;
    row.specular_table = litStats(aov[size_t(AS)], ref[AS], ref.stdError(AS), group(true));
    row.specular_approx = litStats(aov_approx[size_t(AS)], ref[AS], ref.stdError(AS), group(true));
    row.diffuse = litStats(aov[size_t(AD)], ref[AD], ref.stdError(AD), group(false));
    out.rows.push_back(row);
  }
}

// EnvBRDFApprox vs the table the engine bakes.
void measureEnvBrdfApprox(const AccuracyOptions& o, AmbientAccuracy& a) {
  const int size = o.quick ? 32 : 128;
  a.table_size = size;
  const auto table = integrateEnvBrdf(size, o.quick ? 128 : 1024, std::max(o.threads, 1));
  double sum_abs[2] = {0, 0};
  for (int j = 0; j < size; ++j) {
    for (int i = 0; i < size; ++i) {
      const float NoV = (float(i) + 0.5f) / float(size), rough = (float(j) + 0.5f) / float(size);
      const glm::vec2 t = table[size_t(j) * size_t(size) + size_t(i)];
      const glm::vec2 ap = glsl::EnvBRDFApproxScaleBias(rough, NoV);
      const std::string where = "NoV " + num(std::round(NoV * 1000.0) / 1000.0) + ", roughness " +
                                num(std::round(rough * 1000.0) / 1000.0);
      const float f0s[2] = {0.04f, 1.0f};
      for (int k = 0; k < 2; ++k) {
        const double tv = f0s[k] * t.x + t.y, av = f0s[k] * ap.x + ap.y;
        const double d = std::abs(av - tv);
        sum_abs[k] += d;
        if (d > a.max_abs[k]) {
          a.max_abs[k] = d;
          a.where_abs[k] = where;
        }
        if (k == 1 && tv > 0.0 && d / tv > a.max_rel) {
          a.max_rel = d / tv;
          a.where_rel = where;
        }
      }
    }
  }
  for (int k = 0; k < 2; ++k) a.mean_abs[k] = sum_abs[k] / (double(size) * size);
}

// The median and worst of one method over rows, with the configuration of the worst.
template <class Row>
MethodSummary summarize(const std::vector<Row>& rows, const std::function<bool(const Row&)>& use,
                        const std::function<const TermError&(const Row&)>& pick,
                        const std::function<std::string(const Row&)>& where) {
  MethodSummary m;
  std::vector<double> errs;
  for (const Row& r : rows) {
    const TermError& t = pick(r);
    if (!use(r) || !t.valid) continue;
    errs.push_back(t.rel_error);
    if (t.rel_error >= m.worst) {
      m.worst = t.rel_error;
      m.worst_bias = t.bias;
      m.where = where(r);
    }
    if (std::abs(t.peak - 1.0) > std::abs(m.peak_worst - 1.0)) m.peak_worst = t.peak;
  }
  m.count = errs.size();
  if (!errs.empty()) {
    std::nth_element(errs.begin(), errs.begin() + long(errs.size() / 2), errs.end());
    m.median = errs[errs.size() / 2];
  }
  return m;
}

std::string sphereWhere(const SphereSweepRow& r) {
  return "roughness " + num(r.roughness) + ", r/d " + num(r.radius) + ", elevation " +
         num(r.elevation_deg);
}
std::string tubeWhere(const TubeSweepRow& r) {
  return "roughness " + num(r.roughness) + ", len " + num(r.length) + ", r " + num(r.radius) +
         (r.along ? ", along" : ", across");
}

void checkTerm(const TermError& t, const std::string& where, double tol, GoalCheck& c) {
  if (!t.valid) return;
  ++c.count;
  const double p = std::abs(t.peak - 1.0), b = std::abs(t.bias);
  if (p <= tol && b <= tol) ++c.within;
  if (p > c.worst_peak) {
    c.worst_peak = p;
    c.worst_peak_where = where;
  }
  if (b > c.worst_bias) {
    c.worst_bias = b;
    c.worst_bias_where = where;
  }
}

}  // namespace

PointLightAccuracy measurePointLights(const AccuracyOptions& o) {
  Scene s;
  s.camera.position = {0.0f, 2.0f, 3.0f};
  s.camera.target = {0.0f, 0.0f, 0.0f};
  Material m;
  m.base_color = {0.6f, 0.5f, 0.4f};
  m.roughness = 0.35f;
  m.metallic = 0.2f;
  addMeshObject(s, makeSphere(0.8f, 48, 24), m, {0.0f, 0.8f, 0.0f});
  addMeshObject(s, makePlane(6.0f, 6.0f), m, glm::vec3(0.0f));
  for (int k = 0; k < 3; ++k) {
    Light l;
    l.position = {1.5f * float(k - 1), 1.0f + 0.6f * float(k), 1.0f - float(k)};
    l.intensity = 3.0f + float(k);
    l.range = 8.0f;
    s.lights.push_back(l);
  }
  s.environment.kind = EnvironmentKind::None;
  s.settings.falloff_plus_one = false;
  PointLightAccuracy a;
  a.width = o.quick ? 64 : 240;
  a.height = o.quick ? 48 : 180;
  render::Renderer r;
  r.setScene(s);
  const auto aov = renderEngineAovs(r, a.width, a.height);
  const auto g = r.readGBuffer();
  ReferenceOptions ro;
  ro.samples = 4;
  ro.threads = o.threads;
  const ReferenceResult ref = renderReference(s, g, ro);
  a.reference_error = ref.stats.max_rel_error;
  const Mask lit = litMask(g);
  for (int k : {0, 1}) {
    const auto which = static_cast<ReferenceAov>(k);
    PointLightAccuracy::Term t;
    t.name = std::string(toString(which));
    for (size_t i = 0; i < g.model.size(); ++i) {
      if (!lit(i)) continue;
      for (int c = 0; c < 3; ++c) {
        const double rv = ref[which].px[i][c];
        if (rv > 1e-3) t.max_rel = std::max(t.max_rel, std::abs(aov[k].px[i][c] - rv) / rv);
      }
    }
    const LitStats ls = litStats(aov[k], ref[which], ref.stdError(which), lit);
    t.pixels = ls.pixels;
    t.rel_rmse = ls.rel_rmse;
    t.bias = ls.bias;
    a.worst = std::max(a.worst, t.max_rel);
    a.terms.push_back(t);
  }
  return a;
}

namespace {

// The sphere sweep's grid: the full one at 4096 samples, or a quick one.
SphereSweepGrid sphereGrid(const AccuracyOptions& o) {
  SphereSweepGrid g;
  g.threads = o.threads;
  if (o.quick) {
    g.roughness = {0.1f, 0.5f};
    g.radius = {0.1f, 0.5f};
    g.elevation_deg = {45.0f, 5.0f};
    g.samples = 256;
  } else {
    g.samples = 4096;
  }
  return g;
}

}  // namespace

SphereAccuracy measureSphereLights(const AccuracyOptions& o) {
  SphereAccuracy a;
  a.grid = sphereGrid(o);
  const auto t0 = std::chrono::steady_clock::now();
  a.rows = sweepSphere(a.grid);
  a.seconds = secondsSince(t0);
  return a;
}

BudgetAccuracy measureBudget(const AccuracyOptions& o) {
  BudgetAccuracy a;
  a.grid = sphereGrid(o);  // the sphere sweep's configurations
  const auto t0 = std::chrono::steady_clock::now();
  a.sweep = sweepBudget(a.grid, {0.01, 0.02, 0.05, 0.1, 0.2});
  a.seconds = secondsSince(t0);
  return a;
}

SphereAccuracy measureDirectionalLights(const AccuracyOptions& o) {
  SphereAccuracy a;
  a.grid.threads = o.threads;
  a.grid.directional = true;
  // sin(sigma): the sun's (angular diameter kSunAngularDiameter), then disks of 5.7, 29 and 60
  // degrees.
  const float sun = std::sin(0.5f * kSunAngularDiameter);
  if (o.quick) {
    a.grid.roughness = {0.1f, 0.5f};
    a.grid.radius = {sun, 0.25f};
    a.grid.elevation_deg = {45.0f, 5.0f};
    a.grid.samples = 256;
  } else {
    a.grid.roughness = {0.05f, 0.1f, 0.2f, 0.35f, 0.5f, 1.0f};
    a.grid.radius = {sun, 0.05f, 0.25f, 0.5f};
    a.grid.elevation_deg = {90.0f, 45.0f, 15.0f, 5.0f, 0.0f};
    a.grid.samples = 4096;
  }
  const auto t0 = std::chrono::steady_clock::now();
  a.rows = sweepSphere(a.grid);
  a.seconds = secondsSince(t0);
  return a;
}

TubeAccuracy measureTubeLights(const AccuracyOptions& o) {
  TubeAccuracy a;
  a.grid.threads = o.threads;
  if (o.quick) {
    a.grid.roughness = {0.2f, 0.6f};
    a.grid.length = {0.5f, 2.0f};
    a.grid.radius = {0.05f};
    a.grid.samples = 256;
  } else {
    a.grid.samples = 4096;
  }
  const auto t0 = std::chrono::steady_clock::now();
  a.rows = sweepTube(a.grid);
  a.seconds = secondsSince(t0);
  return a;
}

TubeStraddlingAccuracy measureTubeStraddling(const AccuracyOptions& o) {
  TubeStraddlingAccuracy s;
  const auto t0 = std::chrono::steady_clock::now();
  for (float e : {5.0f, 0.0f, -5.0f}) {
    TubeAccuracy a;
    a.grid.threads = o.threads;
    a.grid.elevation_deg = e;
    a.grid.samples = o.quick ? 256 : 4096;
    if (o.quick) {
      a.grid.roughness = {0.2f, 0.6f};
      a.grid.length = {0.5f, 2.0f};
    }
    const float h = std::abs(std::sin(glm::radians(e)));  // the axis's height at distance 1
    std::vector<float> radii;
    for (float r : {0.01f, 0.05f, 0.2f}) {
      if (h < r) radii.push_back(r);
    }
    a.grid.radius = radii;
    const auto t1 = std::chrono::steady_clock::now();
    a.rows = sweepTube(a.grid);
    // A capsule along the plane of incidence long enough to pass over the shading point holds
    // it (the axis |sin e| from it): the shading point inside the light, no straddling case.
    std::erase_if(a.rows, [e](const TubeSweepRow& r) {
      return r.along && 0.5f * r.length >= std::cos(glm::radians(e)) - r.radius;
    });
    a.seconds = secondsSince(t1);
    s.elevations.push_back(std::move(a));
  }
  s.seconds = secondsSince(t0);
  return s;
}

AmbientAccuracy measureAmbient(const AccuracyOptions& o) {
  AmbientAccuracy a;
  const std::vector<float> roughness =
      o.quick ? std::vector<float>{0.1f, 0.6f}
              : std::vector<float>{0.05f, 0.1f, 0.25f, 0.5f, 0.75f, 1.0f};
  a.width = o.quick ? 96 : 320;
  a.height = o.quick ? 54 : 180;
  a.samples = o.quick ? 16 : 512;
  std::vector<Environment> envs;
  a.envs = ambientEnvironments(o, envs);
  for (size_t i = 0; i < a.envs.size(); ++i) {
    if (a.envs[i].skipped.empty()) measureAmbientEnv(o, envs[i], roughness, a, a.envs[i]);
  }
  measureEnvBrdfApprox(o, a);
  return a;
}

std::vector<SceneAccuracy> measureScenes(const AccuracyOptions& o) {
  const std::vector<std::string> names =
      o.quick ? std::vector<std::string>{"default"}
              : std::vector<std::string>{"default", "sphere_grid", "area_lights", "gltf"};
  std::vector<SceneAccuracy> out;
  for (const std::string& name : names) {
    SceneAccuracy a;
    a.name = name;
    a.width = o.quick ? 96 : 320;
    a.samples = o.quick ? 4 : 128;
    Scene s = loadScene((fs::path(o.scenes_dir) / (name + ".json")).string(),
                        {"settings.falloff_plus_one=false"});
    a.height = std::max(
        1, int(std::lround(double(a.width) * s.settings.height / std::max(1, s.settings.width))));
    render::Renderer r;
    r.setScene(s);
    const auto aov = renderEngineAovs(r, a.width, a.height);
    const auto g = r.readGBuffer();
    ReferenceOptions ro;
    ro.samples = a.samples;
    ro.threads = o.threads;
    const ReferenceResult ref = renderReference(s, g, ro);
    ImageRGBf engine = makeImageRGBf(a.width, a.height);
    for (const auto& t : aov)
      for (size_t i = 0; i < t.px.size(); ++i) engine.px[i] += t.px[i];
    const Mask lit = litMask(g);
    ImageRGBf refimg = ref.image;
    for (size_t i = 0; i < refimg.px.size(); ++i) {
      if (!lit(i)) refimg.px[i] = glm::vec3(0.0f);
    }
    a.heat_map = relativeErrorHeatMap(engine, refimg, 0.5f);
    a.lit_pixels = ref.stats.lit_pixels;
    a.reference_mean_rel = ref.stats.mean_rel_error;
    a.reference_max_rel = ref.stats.max_rel_error;
    a.all = litStats(engine, refimg, ref.std_error, lit);
    for (int k = 0; k < kReferenceAovCount; ++k) {
      const auto which = static_cast<ReferenceAov>(k);
      const LitStats t = litStats(aov[size_t(k)], ref[which], ref.stdError(which), lit);
      if (t.ref_sum > 0.0) a.terms.push_back({std::string(toString(which)), t});
    }
    out.push_back(std::move(a));
  }
  return out;
}

std::vector<MethodSummary> summarizeSphere(const SphereAccuracy& a, bool straddling) {
  std::vector<MethodSummary> out;
  auto use = [straddling](const SphereSweepRow& r) { return r.above() != straddling; };
  for (size_t k = 0; k < sphereDiffuseMethods().size(); ++k) {
    MethodSummary m = summarize<SphereSweepRow>(
        a.rows, use, [k](const SphereSweepRow& r) -> const TermError& { return r.diffuse[k]; },
        sphereWhere);
    m.light = "sphere";
    m.term = "diffuse";
    m.method = sphereDiffuseMethods()[k].name;
    out.push_back(m);
  }
  for (size_t k = 0; k < sphereSpecularMethods().size(); ++k) {
    MethodSummary m = summarize<SphereSweepRow>(
        a.rows, use, [k](const SphereSweepRow& r) -> const TermError& { return r.specular[k]; },
        sphereWhere);
    m.light = "sphere";
    m.term = "specular";
    m.method = sphereSpecularMethods()[k].name;
    out.push_back(m);
  }
  return out;
}

std::vector<MethodSummary> summarizeTube(const TubeAccuracy& a) {
  std::vector<MethodSummary> out;
  auto all = [](const TubeSweepRow&) { return true; };
  for (size_t k = 0; k < tubeDiffuseMethods().size(); ++k) {
    MethodSummary m = summarize<TubeSweepRow>(
        a.rows, all, [k](const TubeSweepRow& r) -> const TermError& { return r.diffuse[k]; },
        tubeWhere);
    m.light = "tube";
    m.term = "diffuse";
    m.method = tubeDiffuseMethods()[k].name;
    out.push_back(m);
  }
  for (size_t k = 0; k < tubeSpecularMethods().size(); ++k) {
    MethodSummary m = summarize<TubeSweepRow>(
        a.rows, all, [k](const TubeSweepRow& r) -> const TermError& { return r.specular[k]; },
        tubeWhere);
    m.light = "tube";
    m.term = "specular";
    m.method = tubeSpecularMethods()[k].name;
    out.push_back(m);
  }
  return out;
}

GoalCheck checkSphereGoal(const SphereAccuracy& a, int method, double tol, float max_radius) {
  GoalCheck c;
  for (const SphereSweepRow& r : a.rows) {
    if (r.above() && r.radius <= max_radius)
      checkTerm(r.specular[size_t(method)], sphereWhere(r), tol, c);
  }
  return c;
}

GoalCheck checkStraddlingGoal(const SphereAccuracy& a, int method, double tol) {
  GoalCheck c;
  for (const SphereSweepRow& r : a.rows) {
    if (r.above()) continue;
    TermError t = r.specular[size_t(method)];
    t.peak = 1.0;  // a bias-only goal
    checkTerm(t, sphereWhere(r), tol, c);
  }
  return c;
}

GoalCheck checkTubeStraddlingGoal(const TubeStraddlingAccuracy& a, int method, double tol) {
  GoalCheck c;
  for (const TubeAccuracy& e : a.elevations) {
    for (const TubeSweepRow& r : e.rows) {
      TermError t = r.specular[size_t(method)];
      t.peak = 1.0;  // a bias-only goal
      checkTerm(t, tubeWhere(r) + ", elevation " + num(e.grid.elevation_deg), tol, c);
    }
  }
  return c;
}

GoalCheck checkTubeGoal(const TubeAccuracy& a, int method, bool diffuse, double tol) {
  GoalCheck c;
  for (const TubeSweepRow& r : a.rows) {
    const TermError& t = diffuse ? r.diffuse[size_t(method)] : r.specular[size_t(method)];
    if (diffuse) {
      // Diffuse: the bias over the views (the peak view is the specular's mirror view).
      TermError d = t;
      d.peak = 1.0;
      checkTerm(d, tubeWhere(r), tol, c);
    } else {
      checkTerm(t, tubeWhere(r), tol, c);
    }
  }
  return c;
}

}  // namespace hv::eval
