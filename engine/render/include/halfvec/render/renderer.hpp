// The deferred renderer: G-buffer -> light culling -> light -> ambient -> tone map. It draws into
// whatever context is current (headless EGL or a window) and never asks which.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "halfvec/gl/program.hpp"
#include "halfvec/gl/timer.hpp"
#include "halfvec/image/image.hpp"
#include "halfvec/render/frame_data.hpp"
#include "halfvec/render/gpu_scene.hpp"
#include "halfvec/render/variant_key.hpp"
#include "halfvec/render/view_options.hpp"
#include "halfvec/scene/scene.hpp"
#include "halfvec/shading/gbuffer_data.hpp"

namespace hv {
struct BakeTimings;
}

namespace hv::render {

struct FrameUniforms;  // engine/render/src/passes.hpp
struct PassContext;

enum class DebugView : uint32_t {
  None = 0,
  BaseColor,
  Metallic,
  Roughness,
  Cavity,
  Normal,
  Depth,
  ShadingModel,
  LightsPerTile,
  // Per-term outputs, tone-mapped like the normal image (see TermView).
  DirectDiffuse,
  DirectSpecular,
  AmbientDiffuse,
  AmbientSpecular,
  Emissive,
  // The error budget's predicted error of the direct light per pixel (error_budget.glsl; the
  // light pass's probe LightPassProbe::PredictedError), whatever the scene's max_error.
  PredictedError
};
constexpr size_t kDebugViewCount = size_t(DebugView::PredictedError) + 1;
std::optional<DebugView> debugViewFromString(const std::string& s);
const char* toString(DebugView v);

// What a per-term debug view renders: the frame with the term masks of RenderSettings
// (HV_DIRECT_TERMS / HV_AMBIENT_TERMS; bit 1 diffuse, bit 2 specular) set to that one term, the
// background left black and the G-buffer's emissive left out, so the HDR target holds exactly
// the term as defined for the engine's AOVs (halfvec/eval/engine_aov.hpp). The Emissive view is
// the other way round: no light term, only the emissive. Over the pixels of lit surfaces, the
// four light terms plus Emissive sum to the normal frame (up to half-float rounding).
struct TermView {
  uint8_t direct_terms = 3, ambient_terms = 3;
  bool emissive = true;
  bool operator==(const TermView&) const = default;
};
// The masks of a per-term view; nullopt for the other views.
std::optional<TermView> termView(DebugView v);

struct FrameStats {
  std::vector<std::pair<std::string, double>> passes;  // GPU ms per pass, in order
  double total_ms = 0.0;
  int width = 0, height = 0;
  size_t tile_light_entries = 0;    // sum over tiles of lights in the tile's list
  size_t shadow_maps = 0;           // shadowed lights with a map in the atlas
  size_t shadow_maps_rendered = 0;  // of them, rendered this frame (the others were cached)
};

// What was compiled for the scene and why (docs/variants.md): `render --stats` and the viewer's
// stats panel print it.
struct Manifest {
  std::string key;           // VariantKey::text()
  std::string binary_cache;  // ProgramCache::binaryCacheStatus()
  size_t binary_hits = 0, binary_misses = 0;
  std::vector<gl::VariantInfo> programs;  // the programs the last frame used, in compile order
  int gbuffer_bytes_per_pixel = 16;       // gbufferBytesPerPixel of the scene's key
};

constexpr int kGBufferBytesPerPixel = 16;  // RGBA8 + RGBA8 + RG16 + D32F (docs/gbuffer.md)
// The coat target (RGBA16 snorm) a scene with a clear_coat material adds.
constexpr int kGBufferCoatBytesPerPixel = 8;
// The G-buffer's bytes per pixel for a scene of this key.
constexpr int gbufferBytesPerPixel(bool clear_coat) {
  return kGBufferBytesPerPixel + (clear_coat ? kGBufferCoatBytesPerPixel : 0);
}

// Benchmark instrument (`halfvec bench --breakdown`): what the light pass runs per light.
//  Shade      the real pass
//  FetchOnly  the same loops and light fetches, each light adding its premultiplied color
//             (no shading math): the cost of walking the lists and reading the lights
//  SetupOnly  G-buffer reads, per-pixel setup and the store, no light loop at all
// The two probes act on the tiled pass (the brute-force baseline ignores them) and render wrong
// images by design; never left on outside a measurement.
// PredictedError: the predicted_error view's light pass (light_shade.comp, HV_LIGHT_PROBE 3).
enum class LightPassProbe { Shade = 0, FetchOnly = 1, SetupOnly = 2, PredictedError = 3 };

// Knobs for benchmarks and tests, kept off the renderer's normal API (Renderer::setDebugOptions).
// The defaults are the normal renderer.
// Up to this many lights the tiled culling is one dispatch (shaders/passes/
// light_cull_few.comp: every light against every tile) instead of its three stages; the same
// lists either way (docs/performance.md, "Culling a handful of lights"). At most
// HV_CULL_FEW_MAX_LIGHTS (64).
inline constexpr size_t kCullFewLights = 16;
// And up to kCullFewCoveringLights lights that reach kCullFewCoverage of the screen's tiles or
// more on average (measured: docs/performance.md, "Culling a handful of lights").
inline constexpr size_t kCullFewCoveringLights = 32;
inline constexpr double kCullFewCoverage = 0.5;

struct DebugOptions {
  LightPassProbe light_probe = LightPassProbe::Shade;
  // The tiled light pass reads lights and tile lists through buffer textures when they fit in
  // min(GL_MAX_TEXTURE_BUFFER_SIZE, this many texels; 0 = no extra cap), else through the SSBOs.
  // Tests set a small cap to run the SSBO path.
  size_t light_texel_limit = 0;
  // The tile index list is sized from a CPU upper bound of the culling's (tile, light) pairs
  // when that bound is at most this many entries (default 32 Mi = 128 MiB), else from the GPU's
  // exact count read back mid-frame. Tests set 0 to run the read-back path.
  size_t tile_bound_limit = size_t(32) << 20;
  // Light culling runs in one dispatch per group of tiles up to HV_CULL_FUSED_MAX_LIGHTS (16,384)
  // lights, else in batches of that many lights (count, reserve, fill; docs/lights.md). A value
  // in [1, 16384) forces the batched path with batches of this many lights (tests).
  size_t cull_batch_lights = 0;
  // Adds the floor pass ("floor", after the tone map): a compute pass that reads the G-buffer and
  // writes an RGBA16F scratch target, the least a full-screen pass costs (shaders/passes/
  // floor.comp). `halfvec bench --frame` reports every pass as a multiple of it, from the same
  // frames. The image is unchanged.
  bool floor_pass = false;
  // Every pass waits for its commands to complete before its end timestamp
  // (gl::PassTimer::setFinishEachPass), so that a raster pass whose rasterization the driver
  // defers (llvmpipe) is not timed in the next pass. `halfvec bench --frame` sets it.
  bool finish_each_pass = false;
  // The light culling timed per stage ("light_cull_bounds", "light_cull_bin", "light_cull_tiles";
  // batched: "light_cull_batches" after the bounds) instead of as one "light_cull" pass
  // (`halfvec bench --frame --cull-stages`). The image is unchanged.
  bool cull_stage_timers = false;
  // The single-dispatch culling up to this many lights (kCullFewLights, and kCullFewCoverage's
  // rule; 0: always the stages).
  // Tests compare the two paths' lists.
  size_t cull_few_lights = kCullFewLights;
};

class Renderer {
 public:
  Renderer();  // needs a current GL 4.5 context
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  // Uploads geometry, materials, lights and the environment. The scene must outlive the renderer
  // or the next setScene call.
  void setScene(const Scene& scene);
  // Re-upload after the scene's materials or lights were edited in place.
  void updateMaterials();
  void updateLights();

  // Renders one frame at width x height. The tone-mapped result stays in an internal RGBA8 target
  // unless `present_fbo` is given (0 = a window's default framebuffer).
  FrameStats render(int width, int height, DebugView view = DebugView::None,
                    std::optional<GLuint> present_fbo = std::nullopt);

  // Output options beyond the scene (halfvec/render/view_options.hpp): post-AA, emitter geometry,
  // the highlighted object. All off by default.
  void setViewOptions(const ViewOptions& options) { view_options_ = options; }
  const ViewOptions& viewOptions() const { return view_options_; }

  ImageRGBf readHdr() const;
  // The 8-bit output of the last frame, after the highlight and post-AA when they ran.
  ImageRGBA8 readLdr() const;
  // The G-buffer decoded: base color and cavity as the passes fetch them (through the sRGB
  // target's own decode, gbuffer_decode.comp), the other targets by the spec's conversions.
  GBufferReadback readGBuffer() const;

  struct LightWork {
    size_t lit_pixels = 0;               // default_lit pixels the light pass shades
    size_t light_pixel_evaluations = 0;  // sum over lit pixels of the lights in their list
  };
  // Counts the light pass's work of the last frame (reads back; for benchmarks and tests).
  LightWork lightWork() const;

  // Benchmark and test instruments (DebugOptions); the defaults are the normal renderer.
  void setDebugOptions(const DebugOptions& options);
  const DebugOptions& debugOptions() const { return debug_; }
  // Frames so far whose culling read the list total back mid-frame (the bound was too large).
  size_t tileListReadbacks() const;
  // Capacity of the tile index list (entries).
  size_t tileListCapacity() const;

  // Timings of the environment bake of the current scene (nullptr without an environment).
  const BakeTimings* environmentTimings() const;

  const gl::ProgramCache& programs() const { return programs_; }
  gl::ProgramCache& programs() { return programs_; }
  // Defines every light-culling and light program of the current scene is compiled with (from
  // the variant key: BRDF terms, light options, light types present, culling).
  gl::DefineSet lightingDefines() const;
  // The scene's variant key (recomputed by setScene, updateMaterials, updateLights).
  const VariantKey& variantKey() const { return key_; }
  // The programs of the last rendered frame with their keys, reasons and compile times.
  Manifest manifest() const;
  // The program descriptions the key gives the G-buffer (one per material variant) and ambient
  // passes; for tests that inspect the generated source.
  const std::vector<gl::ProgramDesc>& gbufferPrograms() const { return gbuffer_descs_; }
  const gl::ProgramDesc& ambientProgram() const { return ambient_desc_; }

 private:
  struct Targets;
  struct Passes;  // the pass objects and their resources (engine/render/src/passes.hpp)
  void ensureTargets(int width, int height);
  // The steps of render(): the frame's uniforms (uploaded, bound on HV_UBO_FRAME), the passes that
  // fill the HDR target, the frame's statistics (after the tone map and post passes).
  struct FrameLighting;  // what lightFrame leaves for frameStats (renderer.cpp)
  FrameUniforms frameUniforms(int width, int height, DebugView view) const;
  FrameLighting lightFrame(const PassContext& ctx, FrameUniforms& frame, DebugView view);
  FrameStats frameStats(const FrameLighting& lit, int width, int height);
  void refreshVariants();  // key, program descriptions, draw order
  // Overrides the key's term masks with those of the per-term view being rendered (none: the
  // scene's own). refreshVariants applies it; render sets it from its view.
  void applyTermView(VariantKey& key) const;
  std::optional<TermView> term_view_;

  VariantKey key_;
  RenderSettings key_settings_;                 // the scene settings key_ was derived from
  std::vector<gl::ProgramDesc> gbuffer_descs_;  // per material variant
  std::vector<gl::ProgramDesc> forward_descs_;  // per material variant, when the key has blend
  gl::ProgramDesc ambient_desc_;
  gl::DefineSet light_defines_;
  // gpu_->draws() indices of the G-buffer pass (blended draws left out: the forward pass sorts
  // those each frame), grouped by variant, then material.
  std::vector<size_t> draw_order_;

  const Scene* scene_ = nullptr;
  std::unique_ptr<GpuScene> gpu_;
  std::unique_ptr<Targets> targets_;
  std::unique_ptr<Passes> passes_;
  // A cache: readGBuffer (const) compiles its decode program through it on first use.
  mutable gl::ProgramCache programs_;
  gl::PassTimer timer_;
  gl::Buffer frame_ubo_;
  gl::VertexArray empty_vao_;
  gl::Sampler nearest_, bilinear_;
  size_t tile_entries_ = 0;  // entries the last culling pass produced (read at frame end)
  DebugOptions debug_;
  bool lightPassNeedsLtc() const;   // the light program reads the LTC table (lights.glsl)
  bool lightPassHasBudget() const;  // and the error budget's table (error_budget.glsl)

  // Optional stages (post_passes.cpp): emitter geometry, highlight, post-AA.
  ViewOptions view_options_;
  struct PostStages;
  std::unique_ptr<PostStages> post_;
  PostStages& postStages();
  size_t lights_version_ = 0;  // bumped by setScene and updateLights (emitter instances follow)
  GLuint final_ldr_ = 0;       // the texture readLdr reads: the tone-mapped or anti-aliased image
  void emitterPass(DebugView view);
  bool postPassesActive(DebugView view) const;
  void postPasses(DebugView view, std::optional<GLuint> present_fbo, int width, int height);
};

}  // namespace hv::render
