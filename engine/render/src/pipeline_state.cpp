#include "pipeline_state.hpp"

namespace hv::render {

namespace {
void enable(GLenum cap, bool on) {
  on ? glEnable(cap) : glDisable(cap);
}
}  // namespace

void applyState(const PipelineState& s) {
  enable(GL_DEPTH_TEST, s.depth_test);
  glDepthMask(s.depth_write ? GL_TRUE : GL_FALSE);
  glDepthFunc(s.depth_func);
  enable(GL_CULL_FACE, s.cull_back);
  glCullFace(GL_BACK);
  glFrontFace(GL_CCW);
  enable(GL_FRAMEBUFFER_SRGB, s.framebuffer_srgb);
  enable(GL_BLEND, s.blend_add || s.blend_over);
  if (s.blend_over) {
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
  } else {
    glBlendFunc(GL_ONE, GL_ONE);
  }
  glClipControl(GL_LOWER_LEFT, s.reversed_z_clip ? GL_ZERO_TO_ONE : GL_NEGATIVE_ONE_TO_ONE);
}

}  // namespace hv::render
