// The measurements behind `halfvec accuracy` (docs/accuracy.md): every approximation of the engine
// against the reference, as data. The command formats them (samples/app/accuracy_markdown.cpp).
// Functions that render need a current GL context.
#pragma once

#include <string>
#include <vector>

#include "halfvec/eval/error_fit.hpp"
#include "halfvec/eval/light_accuracy.hpp"
#include "halfvec/image/image.hpp"
#include "halfvec/scene/scene.hpp"

namespace hv::eval {

struct AccuracyOptions {
  bool quick = false;      // small grids and images, few samples (a smoke test; seconds)
  int threads = 0;         // CPU threads (0: all cores)
  std::string assets_dir;  // HV_ASSETS_DIR (HDR environments); empty: none
  std::string scenes_dir;  // the sample scenes (samples/scenes)
};

// Engine vs reference over a set of pixels (all three channels): as TermError (rel_error,
// bias, noise = the reference's relative standard error of the sum), plus pixel_noise = sum of
// the per-pixel standard errors / sum R (the part of rel_error that noise alone gives, about 0.8
// times it for Gaussian noise), the relative RMSE and the 99th percentile of the relative error.
struct LitStats {
  double rel_error = 0.0, bias = 0.0, noise = 0.0, pixel_noise = 0.0, ref_sum = 0.0;
  double rel_rmse = 0.0, p99_rel = 0.0;
  size_t pixels = 0;
};

// ---- Point lights: three point lights on a sphere and a floor, GPU render vs reference ----
struct PointLightAccuracy {
  int width = 0, height = 0;
  double reference_error = 0.0;  // the reference's reported standard error (0: closed form)
  struct Term {
    std::string name;
    size_t pixels = 0;
    double max_rel = 0.0, rel_rmse = 0.0, bias = 0.0;
  };
  std::vector<Term> terms;  // direct diffuse, direct specular
  double worst = 0.0;       // largest relative error over pixels with reference > 1e-3
};
PointLightAccuracy measurePointLights(const AccuracyOptions& o);

// ---- Sphere and tube light sweeps (light_accuracy.hpp), with their grids and timing ----
struct SphereAccuracy {
  SphereSweepGrid grid;
  std::vector<SphereSweepRow> rows;
  double seconds = 0.0;
};
SphereAccuracy measureSphereLights(const AccuracyOptions& o);
// Directional lights: the sphere sweep with a disk of angular radius asin(r) (grid.directional),
// from the sun's size to wide disks.
SphereAccuracy measureDirectionalLights(const AccuracyOptions& o);
struct TubeAccuracy {
  TubeSweepGrid grid;
  std::vector<TubeSweepRow> rows;
  double seconds = 0.0;
};
TubeAccuracy measureTubeLights(const AccuracyOptions& o);
// Capsules straddling the horizon: the tube sweep at elevations 5, 0 and -5 degrees, each with
// the radii whose capsule there crosses the surface plane (|sin e| < r; the axis is parallel to
// the surface, so the whole capsule straddles it).
struct TubeStraddlingAccuracy {
  std::vector<TubeAccuracy> elevations;  // grid.elevation_deg, grid.radius: those that straddle
  double seconds = 0.0;
};
TubeStraddlingAccuracy measureTubeStraddling(const AccuracyOptions& o);

// ---- The error budget (error_fit.hpp): the table's prediction and the budget's choice over the
// sphere sweep, per budget (the trade report's max_error values) ----
struct BudgetAccuracy {
  SphereSweepGrid grid;
  BudgetSweep sweep;
  double seconds = 0.0;
};
BudgetAccuracy measureBudget(const AccuracyOptions& o);

// ---- Clear coat: a coated sphere under each light type and the sky, per coat roughness ----
// Engine against the reference (both lobes, clear_coat.glsl) over the sphere's pixels, coated
// (weight 1) and the same pixels of the same sphere without the coat, per specular method.
struct ClearCoatAccuracy {
  int width = 0, height = 0, samples = 0;
  struct Row {
    std::string light;   // sphere, tube, sun (a directional light of the sun's size), sky
    std::string method;  // representative point, ltc, split sum
    float coat_roughness = 0.0f;
    LitStats coated, bare;
  };
  std::vector<Row> rows;
  double seconds = 0.0;
};
ClearCoatAccuracy measureClearCoat(const AccuracyOptions& o);
// The scene it measures (also the tests'): a sphere of base (0.6, 0.5, 0.4), roughness 0.6, under
// a coat of weight `coat` on a grey floor, seen from the front, lit by one light over the camera's
// right shoulder, `light` one of "point", "sphere" (radius 0.15 m), "tube" (0.8 m by 0.05 m),
// "sun" (a directional light of the sun's angular diameter), or "sky" (the sky alone); physical
// falloff.
Scene clearCoatScene(const std::string& light, float coat, float coat_roughness);

// ---- Ambient light: metallic and dielectric spheres per roughness, each environment ----
struct AmbientAccuracy {
  int width = 0, height = 0, samples = 0;
  struct Row {
    float roughness = 0.0f;
    LitStats specular_table, specular_approx, diffuse;  // split sum (table, EnvBRDFApprox), SH9
  };
  struct Env {
    std::string name, skipped;  // skipped: why it was not measured (no HDR files)
    std::vector<Row> rows;
  };
  std::vector<Env> envs;
  // EnvBRDFApprox (Karis 2014) vs the engine's table, f0 = 0.04 and 1, at every texel center.
  int table_size = 0;
  double mean_abs[2] = {0, 0}, max_abs[2] = {0, 0}, max_rel = 0.0;  // max_rel: f0 = 1
  std::string where_abs[2], where_rel;
};
AmbientAccuracy measureAmbient(const AccuracyOptions& o);

// ---- Sample scenes: engine vs reference per term, with a heat map of the relative error ----
struct SceneAccuracy {
  std::string name;
  int width = 0, height = 0, samples = 0;
  size_t lit_pixels = 0;
  double reference_mean_rel = 0.0, reference_max_rel = 0.0;  // the reference's own noise
  LitStats all;
  std::vector<std::pair<std::string, LitStats>> terms;  // per reference AOV with light in it
  ImageRGBA8 heat_map;                                  // relative error per pixel, 0 to 50%
};
std::vector<SceneAccuracy> measureScenes(const AccuracyOptions& o);

// ---- Summary: worst and typical error of each method of each light type and term ----
struct MethodSummary {
  std::string light, term, method;
  size_t count = 0;                  // configurations with light (reference > 0)
  double median = 0.0, worst = 0.0;  // rel. error over the views
  double worst_bias = 0.0;           // the bias of the worst configuration
  double peak_worst = 1.0;           // the peak ratio E/R farthest from 1
  std::string where;                 // the worst configuration
};
// Sphere methods over the configurations with the sphere above the horizon (straddling = true:
// over those straddling it); tube methods over every configuration.
std::vector<MethodSummary> summarizeSphere(const SphereAccuracy& a, bool straddling);
std::vector<MethodSummary> summarizeTube(const TubeAccuracy& a);

// The fraction of a method's configurations within `tol` of the reference at the peak (|E/R - 1|)
// and over the views (|bias|), restricted by `use` (e.g. a goal's grid); count = how many.
struct GoalCheck {
  size_t count = 0, within = 0;
  double worst_peak = 0.0, worst_bias = 0.0;  // largest |peak - 1| and |bias|
  std::string worst_peak_where, worst_bias_where;
};
GoalCheck checkSphereGoal(const SphereAccuracy& a, int method, double tol, float max_radius);
GoalCheck checkTubeGoal(const TubeAccuracy& a, int method, bool diffuse, double tol);
// Spheres straddling the horizon (elevation < asin(r/d), some of the sphere above it): the
// specular's bias over the views within tol (the peak view can lie below the surface).
GoalCheck checkStraddlingGoal(const SphereAccuracy& a, int method, double tol);
// The same for capsules (bias of the specular over the views, every straddling configuration).
GoalCheck checkTubeStraddlingGoal(const TubeStraddlingAccuracy& a, int method, double tol);

}  // namespace hv::eval
