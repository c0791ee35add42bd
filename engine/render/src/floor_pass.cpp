// The floor pass (DebugOptions::floor_pass): the bench's yardstick. In: the G-buffer. Out: a
// scratch RGBA16F target nobody reads.
#include "passes.hpp"
#include "pipeline_state.hpp"

namespace hv::render {

void runFloorPass(const PassContext& ctx, const GBufferView& gbuffer, GLuint scratch, int width,
                  int height) {
  gl::ScopedPass pass(ctx.timer, "floor");
  applyState(PipelineState{});
  glUseProgram(ctx.programs.get({"floor", {{GL_COMPUTE_SHADER, "passes/floor.comp"}}, {}}));
  bindGBuffer(gbuffer, ctx.nearest);
  glBindImageTexture(HV_IMAGE_FLOOR, scratch, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
  glDispatchCompute((width + kTileSize - 1) / kTileSize, (height + kTileSize - 1) / kTileSize, 1);
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  unbindGBuffer();
  glBindImageTexture(HV_IMAGE_FLOOR, 0, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
  glUseProgram(0);
}

}  // namespace hv::render
