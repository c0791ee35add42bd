// Light culling (compute: per tile bounds, per light count/fill, one scan).
// In: depth, lights. Out: per-tile light lists (TileListView).
#include <algorithm>

#include "passes.hpp"
#include "pipeline_state.hpp"
#include "halfvec/shading/shading.hpp"

namespace hv::render {

namespace {
constexpr size_t kTileHeaderUints = HV_TILE_LIST_HEADER_UINTS;
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
    if (!glsl::sphereTileRect(c, s.w, scale, frame.near_params.x, viewport, tiles, tile_px, r)) {
      continue;
    }
    const glm::ivec2 lo = glm::max(glm::ivec2(r.x, r.y) - 1, glm::ivec2(0));
    const glm::ivec2 hi = glm::min(glm::ivec2(r.z, r.w) + 1, tiles - 1);
    bound += size_t(hi.x - lo.x + 1) * size_t(hi.y - lo.y + 1);
  }
  return bound;
}
}  // namespace

void LightCulling::growList(size_t need) {
  capacity_ = std::max(capacity_, need + need / 4);  // headroom: fewer reallocations
  indices_ =
      gl::createBuffer("tile light indices", (kTileHeaderUints + capacity_) * sizeof(uint32_t));
}

TileListView LightCulling::view() const {
  return {ranges_.id(), types_.id(), indices_.id(), capacity_};
}

// Tiled culling in four dispatches (shaders/passes/light_cull.comp; docs/lights.md): tile surface
// bounds, per-light count, prefix sum, per-light fill. The work is tiles + lights + the (tile,
// light) pairs that touch, instead of tiles x lights. No cap on a tile's list: the index list is
// sized before the fill from an upper bound computed on the CPU (listBound: the lights' tile
// rectangles, which contain every pair the GPU can find), so nothing waits for the GPU mid-frame.
// Only when that bound exceeds Input::bound_limit (32 Mi entries, 128 MiB, by default) is the
// exact total read back between the scan and the fill (a pipeline stall on a GPU) to size the
// list to the need instead.
TileListView LightCulling::run(const PassContext& ctx, FrameUniforms& frame, const Input& in) {
  gl::ScopedPass pass(ctx.timer, "light_cull");
  applyState(PipelineState{});
  const FrameBlock& f = frame.block;
  const size_t tiles = size_t(f.viewport.z) * f.viewport.w;
  if (!ranges_ || tiles > tiles_) {
    ranges_ = gl::createBuffer("tile light ranges", tiles * 2 * sizeof(uint32_t));
    types_ = gl::createBuffer("tile light type split", tiles * 2 * sizeof(uint32_t));
    bounds_ = gl::createBuffer("tile surface bounds", tiles * 2 * 4 * sizeof(float));
    counters_ = gl::createBuffer("tile light counters", tiles * 3 * sizeof(uint32_t));
    tiles_ = tiles;
  }
  if (!indices_) growList(std::max<size_t>(tiles * 16, 1 << 16));
  // Size the list before anything runs, from the CPU bound when it is small enough.
  const size_t bound = listBound(*in.cull_spheres, f);
  const bool bounded = bound <= in.bound_limit;
  if (bounded && bound > capacity_) growList(bound);
  auto stage = [&](const char* name, const char* value) {
    return ctx.programs.get(
        {name, {{GL_COMPUTE_SHADER, "passes/light_cull.comp"}}, {{"HV_CULL_STAGE", value}}});
  };
  const GLuint bounds_prog = stage("light_cull_bounds", "0");
  const GLuint lights_prog = stage("light_cull_lights", "1");
  const GLuint scan_prog = stage("light_cull_scan", "2");
  const uint32_t lights = f.counts.x;
  const GLuint light_groups = (lights + 63) / 64;

  const uint32_t zero = 0;
  glClearNamedBufferSubData(counters_.id(), GL_R32UI, 0, tiles * 3 * sizeof(uint32_t),
                            GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, HV_BINDING_LIGHTS, in.lights);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, HV_BINDING_TILE_COUNTERS, counters_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, HV_BINDING_TILE_RANGES, ranges_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, HV_BINDING_TILE_INDICES, indices_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, HV_BINDING_TILE_TYPES, types_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, HV_BINDING_TILE_BOUNDS, bounds_.id());

  // 1. Surface bounds per tile.
  glUseProgram(bounds_prog);
  glBindTextureUnit(HV_UNIT_DEPTH, in.depth);
  glBindSampler(HV_UNIT_DEPTH, ctx.nearest);
  glDispatchCompute(f.viewport.z, f.viewport.w, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  // 2. Count the (tile, light) pairs per tile and light type.
  glUseProgram(lights_prog);
  glProgramUniform1ui(lights_prog, HV_LOC_CULL_PHASE, 0u);
  if (light_groups > 0) glDispatchCompute(light_groups, 1, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  // 3. Prefix sum: exact ranges, sorted by type.
  glUseProgram(scan_prog);
  glDispatchCompute(1, 1, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
  if (!bounded) {  // the bound is too loose to allocate: read the exact total back (a stall)
    uint32_t total = 0;
    glGetNamedBufferSubData(indices_.id(), 0, sizeof total, &total);
    ++readbacks_;
    if (total > capacity_) {  // grow to the need plus headroom, keep the header
      growList(total);
      glNamedBufferSubData(indices_.id(), 0, sizeof total, &total);
      glBindBufferBase(GL_SHADER_STORAGE_BUFFER, HV_BINDING_TILE_INDICES, indices_.id());
    }
  }
  if (frame.block.counts.y != capacity_) {  // the list was created or grown: tell the shaders
    frame.block.counts.y = static_cast<uint32_t>(capacity_);
    frame.upload();
  }
  // 4. Fill: the same program writes each pair into the slot the scan reserved.
  glUseProgram(lights_prog);
  glProgramUniform1ui(lights_prog, HV_LOC_CULL_PHASE, 1u);
  if (light_groups > 0) glDispatchCompute(light_groups, 1, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
  glBindSampler(HV_UNIT_DEPTH, 0);
  glUseProgram(0);
  return view();
}

}  // namespace hv::render
