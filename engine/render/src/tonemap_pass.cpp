// Tone-map pass. In: the HDR target. Out: RGBA8 (internal target or the window's framebuffer).
// With a G-buffer or culling debug view selected it shows that channel or the lights per tile
// instead; the per-term views (termView) are tone-mapped like the normal image.
#include "pipeline_state.hpp"
#include "halfvec/render/renderer.hpp"
#include "targets.hpp"

namespace hv::render {

void Renderer::tonemapPass(DebugView view, std::optional<GLuint> present_fbo, int width,
                           int height) {
  gl::ScopedPass pass(timer_, "tonemap");
  applyState(PipelineState{});
  Targets& t = *targets_;
  const RenderSettings& s = scene_->settings;
  GLuint prog;
  if (view == DebugView::None || termView(view)) {
    prog = programs_.get({"tonemap",
                          {{GL_VERTEX_SHADER, "passes/fullscreen.vert"},
                           {GL_FRAGMENT_SHADER, "passes/tonemap.frag"}},
                          {{"HV_TONEMAP", std::to_string(static_cast<int>(s.tone_map))},
                           {"HV_GAMMA", std::to_string(static_cast<int>(s.gamma))}}});
    glBindTextureUnit(0, t.hdr.id());
    glBindSampler(0, nearest_.id());
  } else {
    prog = programs_.get({"debug_view",
                          {{GL_VERTEX_SHADER, "passes/fullscreen.vert"},
                           {GL_FRAGMENT_SHADER, "passes/debug_view.frag"}},
                          {}});
    const GLuint inputs[4] = {t.base_cavity.id(), t.material.id(), t.normal.id(), t.depth.id()};
    for (GLuint u = 0; u < 4; ++u) {
      glBindTextureUnit(u, inputs[u]);
      glBindSampler(u, nearest_.id());
    }
    if (tile_ranges_) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 4, tile_ranges_.id());
  }
  const GLuint fbo = present_fbo.value_or(t.output.id());
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  glViewport(0, 0, width, height);
  glUseProgram(prog);
  glBindVertexArray(empty_vao_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  if (present_fbo) {  // keep the internal target in sync for captures (F12, tests)
    glBlitNamedFramebuffer(fbo, t.output.id(), 0, 0, width, height, 0, 0, width, height,
                           GL_COLOR_BUFFER_BIT, GL_NEAREST);
  }
  glBindVertexArray(0);
  glUseProgram(0);
  for (GLuint u = 0; u < 4; ++u) glBindSampler(u, 0);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

}  // namespace hv::render
