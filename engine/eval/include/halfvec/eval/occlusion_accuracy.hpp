// `halfvec accuracy`'s occlusion section: the engine's screen-space ambient occlusion (settings.ao,
// docs/ambient-occlusion.md) and its ambient terms against the reference with environment
// visibility (ReferenceOptions::visibility), environment light only, on a sphere resting on a
// plane, a box corner and stairs under a uniform environment, and DamagedHelmet under the HDR
// environments of the shared assets (skipped with the reason when absent). Returns data; the
// markdown is the app's (samples/app/accuracy_markdown_occlusion.cpp).
#pragma once

#include <string>
#include <vector>

#include "halfvec/eval/accuracy_report.hpp"
#include "halfvec/scene/render_settings.hpp"

namespace hv::eval {

// Engine against reference over the lit pixels of one scene, one configuration.
//   ao_mean_abs, ao_bias: mean |engine AO - reference AO| and mean (engine - reference), where
//     the engine's AO is its ambient diffuse over the same frame's with `ao: none` (exactly the
//     factor it applies without the multi-bounce fit) and the reference's is its AO image with
//     ao_distance = ao_radius;
//   ambient / diffuse / specular: sum |E - R| / sum R over pixels and channels (the relative
//     error of accuracy_report.hpp's LitStats) of the environment's light (diffuse + specular),
//     each term alone, against the reference's shadowed terms (all distances occlude). The
//     environment's light is its ambient terms plus the direct ones, which hold the
//     environment's sun where settings.sky_sun draws it as a light (the scenes have no lights).
struct OcclusionRow {
  std::string config;  // "ao none", "gtao", "gtao, ao_specular=lagarde", ...
  double ao_mean_abs = 0.0, ao_bias = 0.0;
  double ambient = 0.0, diffuse = 0.0, specular = 0.0;
  double ambient_bias = 0.0;  // sum (E - R) / sum R of ambient diffuse + specular
  double ms = 0.0;            // the AO pass's GPU time at this size (0 with ao none)
};
struct OcclusionScene {
  std::string name;     // "resting sphere", "box corner", "stairs", "DamagedHelmet, venice_sunset"
  std::string skipped;  // why it was not measured (empty: measured)
  int width = 0, height = 0, samples = 0;
  size_t lit_pixels = 0;
  double reference_noise = 0.0;  // the reference's relative standard error of ambient, summed
  // The shading's own error: `ao none` against the reference without visibility, the
  // environment's light (as OcclusionRow::ambient).
  double shading_only = 0.0;
  std::vector<OcclusionRow> rows;
};
struct OcclusionAccuracy {
  std::vector<OcclusionScene> scenes;
  double seconds = 0.0;
};

// The configurations measured, in order: ao none, then gtao with its defaults and one change each
// (with `sun`, an environment that has one: also sky_sun environment and shadowed_light).
std::vector<std::pair<std::string, RenderSettings>> occlusionConfigs(const RenderSettings& base,
                                                                     bool sun = false);

OcclusionAccuracy measureOcclusion(const AccuracyOptions& o);

}  // namespace hv::eval
