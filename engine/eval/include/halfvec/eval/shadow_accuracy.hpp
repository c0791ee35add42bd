// The shadows section of `halfvec accuracy` (docs/accuracy.md, "Shadows"): the engine's shadowed
// direct diffuse against the reference with visibility rays (Embree), on a sphere occluder over a
// floor lit by a sphere light or a capsule light, for each shadow filter. Returns data; the
// command formats it (samples/app/accuracy_markdown_shadows.cpp). Needs a current GL context.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "halfvec/eval/accuracy_report.hpp"
#include "halfvec/scene/scene.hpp"

namespace hv::eval {

// One configuration: the light (radius 0: a point light; length > 0: a capsule along `axis`)
// centered kShadowLightHeight above the floor at x = -light_offset, z = 0, the occluder (a sphere
// of radius kShadowOccluderRadius) centered `occluder_height` above the floor at x = z = 0. The
// frame looks down at the +x half of the shadow, where the penumbra is measured. With an offset
// the light shines in from -x and the shadow runs along +x from under the occluder; an occluder
// at height kShadowOccluderRadius rests on the floor (a contact shadow).
struct ShadowCase {
  float light_radius = 0.1f;
  float light_length = 0.0f;
  glm::vec3 axis{1.0f, 0.0f, 0.0f};
  float occluder_height = 1.0f;
  float light_offset = 0.0f;
};
constexpr float kShadowLightHeight = 3.0f;
constexpr float kShadowOccluderRadius = 0.3f;

// How a case is measured: image size (square), reference samples per pixel, shadow map size.
struct ShadowCaseOptions {
  int size = 128;
  int samples = 64;
  int map_size = 1024;
  int threads = 0;
};

// The scene of a case (matte white floor, grey occluder, no environment, inverse-square falloff,
// the most accurate sphere and tube diffuse methods), its light casting shadows with `filter`.
Scene shadowCaseScene(const ShadowCase& c, ShadowFilter filter, int map_size);

// The profile of a shadow along +x: per bin of distance from the shadow's center (one pixel's
// footprint wide), over the floor pixels within 25 degrees of the +x axis, the mean of the
// shadowed and of the unshadowed value.
struct ShadowProfile {
  std::vector<float> rho;               // bin center, metres from the shadow's center
  std::vector<double> shadowed, unlit;  // mean per bin ("unlit": without visibility)
  std::vector<size_t> pixels;           // floor pixels in the bin (0: none seen)
};
// The 10%-90% width of the profile's rising edge: the distance between the first bin going
// outward at 90% of the unshadowed value and the nearest bin inside it at 10% (linear
// interpolation between bins). NaN when the profile never falls to 10% (no umbra in view) or
// never rises to 90%.
double penumbraWidth(const ShadowProfile& p);

// The engine (one filter) against the reference over a case's floor pixels that are not umbra
// in both (lit and penumbra: the engine's value at least 2% of the engine's unshadowed value, or
// the reference's of the reference's without visibility).
struct ShadowFilterError {
  ShadowFilter filter = ShadowFilter::Pcss;
  ShadowResolution resolution = ShadowResolution::Full;  // half: the shadow mask, upsampled
  ShadowQuality quality = ShadowQuality::Medium;         // high: pcss's 32-gather search
  double mean_rel = 0.0;           // sum |E - R| / sum R over lit and penumbra pixels
  double penumbra_mean_rel = 0.0;  // the same over penumbra pixels (either between 2% and 98%)
  double worst_rel = 0.0;          // largest |E - R| / R of a profile bin with R >= 10% unlit
  float worst_rho = 0.0f;          // where (metres from the shadow's center)
  double width = 0.0;              // penumbraWidth of `profile`
  ShadowProfile profile;           // shadowed over the engine's own unshadowed frame
};
struct ShadowCaseResult {
  ShadowCase c;
  size_t pixels = 0, penumbra_pixels = 0;  // of the reference
  double reference_width = 0.0;
  double reference_noise = 0.0;  // the reference's pixel_noise over the pixels (LitStats)
  // The engine without shadows against the reference without visibility, over the floor pixels:
  // the shading's own error (the shadowed frames' penumbra widths are relative to that frame).
  double unshadowed_mean_rel = 0.0;
  double pixel_metres = 0.0;  // a pixel's footprint on the floor
  ShadowProfile reference_profile;
  // hard, pcf, pcss, pcss with shadow_quality high, then pcss at half resolution
  std::vector<ShadowFilterError> filters;
};
ShadowCaseResult measureShadowCase(const ShadowCase& c, const ShadowCaseOptions& o);

struct ShadowAccuracy {
  ShadowCaseOptions options;
  // sphere lights (radius x height), capsules, then contact shadows (ShadowCase::light_offset)
  std::vector<ShadowCaseResult> rows;
  double seconds = 0.0;
};
ShadowAccuracy measureShadows(const AccuracyOptions& o);

}  // namespace hv::eval
