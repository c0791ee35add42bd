// Tone-map pass. In: the HDR target. Out: RGBA8 (internal target or the window's framebuffer).
// With a G-buffer or culling debug view selected it shows that channel or the lights per tile
// instead; the per-term views (termView) are tone-mapped like the normal image.
#include <string>

#include "passes.hpp"
#include "pipeline_state.hpp"

namespace hv::render {

void runTonemapPass(const PassContext& ctx, const TonemapPassInput& in,
                    const TonemapPassOutput& out, GLuint fullscreen_vao) {
  gl::ScopedPass pass(ctx.timer, "tonemap");
  applyState(PipelineState{});
  const RenderSettings& s = in.settings;
  gl::PassBindings b(kPassSlots, "tonemap");
  GLuint prog;
  // The predicted_error view is drawn from the light pass's output by the debug view's shader.
  const bool tone_mapped =
      (in.view == DebugView::None || termView(in.view)) && in.view != DebugView::PredictedError;
  if (tone_mapped) {
    gl::DefineSet defines;  // the tone map's rows of the settings table
    for (auto& [name, value] : settingDefines(s, SettingPass::ToneMap))
      defines.push_back({name, value});
    prog = ctx.programs.get({"tonemap",
                             {{GL_VERTEX_SHADER, "passes/fullscreen.vert"},
                              {GL_FRAGMENT_SHADER, "passes/tonemap.frag"}},
                             defines});
    b.texture(HV_UNIT_HDR, in.hdr, ctx.nearest);
  } else {
    prog = ctx.programs.get({"debug_view",
                             {{GL_VERTEX_SHADER, "passes/fullscreen.vert"},
                              {GL_FRAGMENT_SHADER, "passes/debug_view.frag"}},
                             {}});
    bindGBuffer(b, in.gbuffer, ctx.nearest);
    // 0 before any culling ran: the lights_per_tile view is the only reader, and it culls.
    b.storage(HV_BINDING_TILE_RANGES, in.tile_ranges);
    b.texture(HV_UNIT_DEBUG_HDR, in.hdr, ctx.nearest);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, out.framebuffer);
  glViewport(0, 0, out.width, out.height);
  b.use(prog);
  glBindVertexArray(fullscreen_vao);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  if (out.capture != 0 && out.capture != out.framebuffer) {
    // Keep the internal target in sync for captures (F12, tests).
    glBlitNamedFramebuffer(out.framebuffer, out.capture, 0, 0, out.width, out.height, 0, 0,
                           out.width, out.height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  }
  glBindVertexArray(0);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

}  // namespace hv::render
