// Light culling (compute, per 16x16 tile) and the light pass (compute, per pixel).
// In: depth, G-buffer, lights. Out: per-tile light lists; direct light added into the HDR target.
#include <algorithm>

#include "render/pipeline_state.hpp"
#include "render/renderer.hpp"
#include "render/targets.hpp"

namespace hv::render {

namespace {
constexpr size_t kTileHeaderUints = 4;  // counter + padding before the index array
}

void Renderer::cullLightsPass(FrameBlock& frame) {
  gl::ScopedPass pass(timer_, "light_cull");
  applyState(PipelineState{});
  Targets& t = *targets_;
  const uint32_t tiles = frame.viewport.z * frame.viewport.w;
  if (!tile_ranges_ || tile_ranges_.id() == 0 ||
      size_t(tiles) * 2 * sizeof(uint32_t) > size_t(tile_ranges_capacity_)) {
    tile_ranges_capacity_ = size_t(tiles) * 2 * sizeof(uint32_t);
    tile_ranges_ = gl::createBuffer("tile light ranges", tile_ranges_capacity_);
  }
  if (tile_capacity_ == 0) tile_capacity_ = std::max<size_t>(size_t(tiles) * 64, 1 << 16);
  const GLuint prog = programs_.get(
      {"light_cull", {{GL_COMPUTE_SHADER, "passes/light_cull.comp"}}, lightingDefines()});
  for (int attempt = 0; attempt < 2; ++attempt) {
    if (!tile_indices_) {
      tile_indices_ = gl::createBuffer("tile light indices",
                                       (kTileHeaderUints + tile_capacity_) * sizeof(uint32_t));
    }
    const uint32_t zero = 0;
    glClearNamedBufferSubData(tile_indices_.id(), GL_R32UI, 0, sizeof(uint32_t), GL_RED_INTEGER,
                              GL_UNSIGNED_INT, &zero);
    if (frame.counts.y != tile_capacity_) {  // the list was created or grown: tell the shaders
      frame.counts.y = static_cast<uint32_t>(tile_capacity_);
      glNamedBufferSubData(frame_ubo_.id(), 0, sizeof frame, &frame);
    }
    glUseProgram(prog);
    glBindTextureUnit(3, t.depth.id());
    glBindSampler(3, nearest_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, gpu_->lightBuffer());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 4, tile_ranges_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 5, tile_indices_.id());
    glDispatchCompute(frame.viewport.z, frame.viewport.w, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
    uint32_t total = 0;
    glGetNamedBufferSubData(tile_indices_.id(), 0, sizeof total, &total);
    tile_entries_ = total;
    if (total <= tile_capacity_) break;
    // The lists did not fit: grow to what this frame needs (plus headroom) and cull again.
    tile_capacity_ = size_t(total) + total / 4;
    tile_indices_.reset();
  }
  glBindSampler(3, 0);
  glUseProgram(0);
}

void Renderer::lightPass(const FrameBlock& frame) {
  gl::ScopedPass pass(timer_, "light");
  applyState(PipelineState{});
  Targets& t = *targets_;
  if (gpu_->lightCount() == 0) return;
  const GLuint prog =
      programs_.get({"light", {{GL_COMPUTE_SHADER, "passes/light_shade.comp"}}, lightingDefines()});
  glUseProgram(prog);
  const GLuint inputs[4] = {t.base_cavity.id(), t.material.id(), t.normal.id(), t.depth.id()};
  for (GLuint u = 0; u < 4; ++u) {
    glBindTextureUnit(u, inputs[u]);
    glBindSampler(u, nearest_.id());
  }
  glBindImageTexture(0, t.hdr.id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_RGBA16F);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, gpu_->lightBuffer());
  if (tile_indices_) {
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 4, tile_ranges_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 5, tile_indices_.id());
  }
  glDispatchCompute(frame.viewport.z, frame.viewport.w, 1);
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
  for (GLuint u = 0; u < 4; ++u) glBindSampler(u, 0);
  glBindImageTexture(0, 0, 0, GL_FALSE, 0, GL_READ_WRITE, GL_RGBA16F);
  glUseProgram(0);
}

}  // namespace hv::render
