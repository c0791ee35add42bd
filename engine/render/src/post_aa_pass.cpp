// FXAA pass (halfvec/render/post_aa.hpp): one fullscreen triangle, input texture unit 0.
#include "halfvec/render/post_aa.hpp"

#include "pass_slots.hpp"
#include "pipeline_state.hpp"

namespace hv::render {

std::optional<PostAA> postAAFromString(const std::string& s) {
  if (s == "none") return PostAA::None;
  if (s == "fxaa") return PostAA::Fxaa;
  return std::nullopt;
}

const char* toString(PostAA aa) {
  return aa == PostAA::Fxaa ? "fxaa" : "none";
}

FxaaPass::FxaaPass() {
  linear_ = gl::createSampler("fxaa input (linear clamp)");
  glSamplerParameteri(linear_.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glSamplerParameteri(linear_.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glSamplerParameteri(linear_.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glSamplerParameteri(linear_.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  vao_ = gl::createVertexArray("fxaa fullscreen triangle");
}

void FxaaPass::run(gl::ProgramCache& programs, GLuint input, GLuint output_fbo, int width,
                   int height) {
  applyState(PipelineState{});
  const GLuint prog = programs.get(
      {"fxaa",
       {{GL_VERTEX_SHADER, "passes/fullscreen.vert"}, {GL_FRAGMENT_SHADER, "passes/fxaa.frag"}},
       {}});
  glBindFramebuffer(GL_FRAMEBUFFER, output_fbo);
  glViewport(0, 0, width, height);
  {
    gl::PassBindings b(kPassSlots, "fxaa");
    b.use(prog);
    b.texture(0, input, linear_.id());  // t_ldr (fxaa.frag)
    glBindVertexArray(vao_.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

}  // namespace hv::render
