// Accuracy of the engine's sphere and tube lights, per shading configuration, on the CPU: the
// engine's own formula (shaders/common/lights.glsl compiled as C++ with the option under test,
// one term at a time) against the exact integral over the emitter of docs/lights.md (Monte Carlo:
// the reference renderer's emitter sampling combined with GGX visible-normal sampling by multiple
// importance sampling). Both with the physical falloff (falloff_plus_one = false) and the BRDF
// terms of the method measured. Used by `halfvec accuracy` (docs/accuracy.md) and tests/eval.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "halfvec/eval/light_variants.hpp"
#include "halfvec/scene/scene.hpp"

namespace hv::eval {

// The engine's outgoing radiance toward V (unit, from P) from `light` for one term only
// (HV_DIRECT_TERMS = 1 or 2), with HV_FALLOFF_PLUS_ONE = 0 and cavity 1: glsl::evaluateLight
// compiled as the entry `variant` of kEngineLightVariants (light_variants.hpp, engine_lights.cpp).
glm::vec3 engineLightTerm(CompiledLightVariant variant, const Light& light, const glm::vec3& P,
                          const glm::vec3& N, const glm::vec3& V, const glm::vec3& base_color,
                          float metallic, float roughness);
// The entry that runs `term` with options `o` (the options the term does not read match any
// value). Throws std::invalid_argument naming the options and values that no entry has, and how
// the nearest entry differs, for a combination that is not in kEngineLightVariants; a request
// known at compile time uses compiledLightVariant instead, which does not compile then.
CompiledLightVariant findLightVariant(LightTerm term, const EngineLightOptions& o);
// The same for options chosen at run time: the term of the entry findLightVariant(term, o).
glm::vec3 engineLightTerm(const EngineLightOptions& o, LightTerm term, const Light& light,
                          const glm::vec3& P, const glm::vec3& N, const glm::vec3& V,
                          const glm::vec3& base_color, float metallic, float roughness);

// Monte Carlo value of the exact direct light of a sphere or tube light (the emitter of
// docs/lights.md with the physical falloff) at P, split into diffuse and specular, each with its
// standard error. `samples` pairs of directions: one from the emitter (reference_detail::
// sampleLight), one GGX-VNDF direction traced against the emitter; specular combines both by the
// balance heuristic, diffuse uses the emitter's samples only.
struct LightIntegral {
  glm::dvec3 diffuse{0.0}, specular{0.0};
  glm::dvec3 diffuse_se{0.0}, specular_se{0.0};
};
// The surface is given by its diffuse color and f0 directly (the sweep integrates a white
// diffuse and a white specular lobe, f0 = 1, at once); roughness as makeSurface clamps it. The
// BRDF's D and V terms are `d` and `v` (the engine's defaults otherwise: Schlick-GGX V with the
// Disney remap, as analytic lights use it).
LightIntegral integrateLight(const Light& light, const glm::vec3& P, const glm::vec3& N,
                             const glm::vec3& V, const glm::vec3& diffuse_color,
                             const glm::vec3& f0, float roughness, int samples, uint64_t seed,
                             DistributionTerm d = DistributionTerm::GGX,
                             VisibilityTerm v = VisibilityTerm::SchlickGGX);

// Error of one term of one engine variant over a set of views of one configuration. Values are
// the red channel (lights and surfaces are white). With E_v the engine, R_v the reference:
//   rel_error = sum_v |E_v - R_v| / sum_v R_v,   bias = sum_v (E_v - R_v) / sum_v R_v (> 0: too
//   bright), peak = E_0 / R_0 at the first view (the mirror direction of the light center),
//   noise = sqrt(sum_v se_v^2) / sum_v R_v (the reference's relative standard error of the sum).
// valid = false when sum_v R_v = 0 (a light entirely below the horizon); engine_sum then says
// whether the engine leaks light there.
struct TermError {
  bool valid = false;
  double rel_error = 0.0, bias = 0.0, peak = 0.0, noise = 0.0;
  double engine_sum = 0.0, reference_sum = 0.0;
};
TermError termError(const std::vector<double>& engine, const std::vector<double>& reference,
                    const std::vector<double>& reference_se);

// Views of a configuration: the mirror direction of `light_dir` about N = +z (elevation clamped to
// >= 2 degrees), rings of 8 views at 1 and 2 `footprint` (radians) around it, and 8 fixed views
// (elevations 30 and 60 degrees, 4 azimuths); views within 1 degree of the horizon are dropped.
std::vector<glm::vec3> sweepViews(const glm::vec3& light_dir, float footprint);
// The sphere sweep's views of a sphere of r/d `radius` in direction `dir` over a lobe of
// `roughness`: sweepViews with the footprint 2 alpha + asin(r/d).
std::vector<glm::vec3> sphereSweepViews(const glm::vec3& dir, float roughness, float radius);
// The sweeps' light of `type`: white, intensity 1, no window at the distances swept.
Light sweepLight(LightType type);
// A sphere of r/d `radius` at `elevation_deg` lies entirely above the horizon.
bool sphereAboveHorizon(float radius, float elevation_deg);

// One way of shading one term, as the sweeps compare them; each is measured against the
// reference of its own BRDF terms (o.d, o.v). `variant` is the entry of kEngineLightVariants that
// runs it, found at compile time (a method whose options are not compiled does not build).
struct LightMethod {
  std::string name;
  EngineLightOptions o;
  CompiledLightVariant variant;
};
// The sweeps' methods, in this order (the rows' vectors follow it).
enum SphereDiffuseMethod { kSphereDiffuseKaris, kSphereDiffuseHorizon, kSphereDiffuseMethods };
enum SphereSpecularMethod {
  kSphereRp,             // representative point + (alpha/alpha')^2 (the default), Schlick-GGX V
  kSphereRpPlain,        // representative point without the normalization
  kSphereLtc,            // LTC with the lobe it is fitted to (height-correlated Smith V)
  kSphereRpSmith,        // representative point + normalization with that same lobe
  kSphereLtcSchlick,     // LTC with the default V (Schlick-GGX), magnitude scaled by the V ratio
  kSphereLtcSchlickRaw,  // the same without the V ratio
  kSphereLtcBeckmann,    // LTC (a GGX lobe) against a Beckmann-D reference (V Schlick-GGX, ratio)
  kSphereSpecularMethods
};
enum TubeDiffuseMethod { kTubeDiffuseKaris, kTubeDiffuseLtc, kTubeDiffuseMethods };
enum TubeSpecularMethod {
  kTubeRp,             // eq. 19 + normalization (the default), Schlick-GGX V
  kTubeRpPlain,        // eq. 19 without normalization
  kTubeRpEq18,         // eq. 18 + normalization
  kTubeRpEq18Plain,    // eq. 18 without normalization
  kTubeLtc,            // LTC, height-correlated Smith V
  kTubeRpSmith,        // eq. 19 + normalization, height-correlated Smith V
  kTubeLtcSchlick,     // LTC, Schlick-GGX V with the V ratio
  kTubeLtcSchlickRaw,  // LTC, Schlick-GGX V without it
  kTubeLtcBeckmann,    // LTC against a Beckmann-D reference
  kTubeSpecularMethods
};
const std::vector<LightMethod>& sphereDiffuseMethods();
const std::vector<LightMethod>& sphereSpecularMethods();
const std::vector<LightMethod>& tubeDiffuseMethods();
const std::vector<LightMethod>& tubeSpecularMethods();

// ---- Sphere light sweep: roughness x radius/distance x elevation of the center ----
struct SphereSweepGrid {
  std::vector<float> roughness{0.05f, 0.1f, 0.2f, 0.35f, 0.5f, 0.75f, 1.0f};
  std::vector<float> radius{0.01f, 0.05f, 0.1f, 0.25f, 0.5f, 0.98f};  // distance to center = 1
  std::vector<float> elevation_deg{90.0f, 45.0f, 30.0f, 15.0f, 5.0f, 0.0f, -5.0f};
  int samples = 2048;
  uint64_t seed = 1;
  int threads = 0;
  // The light is a directional light whose disk subtends the sphere's cone (angular radius
  // asin(radius)) instead of the sphere at distance 1, with illuminance 1 at normal incidence
  // (docs/lights.md, "Directional lights": the same cone, the same code).
  bool directional = false;
};
struct SphereSweepRow {
  float roughness = 0.0f, radius = 0.0f, elevation_deg = 0.0f;
  std::vector<TermError> diffuse;   // [SphereDiffuseMethod]
  std::vector<TermError> specular;  // [SphereSpecularMethod]
  // Entirely above the horizon: elevation >= the sphere's angular radius asin(r/d).
  bool above() const;
};
std::vector<SphereSweepRow> sweepSphere(const SphereSweepGrid& grid);

// ---- Tube light sweep: roughness x length x radius x orientation (center at distance 1,
// elevation 45 degrees, axis parallel to the surface, across (y) or along (x) the plane of
// incidence) ----
struct TubeSweepGrid {
  std::vector<float> roughness{0.05f, 0.1f, 0.2f, 0.35f, 0.5f, 0.75f, 1.0f};
  std::vector<float> length{0.25f, 0.5f, 1.0f, 2.0f};
  std::vector<float> radius{0.01f, 0.05f, 0.2f};
  float elevation_deg = 45.0f;
  int samples = 2048;
  uint64_t seed = 1;
  int threads = 0;
};
struct TubeSweepRow {
  float roughness = 0.0f, length = 0.0f, radius = 0.0f;
  bool along = false;               // axis along the plane of incidence (else across it)
  std::vector<TermError> diffuse;   // [TubeDiffuseMethod]
  std::vector<TermError> specular;  // [TubeSpecularMethod]
};
std::vector<TubeSweepRow> sweepTube(const TubeSweepGrid& grid);

}  // namespace hv::eval
