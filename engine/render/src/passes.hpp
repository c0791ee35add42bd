// The passes of a frame, each with its inputs and outputs in its signature (private to
// engine/render). A pass reads only what its input struct names and writes only what its output
// names; the Renderer (renderer.cpp) owns the targets and wires one pass's output into the next.
// Adding a pass: a struct of what it reads and writes, a run function in its own .cpp, one line in
// Renderer::render. Resource slots are the #defines of shaders/common/bindings.glsl, which the
// shaders include too. Every pass binds through one gl::PassBindings scope opened with kPassSlots
// (halfvec/gl/bindings.hpp): the scope clears the shared slots when it opens, declares what the
// pass binds, releases it at the end and, under GL debug output, reports a program that reads a
// slot the pass did not bind.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "halfvec/gl/bindings.hpp"
#include "halfvec/gl/objects.hpp"
#include "halfvec/gl/program.hpp"
#include "halfvec/gl/timer.hpp"
#include "halfvec/ibl/ibl.hpp"
#include "halfvec/render/frame_data.hpp"
#include "halfvec/render/gpu_scene.hpp"
#include "halfvec/render/renderer.hpp"
#include "halfvec/render/variant_key.hpp"
#include "halfvec/shaders/common/bindings.glsl"
#include "ltc_textures.hpp"
#include "pass_slots.hpp"

namespace hv::render {

class ShadowMaps;  // shadow_pass.hpp

// What every pass runs with: the program cache, the frame's timer (each pass is one timed,
// named scope) and the samplers the compute passes share.
struct PassContext {
  gl::ProgramCache& programs;
  gl::PassTimer& timer;
  GLuint nearest = 0;   // nearest, clamp to edge: for texelFetch-style reads
  GLuint bilinear = 0;  // bilinear, clamp to edge, no mips: depth between texels (a plane's
                        // reversed-Z depth is affine in screen space: the AO horizon search, the
                        // traced specular occlusion), the AO denoise's quads
};

// The per-frame uniform block and its buffer (binding HV_UBO_FRAME for the whole frame). A pass
// that changes a field (culling grows the tile list) uploads it again.
struct FrameUniforms {
  FrameBlock block;
  GLuint ubo = 0;
  void upload() const;
};

// The four G-buffer targets as the passes after the G-buffer pass read them.
struct GBufferView {
  GLuint base_cavity = 0, material = 0, normal = 0, depth = 0;
  GLuint coat = 0;  // the coat target of a scene with clear coat, else 0
};
// Binds the G-buffer on units HV_UNIT_BASE_CAVITY .. HV_UNIT_DEPTH, and its coat target (if any)
// on HV_UNIT_COAT, with `sampler`.
void bindGBuffer(gl::PassBindings& b, const GBufferView& g, GLuint sampler);

// The tile light lists: culling's output, read by the light pass, the lights_per_tile view and
// Renderer::lightWork. `ranges`: per tile (offset, count) into `indices` (after a 4-uint header
// whose first uint is the total); `types`: per tile (points, spheres), tubes follow.
struct TileListView {
  GLuint ranges = 0, types = 0, indices = 0;
  size_t capacity = 0;  // entries `indices` holds after its header
  explicit operator bool() const { return indices != 0; }
};

// ---- Drawing the scene's geometry (scene_draws.cpp) --------------------------------------------
// The draws `order` (indices into gpu.draws()), each with programs[key.material_variant[its
// material]], its transform (HV_LOC_MODEL, HV_LOC_NORMAL_MATRIX), winding (mirroring transforms
// flip it), face culling (double-sided materials draw both faces) and its material's block and
// textures. The caller has applied its state and bound its framebuffer; the winding ends as
// counter-clockwise, face culling as the last draw left it.
struct SceneDraws {
  const Scene& scene;
  const GpuScene& gpu;
  const VariantKey& key;
  const std::vector<gl::ProgramDesc>& programs;  // per material variant of `key`
  const std::vector<size_t>& order;
  // Called before each draw with its index into gpu.draws(), after its program is bound.
  const std::function<void(size_t)>* before_draw = nullptr;
  // The material textures bound per draw: all slots, or the forward pass's first
  // HV_FORWARD_MATERIAL_TEXTURES (bindings.glsl).
  GLuint material_textures = HV_MATERIAL_TEXTURE_COUNT;
  // Called with a material variant's index into key.material_variants when its program is bound.
  const std::function<void(int)>* before_variant = nullptr;
};
void drawScene(const PassContext& ctx, gl::PassBindings& b, const SceneDraws& in);

// ---- G-buffer (gbuffer_pass.cpp) --------------------------------------------------------------
struct GBufferPassInput {
  const Scene& scene;
  const GpuScene& gpu;
  const VariantKey& key;
  const std::vector<gl::ProgramDesc>& programs;  // per material variant of `key`
  const std::vector<size_t>& draw_order;  // gpu.draws() indices of opaque and masked surfaces,
                                          // grouped by variant
  bool emissive = true;                   // false: the HDR attachment keeps its clear, 0
};
struct GBufferPassOutput {
  GLuint framebuffer = 0;  // base+cavity, material, normal, HDR color attachments + depth
  int width = 0, height = 0;
  bool coat = false;  // a fifth color attachment: the coat target (clear-coat scenes)
};
void runGBufferPass(const PassContext& ctx, const GBufferPassInput& in,
                    const GBufferPassOutput& out);

// ---- Light culling (light_cull_pass.cpp) -------------------------------------------------------
class LightCulling {
 public:
  struct Input {
    GLuint depth = 0;   // the G-buffer's depth
    GLuint lights = 0;  // GpuLight records (std430)
    size_t light_count = 0;
    const std::vector<glm::vec4>* cull_spheres = nullptr;  // world bounding spheres per light
    size_t bound_limit = size_t(32) << 20;                 // DebugOptions::tile_bound_limit
    size_t batch_lights = 0;                               // DebugOptions::cull_batch_lights
    bool stage_timers = false;                             // DebugOptions::cull_stage_timers
    size_t few_lights = kCullFewLights;                    // DebugOptions::cull_few_lights
  };
  // Builds the lists for `frame`; updates frame.block.tile_capacity when it grows.
  TileListView run(const PassContext& ctx, FrameUniforms& frame, const Input& in);
  TileListView view() const;
  // The number of (tile, light) entries the last run wrote, read from a 4-byte copy made after
  // the dispatches: the CPU never reads the list itself, which a driver would otherwise move to
  // host memory, where every light-pass read of it crosses the bus (docs/performance.md).
  uint32_t readTotal() const;
  size_t readbacks() const { return readbacks_; }
  size_t capacity() const { return capacity_; }

 private:
  struct Plan;  // the frame's grid of groups and batches (light_cull_pass.cpp)
  static Plan plan(const FrameBlock& frame, const Input& in, size_t bound);
  void cull(const PassContext& ctx, gl::PassBindings& b, const Plan& p, bool stage_timers) const;
  void stages(const PassContext& ctx, gl::PassBindings& b, const Plan& p, bool stage_timers) const;
  void dispatch(gl::PassBindings& b, const Plan& p, GLuint program, size_t record,
                bool per_light) const;
  void growList(size_t need);
  // Sizes the per-tile, per-group and per-light buffers (masks cleared when created).
  void ensureBuffers(size_t tiles, size_t groups, size_t lights, size_t mask_uints);
  // Writes `count` CullBatch records (cull_layout.glsl), one per GL_UNIFORM_BUFFER_OFFSET_ALIGNMENT
  // stride, for the dispatches to bind as ranges.
  void uploadBatches(const void* records, size_t count);
  gl::Buffer ranges_, types_, indices_;  // the lists (TileListView)
  gl::Buffer total_;                     // a copy of the list's total, for the CPU to read
  gl::Buffer lights_;                    // per light: view-space sphere, tile rectangle
  gl::Buffer bounds_;                    // per tile, block and group: surface AABB
  gl::Buffer masks_;                     // per group: light mask (0 between frames)
  gl::Buffer tile_state_;                // per tile: counts, then cursors (batched culling)
  gl::Buffer batches_;                   // CullBatch records, batch_stride_ bytes apart
  size_t batch_stride_ = 0, batch_records_ = 0;
  size_t capacity_ = 0;  // uints in the index list after its header
  size_t tiles_ = 0, groups_ = 0, lights_capacity_ = 0, mask_uints_ = 0;
  size_t readbacks_ = 0;
};

// ---- Shadow mask (shadow_mask_pass.cpp) --------------------------------------------------------
// settings.shadow_resolution half, one timed pass "shadow_mask" of two steps: the visibility of
// every light with a shadow map at one pixel per 2x2 block (passes/shadow_mask.comp, one dispatch
// layer per light), then resolved to every pixel by a depth- and normal-aware upsample
// (passes/shadow_resolve.comp). In: the G-buffer, the lights (their shadow_cube written by the
// shadow-map pass) and the maps. Out: the resolved mask (R8 2D array at the frame's size, a layer
// per light: shadow_mask.glsl, shadowMaskLayer), which the light pass reads on
// HV_UNIT_SHADOW_MASK.
class ShadowMaskPass {
 public:
  struct Input {
    GBufferView gbuffer;
    GLuint lights = 0;                    // the GPU light buffer
    const std::vector<uint32_t>& mapped;  // the lights with a map (ShadowMaps::Stats::mapped)
    const ShadowMaps& shadows;
    gl::DefineSet defines;  // the scene's lighting defines (the lookup is the light pass's)
  };
  struct Output {
    GLuint mask = 0;  // the resolved mask
  };
  Output run(const PassContext& ctx, const Input& in, int width, int height);

 private:
  gl::Texture mask_, geometry_;   // step 1: half resolution
  gl::Texture resolved_;          // step 2: the frame's resolution
  gl::Buffer lights_;             // per dispatch layer: its light's index
  gl::Buffer fallback_;           // the resolve's indirect dispatch and the workgroups it lists
  size_t fallback_capacity_ = 0;  // workgroups
  int width_ = 0, height_ = 0, layers_ = 0;  // the frame's size, the layers
  size_t lights_capacity_ = 0;
};

// ---- Light pass (light_pass.cpp) ---------------------------------------------------------------
// What the programs that evaluate lights read besides the lights: the LTC table (created in
// `*ltc` the first time; null: the programs do not read it), the error budget's table on
// `error_table_unit` (0: the programs have no budget; it lives in `*ltc` too) and the shadow
// atlas (null: none).
void bindLightTables(gl::PassBindings& b, std::unique_ptr<LtcTextures>* ltc,
                     GLuint error_table_unit, const ShadowMaps* shadows);

class LightPass {
 public:
  struct Input {
    GBufferView gbuffer;
    GLuint lights = 0;
    size_t light_count = 0;
    TileListView tiles;     // empty: brute force over every light
    gl::DefineSet defines;  // the scene's lighting defines (Renderer::lightingDefines)
    LightPassProbe probe = LightPassProbe::Shade;
    size_t texel_limit = 0;    // DebugOptions::light_texel_limit
    bool ltc = false;          // the program reads the LTC table (Renderer::lightPassNeedsLtc)
    bool error_table = false;  // and the error budget's (Renderer::lightPassHasBudget)
    const ShadowMaps* shadows = nullptr;  // the shadow atlas, when the program has shadows
    ShadowMaskPass::Output mask;          // the shadow mask, with shadow_resolution half
  };
  // Adds the direct light of every lit pixel into `hdr` (RGBA16F image).
  void run(const PassContext& ctx, const FrameBlock& frame, const Input& in, GLuint hdr);

 private:
  gl::Texture light_texels_, tile_index_texels_;  // buffer-texture views of the two buffers
  std::unique_ptr<LtcTextures> ltc_;  // the LTC table, created when a program first needs it
};

// ---- Ambient pass and the environment (ambient_pass.cpp) ---------------------------------------
// The three units an environment binds: the ambient pass's, or the forward pass's
// (bindings.glsl).
struct EnvironmentUnits {
  GLuint radiance = HV_UNIT_RADIANCE, env_brdf = HV_UNIT_ENV_BRDF, irradiance = HV_UNIT_IRRADIANCE;
};
// The environment's GPU resources: the uploaded IBL bake.
class GpuEnvironment {
 public:
  explicit GpuEnvironment(const Scene& scene);  // bakes (or loads the cached bake) and uploads
  bool present() const { return present_; }
  const BakeTimings& timings() const { return timings_; }
  // Binds the radiance, env BRDF and irradiance textures on `units` and the environment block; a
  // missing texture is replaced by one of the right type (`fallback_2d`, a black cube).
  void bind(gl::PassBindings& b, GLuint fallback_2d,
            const EnvironmentUnits& units = EnvironmentUnits{}) const;

 private:
  gl::Texture radiance_, irradiance_, env_brdf_, black_cube_;
  gl::Buffer block_;
  gl::Sampler trilinear_;
  bool present_ = false;
  BakeTimings timings_;
};
struct AmbientPassInput {
  GBufferView gbuffer;
  const GpuEnvironment& environment;
  const gl::ProgramDesc& program;  // Renderer::ambientProgram()
  GLuint ao = 0;                   // AoPass::run's target when the key has `ao: gtao`
};
// Adds the image-based light into `hdr` and draws the environment on background pixels.
void runAmbientPass(const PassContext& ctx, const AmbientPassInput& in, GLuint hdr, int width,
                    int height);

// ---- Blended surfaces (forward_pass.cpp) -------------------------------------------------------
// glTF alphaMode BLEND: after the deferred passes, the blended draws back to front (by the view
// depth of their bounds' centres), depth-tested against the opaque depth without writing it, each
// fragment lit by every light and the environment and blended over the HDR target
// (forward.frag). One timed pass "forward".
class ForwardPass {
 public:
  struct Input {
    const Scene& scene;
    const GpuScene& gpu;
    const VariantKey& key;
    const std::vector<gl::ProgramDesc>& programs;  // per material variant of `key`: forward.frag
    const GpuEnvironment& environment;
    bool ltc = false;                     // the programs read the LTC table
    bool error_table = false;             // and the error budget's
    const ShadowMaps* shadows = nullptr;  // the shadow atlas, when the programs have shadows
  };
  struct Output {
    GLuint framebuffer = 0;  // the HDR target + the G-buffer's depth
    int width = 0, height = 0;
  };
  // The blended draws of `gpu` in drawing order: farthest first from `camera_pos` (world).
  static std::vector<size_t> backToFront(const Scene& scene, const GpuScene& gpu,
                                         const glm::vec3& camera_pos);
  // The lights (indices into the GPU light list) whose culling sphere meets the world-space
  // bounding box of draw `draw`: the only ones that can light its fragments (a light's window is
  // exactly 0 outside that sphere, lights.glsl lightCullRadius).
  static std::vector<uint32_t> lightsReaching(const Scene& scene, const GpuScene& gpu, size_t draw);
  void run(const PassContext& ctx, const Input& in, const Output& out);

 private:
  std::unique_ptr<LtcTextures> ltc_;
  gl::Buffer draw_lights_;  // per blended draw its lightsReaching list, concatenated
  size_t draw_lights_capacity_ = 0;
};

// ---- Screen-space ambient occlusion (ao_pass.cpp) ----------------------------------------------
// GTAO (Jimenez et al. 2016) at full or half resolution: the horizon search (gtao.comp), then the
// edge-keeping denoise (ao_denoise.comp), one timed pass "ao". In: the G-buffer's normal and
// depth. Out: an RGBA16F target of (visibility, inverse view distance, octahedral world bent
// normal where ao_specular is cone), which the ambient pass reads on HV_UNIT_AO.
class AoPass {
 public:
  // The programs of the key (aoDefines); call when the key changes.
  void setVariant(const VariantKey& key, const Scene& scene);
  // Returns the denoised AO target (owned by the pass, valid until the next run).
  GLuint run(const PassContext& ctx, const GBufferView& gbuffer, const RenderSettings& settings,
             int width, int height);

 private:
  gl::ProgramDesc gtao_, denoise_;
  gl::Texture raw_, denoised_;
  int width_ = 0, height_ = 0;
};

// ---- Tone map and debug views (tonemap_pass.cpp) -----------------------------------------------
struct TonemapPassInput {
  GLuint hdr = 0;
  GBufferView gbuffer;     // the G-buffer debug views
  GLuint tile_ranges = 0;  // lights_per_tile (0: none yet)
  DebugView view = DebugView::None;
  const RenderSettings& settings;
};
struct TonemapPassOutput {
  GLuint framebuffer = 0;  // where the tone-mapped image goes
  GLuint capture = 0;      // if not 0 and not `framebuffer`: a copy is blitted there (captures)
  int width = 0, height = 0;
};
void runTonemapPass(const PassContext& ctx, const TonemapPassInput& in,
                    const TonemapPassOutput& out, GLuint fullscreen_vao);

// ---- Floor (floor_pass.cpp) -------------------------------------------------------------------
// Reads the G-buffer, writes `scratch` (RGBA16F, width x height): DebugOptions::floor_pass.
void runFloorPass(const PassContext& ctx, const GBufferView& gbuffer, GLuint scratch, int width,
                  int height);

}  // namespace hv::render
