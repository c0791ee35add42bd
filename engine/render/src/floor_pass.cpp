// The floor pass (DebugOptions::floor_pass): the bench's yardstick. In: the G-buffer. Out: a
// scratch RGBA16F target nobody reads.
#include "passes.hpp"
#include "pipeline_state.hpp"

namespace hv::render {

void runFloorPass(const PassContext& ctx, const GBufferView& gbuffer, GLuint scratch, int width,
                  int height) {
  gl::ScopedPass pass(ctx.timer, "floor");
  applyState(PipelineState{});
  gl::PassBindings b(kPassSlots, "floor");
  b.use(ctx.programs.get({"floor", {{GL_COMPUTE_SHADER, "passes/floor.comp"}}, {}}));
  bindGBuffer(b, gbuffer, ctx.nearest);
  b.image(HV_IMAGE_FLOOR, scratch, GL_WRITE_ONLY, GL_RGBA16F);
  glDispatchCompute((width + kTileSize - 1) / kTileSize, (height + kTileSize - 1) / kTileSize, 1);
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
}

}  // namespace hv::render
