// Light culling (compute: tile bounds, light binning into groups of tiles, per-tile walks).
// In: depth, lights. Out: per-tile light lists (TileListView).
#include <algorithm>
#include <cstddef>
#include <cstring>
#include <optional>

#include "passes.hpp"
#include "pipeline_state.hpp"
#include "halfvec/shading/shading.hpp"

namespace hv::render {

static_assert(sizeof(glsl::CullLight) == 64, "CullLight: vec4 + uvec4 + 2 vec4, std430");
static_assert(sizeof(glsl::CullBatch) == 16, "CullBatch: 4 uints, std140");

namespace {
constexpr size_t kTileHeaderUints = HV_TILE_LIST_HEADER_UINTS;

// A stage's own timer when `on` (Input::stage_timers), else nothing.
class StageTimer {
 public:
  StageTimer(gl::PassTimer& timer, bool on, const char* name) {
    if (on) pass_.emplace(timer, name);
  }

 private:
  std::optional<gl::ScopedPass> pass_;
};
// Upper bound of the (tile, light) pairs the culling can find: the sum of the lights' tile
// rectangles (sphereTileRect, the function the GPU runs), each widened by one tile on every side
// so that rounding differences between the two compilers cannot make it smaller than the GPU's.
size_t listBound(const std::vector<glm::vec4>& spheres, const FrameBlock& frame) {
  const glm::vec2 scale(frame.proj[0][0], frame.proj[1][1]);
  const glm::vec2 viewport(frame.viewport.x, frame.viewport.y);
  const glm::ivec2 tiles(frame.viewport.z, frame.viewport.w);
  const glm::vec2 tile_px(kTileSize, kTileHeight);
  size_t bound = 0;
  for (const glm::vec4& s : spheres) {
    const glm::vec3 c = glm::vec3(frame.view * glm::vec4(glm::vec3(s), 1.0f));
    glm::ivec4 r;
    if (!glsl::sphereTileRect(c, s.w, scale, frame.frame_params.x, viewport, tiles, tile_px, r)) {
      continue;
    }
    const glm::ivec2 lo = glm::max(glm::ivec2(r.x, r.y) - 1, glm::ivec2(0));
    const glm::ivec2 hi = glm::min(glm::ivec2(r.z, r.w) + 1, tiles - 1);
    bound += size_t(hi.x - lo.x + 1) * size_t(hi.y - lo.y + 1);
  }
  return bound;
}
// The program of one culling stage, shaders/passes/<name>.comp.
GLuint stageProgram(const PassContext& ctx, const char* name) {
  return ctx.programs.get(
      {name, {{GL_COMPUTE_SHADER, std::string("passes/") + name + ".comp"}}, {}});
}
}  // namespace

void LightCulling::growList(size_t need) {
  capacity_ = std::max(capacity_, need + need / 4);  // headroom: fewer reallocations
  indices_ =
      gl::createBuffer("tile light indices", (kTileHeaderUints + capacity_) * sizeof(uint32_t));
}

void LightCulling::uploadBatches(const void* records, size_t count) {
  if (batch_stride_ == 0) {
    GLint align = 0;
    glGetIntegerv(GL_UNIFORM_BUFFER_OFFSET_ALIGNMENT, &align);
    const size_t a = std::max<size_t>(size_t(align), 1);
    batch_stride_ = (sizeof(glsl::CullBatch) + a - 1) / a * a;
  }
  if (!batches_ || count > batch_records_) {
    batch_records_ = std::max(count, batch_records_);
    batches_ = gl::createBuffer("culling batches", batch_records_ * batch_stride_);
  }
  std::vector<std::byte> bytes(count * batch_stride_);
  for (size_t i = 0; i < count; ++i) {
    std::memcpy(bytes.data() + i * batch_stride_,
                static_cast<const std::byte*>(records) + i * sizeof(glsl::CullBatch),
                sizeof(glsl::CullBatch));
  }
  glNamedBufferSubData(batches_.id(), 0, GLsizeiptr(bytes.size()), bytes.data());
}

uint32_t LightCulling::readTotal() const {
  uint32_t total = 0;
  if (total_) glGetNamedBufferSubData(total_.id(), 0, sizeof total, &total);
  return total;
}

TileListView LightCulling::view() const {
  return {ranges_.id(), types_.id(), indices_.id(), capacity_};
}

void LightCulling::ensureBuffers(size_t tiles, size_t groups, size_t lights, size_t mask_uints) {
  if (!ranges_ || tiles > tiles_ || groups > groups_) {
    tiles_ = std::max(tiles, tiles_);
    groups_ = std::max(groups, groups_);
    ranges_ = gl::createBuffer("tile light ranges", tiles_ * 2 * sizeof(uint32_t));
    types_ = gl::createBuffer("tile light type split", tiles_ * 2 * sizeof(uint32_t));
    tile_state_ = gl::createBuffer("culling tile counts and cursors",
                                   tiles_ * HV_CULL_TILE_STATE_UINTS * sizeof(uint32_t));
    // Per tile, then per group its blocks' and its own box (shaders/common/cull_layout.glsl).
    bounds_ = gl::createBuffer(
        "culling tile, block and group bounds",
        (tiles_ + groups_ * HV_CULL_BOXES_PER_GROUP) * HV_CULL_BOX_VEC4S * sizeof(glm::vec4));
  }
  if (!lights_ || lights > lights_capacity_) {
    lights_capacity_ = std::max<size_t>(lights, 1);
    lights_ = gl::createBuffer("culling lights (view sphere, tile rectangle)",
                               lights_capacity_ * sizeof(glsl::CullLight));
  }
  if (!masks_ || mask_uints > mask_uints_) {
    mask_uints_ = mask_uints;
    masks_ = gl::createBuffer("culling group light masks", mask_uints_ * sizeof(uint32_t));
    const uint32_t zero = 0;  // the walks keep them 0 between frames
    glClearNamedBufferData(masks_.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
  }
}

// Tiled culling (shaders/passes/light_cull_*.comp; docs/lights.md): per tile, its surface bounds
// (and per block of 2 x 4 tiles and per group of 8 x 8 tiles); per light and band of group rows,
// its view sphere and tile rectangle, and its bit in the light mask of every group its sphere
// touches; per group, the mask refined per block, then each tile's walk of its block's mask in
// light order, twice: count, then (after one reservation per group) write. Up to
// HV_CULL_FUSED_MAX_LIGHTS lights the last steps are one dispatch; above, the lights are binned
// and walked in batches. No cap on a tile's list: the index list is sized before the dispatches
// from an upper bound computed on the CPU (listBound: the lights' tile rectangles, which contain
// every pair the GPU can find), so nothing waits for the GPU. Only when that bound exceeds
// Input::bound_limit (32 Mi entries, 128 MiB, by default) is the exact total read back after the
// dispatches (a pipeline stall on a GPU) and, if the list was too small, the list grown to it
// and the culling run again.
// What one frame's culling dispatches: the grid of groups, the batches and their records.
struct LightCulling::Plan {
  size_t tiles = 0, groups = 0;
  GLuint groups_x = 0, groups_y = 0;
  GLuint bands = 0;  // bands of HV_CULL_BIN_GROUP_ROWS group rows (binning)
  size_t batch_lights = 0, batches = 0;
  size_t words = 0, summary = 0;  // mask and summary words per group
  bool fused = false;             // one batch, binned and walked in one dispatch each
  bool few = false;               // a handful of lights: one dispatch (light_cull_few.comp)
  // The dispatches' CullBatch records, one uniform-buffer range each: record 0 for the stages
  // that read no batch (bounds, reserve), record 1 + b for batch b.
  std::vector<glsl::CullBatch> records;
};

LightCulling::Plan LightCulling::plan(const FrameBlock& f, const Input& in, size_t bound) {
  Plan p;
  p.tiles = size_t(f.viewport.z) * f.viewport.w;
  p.groups_x = (f.viewport.z + HV_CULL_GROUP_TILES - 1) / HV_CULL_GROUP_TILES;
  p.groups_y = (f.viewport.w + HV_CULL_GROUP_TILES - 1) / HV_CULL_GROUP_TILES;
  p.groups = size_t(p.groups_x) * p.groups_y;
  p.bands = (p.groups_y + HV_CULL_BIN_GROUP_ROWS - 1) / HV_CULL_BIN_GROUP_ROWS;
  p.batch_lights = in.batch_lights > 0 && in.batch_lights < HV_CULL_FUSED_MAX_LIGHTS
                       ? in.batch_lights
                       : HV_CULL_FUSED_MAX_LIGHTS;
  p.fused = in.light_count <= p.batch_lights && p.batch_lights == HV_CULL_FUSED_MAX_LIGHTS;
  // One dispatch for a handful of lights, or for up to kCullFewCoveringLights lights that reach
  // kCullFewCoverage of the tiles or more on average (the list's bound over the tiles: the
  // stages' group and block tests then have little to skip).
  static_assert(kCullFewCoveringLights <= HV_CULL_FEW_MAX_LIGHTS);
  const size_t few = std::min<size_t>(in.few_lights, HV_CULL_FEW_MAX_LIGHTS);
  const bool covering = in.few_lights > 0 && in.light_count <= kCullFewCoveringLights &&
                        double(bound) >= kCullFewCoverage * double(in.light_count * p.tiles);
  p.few = p.fused && (in.light_count <= few || covering);
  // Mask words per group: one bit per light of a batch; summary words: one bit per mask word.
  p.words = (std::min(in.light_count, p.batch_lights) + 31) / 32;
  p.summary = (p.words + 31) / 32;
  p.batches = (in.light_count + p.batch_lights - 1) / p.batch_lights;
  p.records.assign(1 + p.batches, {0, 0, uint32_t(p.words), uint32_t(p.summary)});
  for (size_t b = 0; b < p.batches; ++b) {
    p.records[1 + b].first = uint32_t(b * p.batch_lights);
    p.records[1 + b].end = uint32_t(std::min((b + 1) * p.batch_lights, in.light_count));
  }
  return p;
}

// One stage with batch record `record` (BIN: per light of the batch and band; others: per group
// of tiles).
void LightCulling::dispatch(gl::PassBindings& b, const Plan& p, GLuint program, size_t record,
                            bool per_light) const {
  b.use(program);
  b.uniformRange(HV_UBO_CULL_BATCH, batches_.id(), GLintptr(record * batch_stride_),
                 sizeof(glsl::CullBatch));
  if (per_light) {
    const size_t n = p.records[record].end - p.records[record].first;
    glDispatchCompute(GLuint((n + HV_CULL_BIN_LIGHTS - 1) / HV_CULL_BIN_LIGHTS), p.bands, 1);
  } else {
    glDispatchCompute(p.groups_x, p.groups_y, 1);
  }
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

// Every stage once: the few-lights dispatch, or the staged path.
void LightCulling::cull(const PassContext& ctx, gl::PassBindings& b, const Plan& p,
                        bool stage_timers) const {
  b.storage(HV_BINDING_TILE_INDICES, indices_.id());
  if (p.few) {
    const uint32_t zero = 0;  // the list's total, for the groups' reservations
    glClearNamedBufferSubData(indices_.id(), GL_R32UI, 0, sizeof zero, GL_RED_INTEGER,
                              GL_UNSIGNED_INT, &zero);
    const StageTimer t(ctx.timer, stage_timers, "light_cull_few");
    dispatch(b, p, stageProgram(ctx, "light_cull_few"), 1, false);
  } else {
    stages(ctx, b, p, stage_timers);
  }
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
  // The list's header holds the total; the CPU reads it from this copy (readTotal).
  glCopyNamedBufferSubData(indices_.id(), total_.id(), 0, 0, sizeof(uint32_t));
}

// The staged path: bounds, then binning and walks (one dispatch each, or per batch).
void LightCulling::stages(const PassContext& ctx, gl::PassBindings& b, const Plan& p,
                          bool stage_timers) const {
  auto stage = [&](const char* name) { return stageProgram(ctx, name); };
  const GLuint bin = stage("light_cull_bin");
  {
    const StageTimer t(ctx.timer, stage_timers, "light_cull_bounds");
    dispatch(b, p, stage("light_cull_bounds"), 0, false);  // also sets the list's total to 0
  }
  if (p.fused) {
    {
      const StageTimer t(ctx.timer, stage_timers, "light_cull_bin");
      dispatch(b, p, bin, 1, true);
    }
    const StageTimer t(ctx.timer, stage_timers, "light_cull_tiles");
    dispatch(b, p, stage("light_cull_tiles"), 1, false);
  } else {  // batches: binning and walks interleave, timed together
    const StageTimer t(ctx.timer, stage_timers, "light_cull_batches");
    const GLuint count = stage("light_cull_count"), fill = stage("light_cull_fill");
    for (size_t k = 0; k < p.batches; ++k) {
      dispatch(b, p, bin, 1 + k, true);
      dispatch(b, p, count, 1 + k, false);
    }
    dispatch(b, p, stage("light_cull_reserve"), 0, false);
    for (size_t k = 0; k < p.batches; ++k) {
      dispatch(b, p, bin, 1 + k, true);
      dispatch(b, p, fill, 1 + k, false);
    }
  }
}

// Tiled culling (shaders/passes/light_cull_*.comp; docs/lights.md): per tile, its surface bounds
// (and per block of 2 x 4 tiles and per group of 8 x 8 tiles); per light and band of group rows,
// its view sphere and tile rectangle, and its bit in the light mask of every group its sphere
// touches; per group, the mask refined per block, then each tile's walk of its block's mask in
// light order, twice: count, then (after one reservation per group) write. Up to
// HV_CULL_FUSED_MAX_LIGHTS lights the last steps are one dispatch; above, the lights are binned
// and walked in batches. Up to Input::few_lights lights (kCullFewLights) all of it is one
// dispatch, every light tested against every tile (light_cull_few.comp): the same lists. No cap
// on a tile's list: the index list is sized before the dispatches from an upper bound computed on
// the CPU (listBound: the lights' tile rectangles, which contain every pair the GPU can find), so
// nothing waits for the GPU. Only when that bound exceeds Input::bound_limit (32 Mi entries, 128
// MiB, by default) is the exact total read back after the dispatches (a pipeline stall on a GPU)
// and, if the list was too small, the list grown to it and the culling run again.
TileListView LightCulling::run(const PassContext& ctx, FrameUniforms& frame, const Input& in) {
  // One timer for the pass, or with Input::stage_timers one per stage instead (the timer does not
  // nest: the frame's total is the sum of its timers).
  std::optional<gl::ScopedPass> pass;
  if (!in.stage_timers) pass.emplace(ctx.timer, "light_cull");
  applyState(PipelineState{});
  // The list's size before anything runs: from the CPU bound, when it is small enough.
  const size_t bound = in.light_count > 0 ? listBound(*in.cull_spheres, frame.block) : 0;
  const Plan p = plan(frame.block, in, bound);
  ensureBuffers(p.tiles, p.groups, in.light_count, p.groups * (p.words + p.summary));
  if (!indices_) growList(std::max<size_t>(p.tiles * 16, 1 << 16));
  if (!total_) {  // client storage: the CPU reads it every frame, the GPU writes 4 bytes
    total_ = gl::createBuffer("tile light total (CPU copy)", sizeof(uint32_t), nullptr,
                              GL_CLIENT_STORAGE_BIT | GL_MAP_READ_BIT);
  }
  const uint32_t zero = 0;
  if (in.light_count == 0) {  // empty lists
    glClearNamedBufferSubData(indices_.id(), GL_R32UI, 0, sizeof zero, GL_RED_INTEGER,
                              GL_UNSIGNED_INT, &zero);
    glClearNamedBufferSubData(total_.id(), GL_R32UI, 0, sizeof zero, GL_RED_INTEGER,
                              GL_UNSIGNED_INT, &zero);
    for (GLuint b : {ranges_.id(), types_.id()}) {
      glClearNamedBufferSubData(b, GL_R32UI, 0, p.tiles * 2 * sizeof(uint32_t), GL_RED_INTEGER,
                                GL_UNSIGNED_INT, &zero);
    }
    return view();
  }
  const bool bounded = bound <= in.bound_limit;
  if (bounded && bound > capacity_) growList(bound);
  uploadBatches(p.records.data(), p.records.size());
  gl::PassBindings b(kPassSlots, "light_cull");
  b.storage(HV_BINDING_LIGHTS, in.lights);
  b.storage(HV_BINDING_CULL_LIGHTS, lights_.id());
  b.storage(HV_BINDING_CULL_BOUNDS, bounds_.id());
  b.storage(HV_BINDING_CULL_MASKS, masks_.id());
  b.storage(HV_BINDING_CULL_TILE_STATE, tile_state_.id());
  b.storage(HV_BINDING_TILE_RANGES, ranges_.id());
  b.storage(HV_BINDING_TILE_TYPES, types_.id());
  b.texture(HV_UNIT_DEPTH, in.depth, ctx.nearest);
  if (frame.block.tile_capacity != capacity_) {  // the list was created or grown: tell the shaders
    frame.block.tile_capacity = static_cast<uint32_t>(capacity_);
    frame.upload();
  }
  cull(ctx, b, p, in.stage_timers);
  if (!bounded) {  // the bound is too loose to allocate: read the exact total back (a stall)
    const uint32_t total = readTotal();
    ++readbacks_;
    if (total > capacity_) {  // the fill left entries out: grow to the need, cull again
      growList(total);
      frame.block.tile_capacity = static_cast<uint32_t>(capacity_);
      frame.upload();
      cull(ctx, b, p, in.stage_timers);
    }
  }
  return view();
}

}  // namespace hv::render
