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
  GLuint prog;
  const bool tone_mapped = in.view == DebugView::None || termView(in.view);
  if (tone_mapped) {
    gl::DefineSet defines;  // the tone map's rows of the settings table
    for (auto& [name, value] : settingDefines(s, SettingPass::ToneMap))
      defines.push_back({name, value});
    prog = ctx.programs.get({"tonemap",
                             {{GL_VERTEX_SHADER, "passes/fullscreen.vert"},
                              {GL_FRAGMENT_SHADER, "passes/tonemap.frag"}},
                             defines});
    glBindTextureUnit(HV_UNIT_HDR, in.hdr);
    glBindSampler(HV_UNIT_HDR, ctx.nearest);
  } else {
    prog = ctx.programs.get({"debug_view",
                             {{GL_VERTEX_SHADER, "passes/fullscreen.vert"},
                              {GL_FRAGMENT_SHADER, "passes/debug_view.frag"}},
                             {}});
    bindGBuffer(in.gbuffer, ctx.nearest);
    if (in.tile_ranges) {
      glBindBufferBase(GL_SHADER_STORAGE_BUFFER, HV_BINDING_TILE_RANGES, in.tile_ranges);
    }
  }
  glBindFramebuffer(GL_FRAMEBUFFER, out.framebuffer);
  glViewport(0, 0, out.width, out.height);
  glUseProgram(prog);
  glBindVertexArray(fullscreen_vao);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  if (out.capture != 0 && out.capture != out.framebuffer) {
    // Keep the internal target in sync for captures (F12, tests).
    glBlitNamedFramebuffer(out.framebuffer, out.capture, 0, 0, out.width, out.height, 0, 0,
                           out.width, out.height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  }
  glBindVertexArray(0);
  glUseProgram(0);
  if (tone_mapped) {
    glBindSampler(HV_UNIT_HDR, 0);
  } else {
    unbindGBuffer();
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

}  // namespace hv::render
