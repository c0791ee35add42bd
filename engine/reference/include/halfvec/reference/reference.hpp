// CPU ground truth for the deferred renderer: per G-buffer pixel, the lighting integral the engine
// approximates, computed exactly (point lights) or by Monte Carlo (sphere/tube lights, the
// environment), with the engine's own BRDF (BrdfConfig::fromSettings, the shared hv::glsl terms)
// and no interreflection. With ReferenceOptions::visibility, every light and environment sample
// is traced against the scene's triangles (Embree): shadows and the occlusion of the
// environment; without it, the light is visible wherever it is above the horizon, the model the
// engine's shading approximates. Estimators, pdfs, MIS, visibility and error reporting:
// docs/reference.md. No OpenGL: GBufferReadback is only a data type here.
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <vector>

#include <glm/glm.hpp>

#include "halfvec/ibl/ibl.hpp"
#include "halfvec/image/image.hpp"
#include "halfvec/shading/gbuffer_data.hpp"
#include "halfvec/scene/scene.hpp"

namespace hv {

// The four separately accumulated parts of a lit pixel; their sum is ReferenceResult::image.
enum class ReferenceAov : int {
  DirectDiffuse = 0,
  DirectSpecular = 1,
  AmbientDiffuse = 2,
  AmbientSpecular = 3
};
constexpr int kReferenceAovCount = 4;
const char* toString(ReferenceAov aov);  // "direct_diffuse", ...

struct ReferenceOptions {
  // Most Monte Carlo samples per lit pixel. One sample = one cosine and one GGX-VNDF direction
  // for the environment plus one point on each sphere/tube light.
  int samples = 256;
  // Stop a pixel early once the relative standard error of its luminance falls below this
  // (checked every `batch` samples, after at least `min_samples`); 0 = always take `samples`.
  float target_rel_error = 0.0f;
  int min_samples = 16;
  int batch = 16;
  int threads = 0;        // worker threads over rows; 0 = hardware concurrency
  bool progress = false;  // progress lines on stderr
  uint64_t seed = 1;      // same seed, same image (independent of `threads`)
  SkyParams sky;          // parameters of EnvironmentKind::Sky (as for the bake)
  // Visibility rays against the scene's triangles for every point light, every area-light
  // sample (both MIS strategies) and every environment sample, and the ambient occlusion image.
  // Off: nothing occludes (the shading integral alone; the images are those of the reference
  // before visibility existed, bit for bit).
  bool visibility = false;
  // Ambient occlusion: occluders farther than this from the shading point do not count.
  float ao_distance = std::numeric_limits<float>::infinity();
};

struct ReferenceStats {
  size_t lit_pixels = 0;  // default_lit pixels integrated
  size_t background_pixels = 0;
  size_t unlit_pixels = 0;               // left black: emissive is not in the G-buffer readback
  uint64_t total_samples = 0;            // over lit pixels
  int min_samples = 0, max_samples = 0;  // per lit pixel
  // Relative standard error of luminance, se(Y) / Y, over lit pixels with Y > 0.
  double mean_rel_error = 0.0;
  double max_rel_error = 0.0;
  double seconds = 0.0;
  bool visibility = false;  // ReferenceOptions::visibility of the run
  uint64_t rays = 0;        // visibility rays traced (0 without visibility)
  size_t triangles = 0;     // in the visibility scene (0 without visibility)
};

struct ReferenceResult {
  ImageRGBf image;      // sum of the AOVs on lit pixels; environment radiance on background
  ImageRGBf std_error;  // per-pixel, per-channel standard error of `image` (0 where exact)
  std::array<ImageRGBf, kReferenceAovCount> aov;            // indexed by ReferenceAov
  std::array<ImageRGBf, kReferenceAovCount> aov_std_error;  // likewise
  // Ambient occlusion on lit pixels (the same value in the three channels): the cosine-weighted
  // fraction of the hemisphere around the G-buffer normal that no triangle within
  // ReferenceOptions::ao_distance hides, (1/pi) integral of V(l) NoL dl; one cosine-distributed
  // ray per sample, from its own random stream. Not times the cavity (a material input). 1 on
  // lit pixels without visibility, 0 elsewhere.
  ImageRGBf ao;
  ImageRGBf ao_std_error;
  std::vector<int> samples;  // samples per pixel (0 off lit pixels), row 0 = top
  ReferenceStats stats;

  const ImageRGBf& operator[](ReferenceAov a) const { return aov[static_cast<int>(a)]; }
  const ImageRGBf& stdError(ReferenceAov a) const { return aov_std_error[static_cast<int>(a)]; }
};

// The world-from-clip matrix of the engine's camera (engine/render/src/frame_data.cpp
// makeFrameBlock: glm::lookAt view, reversed-Z infinite perspective), recomputed here so this
// module needs no GL library. Pixel (x, y) (row 0 = top) has uv = ((x + 0.5) / w, 1 - (y + 0.5) /
// h).
glm::mat4 referenceInvViewProj(const Camera& camera, int width, int height);

// Renders the reference for the G-buffer `gb` of `scene` (gb.width x gb.height). Lit pixels
// (isLit: default_lit, clear_coat): direct + ambient light as described in docs/reference.md.
// Background: the full-resolution environment radiance along the view ray. Unlit: black (the
// engine's emissive is not in GBufferReadback; compare lit and background pixels only).
// Throws std::invalid_argument if the readback's arrays do not match its size.
ReferenceResult renderReference(const Scene& scene, const GBufferReadback& gb,
                                const ReferenceOptions& options = {});

}  // namespace hv
