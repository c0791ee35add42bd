#include "halfvec/render/renderer.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "pipeline_state.hpp"
#include "post_stages.hpp"
#include "targets.hpp"
#include "halfvec/scene/enums.hpp"
#include "halfvec/shading/light_gpu.hpp"
#include "halfvec/shading/shading.hpp"

namespace hv::render {

namespace {
constexpr const char* kDebugViewNames[] = {"none",
                                           "basecolor",
                                           "metallic",
                                           "roughness",
                                           "cavity",
                                           "normal",
                                           "depth",
                                           "shading_model",
                                           "lights_per_tile",
                                           "direct_diffuse",
                                           "direct_specular",
                                           "ambient_diffuse",
                                           "ambient_specular",
                                           "emissive",
                                           "predicted_error"};
static_assert(std::size(kDebugViewNames) == kDebugViewCount, "one name per DebugView");
}  // namespace

std::optional<DebugView> debugViewFromString(const std::string& s) {
  for (size_t i = 0; i < std::size(kDebugViewNames); ++i) {
    if (s == kDebugViewNames[i]) return static_cast<DebugView>(i);
  }
  return std::nullopt;
}

const char* toString(DebugView v) {
  return kDebugViewNames[static_cast<size_t>(v)];
}

std::optional<TermView> termView(DebugView v) {
  switch (v) {
    case DebugView::DirectDiffuse:
      return TermView{1, 0, false};
    case DebugView::DirectSpecular:
      return TermView{2, 0, false};
    case DebugView::AmbientDiffuse:
      return TermView{0, 1, false};
    case DebugView::AmbientSpecular:
      return TermView{0, 2, false};
    case DebugView::Emissive:
      return TermView{0, 0, true};
    case DebugView::PredictedError:  // the direct light's pairs alone (no ambient, no emissive)
      return TermView{3, 0, false};
    default:
      return std::nullopt;
  }
}

void Renderer::applyTermView(VariantKey& key) const {
  if (!term_view_) return;
  key.settings.direct_terms = term_view_->direct_terms;
  key.settings.ambient_terms = term_view_->ambient_terms;
}

Renderer::Renderer() : targets_(std::make_unique<Targets>()), passes_(std::make_unique<Passes>()) {
  frame_ubo_ = gl::createBuffer("frame uniforms", sizeof(FrameBlock));
  empty_vao_ = gl::createVertexArray("fullscreen triangle");
  programs_.setBinaryCacheDir(gl::defaultProgramCacheDir());
  nearest_ = gl::createSampler("nearest clamp");
  glSamplerParameteri(nearest_.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glSamplerParameteri(nearest_.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glSamplerParameteri(nearest_.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glSamplerParameteri(nearest_.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  bilinear_ = gl::createSampler("bilinear clamp");
  glSamplerParameteri(bilinear_.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glSamplerParameteri(bilinear_.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glSamplerParameteri(bilinear_.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glSamplerParameteri(bilinear_.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

Renderer::~Renderer() = default;

void Renderer::setScene(const Scene& scene) {
  scene_ = &scene;
  ++lights_version_;
  gpu_ = std::make_unique<GpuScene>(scene);
  passes_->environment = std::make_unique<GpuEnvironment>(scene);
  passes_->shadows.invalidate();  // other casters
  refreshVariants();
}

void Renderer::updateMaterials() {
  if (gpu_) gpu_->updateMaterials(*scene_);
  if (scene_) refreshVariants();
}

void Renderer::updateLights() {
  ++lights_version_;
  if (gpu_) gpu_->updateLights(*scene_);
  if (scene_) refreshVariants();
}

gl::DefineSet Renderer::lightingDefines() const {
  return light_defines_;
}

namespace {
gl::DefineSet toDefineSet(const std::vector<KeyDefine>& defs,
                          std::map<std::string, std::string>* reasons = nullptr) {
  gl::DefineSet d;
  for (const KeyDefine& k : defs) {
    d.push_back({k.name, k.value});
    if (reasons) (*reasons)[k.name] = k.why;
  }
  return d;
}
}  // namespace

void Renderer::refreshVariants() {
  key_ = deriveVariantKey(*scene_);
  applyTermView(key_);
  key_settings_ = scene_->settings;
  // One program per material variant of the key: the G-buffer pass's, and the forward pass's
  // when a material is blended.
  const auto materialPrograms = [&](const char* pass, const char* frag, auto defines) {
    std::vector<gl::ProgramDesc> descs;
    for (size_t v = 0; v < key_.material_variants.size(); ++v) {
      gl::ProgramDesc d{
          pass, {{GL_VERTEX_SHADER, "passes/gbuffer.vert"}, {GL_FRAGMENT_SHADER, frag}}, {}};
      d.name = std::string(pass) + " " + (key_.uber ? "uber" : key_.material_variants[v].text());
      d.defines = toDefineSet(defines(key_, v, *scene_), &d.reasons);
      descs.push_back(std::move(d));
    }
    return descs;
  };
  gbuffer_descs_ = materialPrograms("gbuffer", "passes/gbuffer.frag", gbufferDefines);
  forward_descs_.clear();
  if (key_.blend)
    forward_descs_ = materialPrograms("forward", "passes/forward.frag", forwardDefines);
  ambient_desc_ = {"ambient", {{GL_COMPUTE_SHADER, "passes/ambient.comp"}}, {}};
  ambient_desc_.defines = toDefineSet(ambientDefines(key_, *scene_), &ambient_desc_.reasons);
  passes_->ao.setVariant(key_, *scene_);
  // The light passes build their own descriptions from lightingDefines(); their reasons go to
  // the cache's table.
  const auto light = lightDefines(key_, *scene_);
  light_defines_ = toDefineSet(light);
  std::map<std::string, std::pair<std::string, std::string>> reasons;
  for (const KeyDefine& k : light) reasons[k.name] = {k.value, k.why};
  for (const KeyDefine& k : toneMapDefines(key_, *scene_)) reasons[k.name] = {k.value, k.why};
  programs_.setDefineReasons(std::move(reasons));
  // Draws grouped by program, then by material (fewer program and texture switches).
  const auto& draws = gpu_->draws();
  draw_order_.clear();
  for (size_t i = 0; i < draws.size(); ++i) {
    if (scene_->materials[size_t(draws[i].material)].alpha_mode != AlphaMode::Blend) {
      draw_order_.push_back(i);
    }
  }
  std::stable_sort(draw_order_.begin(), draw_order_.end(), [&](size_t a, size_t b) {
    const int va = key_.material_variant[size_t(draws[a].material)];
    const int vb = key_.material_variant[size_t(draws[b].material)];
    return va != vb ? va < vb : draws[a].material < draws[b].material;
  });
}

Manifest Renderer::manifest() const {
  Manifest m;
  m.key = key_.text();
  m.binary_cache = programs_.binaryCacheStatus();
  m.binary_hits = programs_.binaryHits();
  m.binary_misses = programs_.binaryMisses();
  m.gbuffer_bytes_per_pixel = gbufferBytesPerPixel(key_.clear_coat);
  for (const auto& v : programs_.variants()) {
    if (v.last_frame == programs_.frame()) m.programs.push_back(v);
  }
  return m;
}

void Renderer::ensureTargets(int w, int h) {
  Targets& t = *targets_;
  const bool coat = key_.clear_coat;
  if (t.width == w && t.height == h && t.gbuffer && bool(t.coat) == coat) return;
  t = Targets{};
  t.width = w;
  t.height = h;
  t.base_cavity = gl::createTexture2D("gbuffer base color + cavity", GL_SRGB8_ALPHA8, w, h);
  t.material = gl::createTexture2D("gbuffer metallic roughness model", GL_RGBA8, w, h);
  t.normal = gl::createTexture2D("gbuffer octahedral normal", GL_RG16_SNORM, w, h);
  t.depth = gl::createTexture2D("gbuffer depth (reversed Z)", GL_DEPTH_COMPONENT32F, w, h);
  t.hdr = gl::createTexture2D("hdr accumulation", GL_RGBA16F, w, h);
  t.ldr = gl::createTexture2D("tone-mapped output", GL_RGBA8, w, h);
  if (coat) {
    t.coat = gl::createTexture2D("gbuffer clear coat", GL_RGBA16_SNORM, w, h);
    t.gbuffer = gl::createFramebuffer(
        "gbuffer", {{&t.base_cavity}, {&t.material}, {&t.normal}, {&t.hdr}, {&t.coat}}, &t.depth);
  } else {
    t.gbuffer = gl::createFramebuffer(
        "gbuffer", {{&t.base_cavity}, {&t.material}, {&t.normal}, {&t.hdr}}, &t.depth);
  }
  t.output = gl::createFramebuffer("output", {{&t.ldr}});
  t.forward = gl::createFramebuffer("forward (hdr + gbuffer depth)", {{&t.hdr}}, &t.depth);
}

struct Renderer::FrameLighting {
  ShadowMaps::Stats shadows;
  TileListView tiles;   // the culling's lists, when culled
  bool culled = false;  // the culling pass ran
};

FrameStats Renderer::render(int width, int height, DebugView view,
                            std::optional<GLuint> present_fbo) {
  if (!scene_) throw gl::GlError("Renderer::render called before setScene");
  if (width <= 0 || height <= 0) return {};
  ensureTargets(width, height);
  const std::optional<TermView> terms = termView(view);
  const bool terms_changed = terms != term_view_;
  term_view_ = terms;
  // Settings edited in place (viewer), or another term view: other term masks.
  if (!(scene_->settings == key_settings_) || terms_changed) refreshVariants();
  programs_.beginFrame();
  FrameUniforms frame = frameUniforms(width, height, view);
  const PassContext ctx{programs_, timer_, nearest_.id(), bilinear_.id()};
  const FrameLighting lit = lightFrame(ctx, frame, view);
  Targets& t = *targets_;
  const bool post = postPassesActive(view);
  final_ldr_ = 0;
  // With post passes, the tone map writes the output target and postPasses presents it.
  const bool present = present_fbo.has_value() && !post;
  runTonemapPass(
      ctx, {t.hdr.id(), t.gbufferView(), passes_->culling.view().ranges, view, scene_->settings},
      {present ? *present_fbo : t.output.id(), present ? t.output.id() : 0u, width, height},
      empty_vao_.id());
  if (post) postPasses(view, present_fbo, width, height);
  if (debug_.floor_pass) {
    if (!t.floor) t.floor = gl::createTexture2D("floor pass scratch", GL_RGBA16F, width, height);
    runFloorPass(ctx, t.gbufferView(), t.floor.id(), width, height);
  }
  applyState(PipelineState{});
  return frameStats(lit, width, height);
}

FrameUniforms Renderer::frameUniforms(int width, int height, DebugView view) const {
  FrameUniforms frame{makeFrameBlock(*scene_, width, height), frame_ubo_.id()};
  frame.block.light_count = static_cast<uint32_t>(gpu_->lightCount());
  frame.block.directional_lights = gpu_->directionalLights();
  frame.block.tile_capacity = static_cast<uint32_t>(passes_->culling.capacity());
  frame.block.debug_view = static_cast<uint32_t>(view);
  // Term views: no background (ambient.comp), no emissive (masked out in the G-buffer pass).
  frame.block.frame_flags = !term_view_            ? 0u
                            : term_view_->emissive ? kFrameNoBackground
                                                   : kFrameNoBackground | kFrameNoEmissive;
  frame.upload();
  glBindBufferBase(GL_UNIFORM_BUFFER, HV_UBO_FRAME, frame_ubo_.id());
  return frame;
}

// Shadow maps, G-buffer, culling, direct and ambient light and the emitters: the HDR target.
Renderer::FrameLighting Renderer::lightFrame(const PassContext& ctx, FrameUniforms& frame,
                                             DebugView view) {
  Targets& t = *targets_;
  Passes& p = *passes_;
  const GBufferView gbuffer = t.gbufferView();
  FrameLighting lit;
  // Shadow maps of the shadowed lights (cached until a light or a caster changes).
  const bool mask = key_.shadows && key_.settings.shadow_resolution == ShadowResolution::Half;
  if (key_.shadows) {
    lit.shadows =
        p.shadows.run(ctx, {*scene_, *gpu_, key_.settings.shadow_map_size, lights_version_, mask});
  }
  runGBufferPass(ctx,
                 {*scene_, *gpu_, key_, gbuffer_descs_, draw_order_,
                  (frame.block.frame_flags & kFrameNoEmissive) == 0},
                 {t.gbuffer.id(), t.width, t.height, bool(t.coat)});
  // key_.settings: culling auto resolved (chooseCulling).
  lit.culled = key_.settings.culling == Culling::Tiled || view == DebugView::LightsPerTile;
  if (lit.culled) {
    lit.tiles =
        p.culling.run(ctx, frame,
                      {t.depth.id(), gpu_->lightBuffer(), gpu_->lightCount(),
                       &gpu_->lightCullSpheres(), debug_.tile_bound_limit, debug_.cull_batch_lights,
                       debug_.cull_stage_timers, debug_.cull_few_lights});
  }
  // The predicted_error view: the light pass's probe with the budget's code compiled in.
  const bool predicted = view == DebugView::PredictedError;
  gl::DefineSet light_defines = lightingDefines();
  // shadow_resolution half: the visibility once per 2x2 pixels, before the light pass.
  ShadowMaskPass::Output shadow_mask;
  if (mask) {
    shadow_mask = p.shadow_mask.run(
        ctx, {gbuffer, gpu_->lightBuffer(), lit.shadows.mapped, p.shadows, lightingDefines()},
        t.width, t.height);
  }
  if (predicted) {
    for (auto& d : light_defines) {
      if (d.name == "HV_ERROR_BUDGET") d.value = "1";
    }
  }
  LightPass::Input light{
      gbuffer,
      gpu_->lightBuffer(),
      gpu_->lightCount(),
      key_.settings.culling == Culling::Tiled ? p.culling.view() : TileListView{},
      light_defines,
      predicted ? LightPassProbe::PredictedError : debug_.light_probe,
      debug_.light_texel_limit,
      lightPassNeedsLtc() || predicted,
      lightPassHasBudget() || predicted,
      key_.shadows ? &p.shadows : nullptr,
      shadow_mask};
  p.light.run(ctx, frame.block, light, t.hdr.id());
  // Without an environment the ambient pass would add nothing: the background is black, the HDR
  // target's clear value (docs/performance.md "Passes of the frame").
  if (p.environment->present()) {
    const GLuint ao = key_.ao ? p.ao.run(ctx, gbuffer, key_.settings, t.width, t.height) : 0u;
    runAmbientPass(ctx, {gbuffer, *p.environment, ambient_desc_, ao}, t.hdr.id(), t.width,
                   t.height);
  }
  emitterPass(view);
  if (key_.blend) {
    p.forward.run(ctx,
                  {*scene_, *gpu_, key_, forward_descs_, *p.environment, lightPassNeedsLtc(),
                   lightPassHasBudget(), key_.shadows ? &p.shadows : nullptr},
                  {t.forward.id(), t.width, t.height});
  }
  return lit;
}

FrameStats Renderer::frameStats(const FrameLighting& lit, int width, int height) {
  FrameStats stats;
  stats.passes = timer_.resolve();
  for (auto& [name, ms] : stats.passes) stats.total_ms += ms;
  stats.width = width;
  stats.height = height;
  if (lit.culled) {
    // The scan's total, for the stats: read after the timers, which already waited for the frame.
    tile_entries_ = passes_->culling.readTotal();
  }
  stats.tile_light_entries = tile_entries_;
  stats.shadow_maps = lit.shadows.maps;
  stats.shadow_maps_rendered = lit.shadows.rendered;
  return stats;
}

void Renderer::setDebugOptions(const DebugOptions& options) {
  debug_ = options;
  timer_.setFinishEachPass(options.finish_each_pass);
}

size_t Renderer::tileListReadbacks() const {
  return passes_->culling.readbacks();
}

size_t Renderer::tileListCapacity() const {
  return passes_->culling.capacity();
}

const BakeTimings* Renderer::environmentTimings() const {
  const auto& env = passes_->environment;
  return env && env->present() ? &env->timings() : nullptr;
}

namespace {
// GL rows go bottom-up; images here are top-down.
template <class T>
void flipRows(std::vector<T>& v, int w, int h, int comps) {
  for (int y = 0; y < h / 2; ++y) {
    std::swap_ranges(v.begin() + size_t(y) * w * comps, v.begin() + size_t(y + 1) * w * comps,
                     v.begin() + size_t(h - 1 - y) * w * comps);
  }
}
}  // namespace

ImageRGBf Renderer::readHdr() const {
  const Targets& t = *targets_;
  std::vector<float> px(size_t(t.width) * t.height * 3);
  glGetTextureImage(t.hdr.id(), 0, GL_RGB, GL_FLOAT, GLsizei(px.size() * sizeof(float)), px.data());
  flipRows(px, t.width, t.height, 3);
  ImageRGBf img = makeImageRGBf(t.width, t.height);
  for (size_t i = 0; i < img.px.size(); ++i) img.px[i] = {px[3 * i], px[3 * i + 1], px[3 * i + 2]};
  return img;
}

ImageRGBA8 Renderer::readLdr() const {
  const Targets& t = *targets_;
  ImageRGBA8 img = makeImageRGBA8(t.width, t.height);
  glGetTextureImage(final_ldr_ ? final_ldr_ : t.ldr.id(), 0, GL_RGBA, GL_UNSIGNED_BYTE,
                    GLsizei(img.px.size()), img.px.data());
  flipRows(img.px, t.width, t.height, 4);
  return img;
}

Renderer::LightWork Renderer::lightWork() const {
  const Targets& t = *targets_;
  const size_t n = size_t(t.width) * t.height;
  std::vector<uint8_t> mat(n * 4);
  glGetTextureImage(t.material.id(), 0, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(mat.size()), mat.data());
  const bool brute = key_.settings.culling == Culling::BruteForce;
  const int tiles_x = (t.width + kTileSize - 1) / kTileSize;
  const int tiles_y = (t.height + kTileHeight - 1) / kTileHeight;
  std::vector<uint32_t> ranges(size_t(tiles_x) * tiles_y * 2);
  const TileListView tiles = passes_->culling.view();
  if (!brute && tiles) {
    glGetNamedBufferSubData(tiles.ranges, 0, GLsizeiptr(ranges.size() * sizeof(uint32_t)),
                            ranges.data());
  }
  LightWork w;
  for (int y = 0; y < t.height; ++y) {
    for (int x = 0; x < t.width; ++x) {
      // The byte read back is the stored unorm8 code: as a float, what the shaders decode.
      const uint8_t stored = mat[(size_t(y) * t.width + x) * 4 + 2];
      if (!glsl::isLitModel(glsl::decodeShadingModel(stored / 255.0f))) continue;
      ++w.lit_pixels;
      const size_t tile = size_t(y / kTileHeight) * tiles_x + x / kTileSize;
      w.light_pixel_evaluations += brute ? gpu_->lightCount() : ranges[tile * 2 + 1];
    }
  }
  return w;
}

GBufferReadback Renderer::readGBuffer() const {
  const Targets& t = *targets_;
  const size_t n = size_t(t.width) * t.height;
  GBufferReadback g;
  g.width = t.width;
  g.height = t.height;
  std::vector<float> mat(n * 4), nrm(n * 2), depth(n), base(n * 4);
  // The base color as the light and ambient passes fetch it: the SRGB8 target's own decode
  // (gbuffer_decode.comp), which the GL lets differ from the exact curve; the reference then
  // shades the values the engine shaded.
  {
    const gl::Texture decoded =
        gl::createTexture2D("gbuffer base color, decoded", GL_RGBA32F, t.width, t.height);
    gl::PassBindings b(kPassSlots, "gbuffer readback");
    b.use(
        programs_.get({"gbuffer_decode", {{GL_COMPUTE_SHADER, "passes/gbuffer_decode.comp"}}, {}}));
    b.texture(HV_UNIT_BASE_CAVITY, t.base_cavity.id(), nearest_.id());
    b.image(HV_IMAGE_READBACK, decoded.id(), GL_WRITE_ONLY, GL_RGBA32F);
    glDispatchCompute(GLuint(t.width + kTileSize - 1) / kTileSize,
                      GLuint(t.height + kTileSize - 1) / kTileSize, 1);
    glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT);
    glGetTextureImage(decoded.id(), 0, GL_RGBA, GL_FLOAT, GLsizei(base.size() * 4), base.data());
  }
  glGetTextureImage(t.material.id(), 0, GL_RGBA, GL_FLOAT, GLsizei(mat.size() * 4), mat.data());
  glGetTextureImage(t.normal.id(), 0, GL_RG, GL_FLOAT, GLsizei(nrm.size() * 4), nrm.data());
  glGetTextureImage(t.depth.id(), 0, GL_DEPTH_COMPONENT, GL_FLOAT, GLsizei(depth.size() * 4),
                    depth.data());
  flipRows(base, t.width, t.height, 4);
  flipRows(mat, t.width, t.height, 4);
  flipRows(nrm, t.width, t.height, 2);
  flipRows(depth, t.width, t.height, 1);
  g.base_color.resize(n);
  g.metallic.resize(n);
  g.roughness.resize(n);
  g.cavity.resize(n);
  g.normal.resize(n);
  g.model.resize(n);
  g.depth = depth;
  for (size_t i = 0; i < n; ++i) {
    g.base_color[i] = {base[4 * i], base[4 * i + 1], base[4 * i + 2]};
    g.cavity[i] = base[4 * i + 3];  // alpha of an sRGB format is linear
    g.metallic[i] = mat[4 * i];
    g.roughness[i] = glsl::decodeRoughness16(glsl::vec2(mat[4 * i + 1], mat[4 * i + 3]));
    g.model[i] = glsl::decodeShadingModel(mat[4 * i + 2]);
    g.normal[i] = glsl::octDecode(glsl::vec2(nrm[2 * i], nrm[2 * i + 1]));
  }
  if (t.coat) {
    std::vector<float> coat(n * 4);
    glGetTextureImage(t.coat.id(), 0, GL_RGBA, GL_FLOAT, GLsizei(coat.size() * 4), coat.data());
    flipRows(coat, t.width, t.height, 4);
    g.clearcoat.resize(n);
    g.clearcoat_roughness.resize(n);
    g.coat_normal.resize(n);
    for (size_t i = 0; i < n; ++i) {
      const bool coated = g.model[i] == glsl::HV_MODEL_CLEAR_COAT;
      g.clearcoat[i] = coated ? coat[4 * i + 2] : 0.0f;
      g.clearcoat_roughness[i] = coated ? coat[4 * i + 3] : 0.0f;
      g.coat_normal[i] =
          coated ? glsl::octDecode(glsl::vec2(coat[4 * i], coat[4 * i + 1])) : g.normal[i];
    }
  }
  return g;
}

// The light program reads the LTC table (lights.glsl HV_LTC_TABLE) when a light type it compiles
// shades its specular with it, or may (an error budget: HV_SPHERE_BUDGET).
bool Renderer::lightPassNeedsLtc() const {
  const RenderSettings& s = key_.settings;
  return ((key_.sphere_lights || key_.directional_lights) &&
          s.sphere_specular == SphereSpecular::Ltc) ||
         (key_.tube_lights && s.tube_specular == TubeSpecular::Ltc) || lightPassHasBudget();
}
bool Renderer::lightPassHasBudget() const {
  const RenderSettings& s = key_.settings;
  return (key_.sphere_lights || key_.directional_lights) && s.max_error != 0.0f &&
         s.sphere_specular == SphereSpecular::RepresentativePoint;
}

}  // namespace hv::render
