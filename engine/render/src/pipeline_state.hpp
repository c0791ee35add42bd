// Fixed-function state as one value a pass applies in full, so no state leaks from one pass
// into the next (each pass states everything it depends on; the frame ends in the default).
#pragma once

#include "halfvec/gl/gl.hpp"

namespace hv::render {

struct PipelineState {
  bool depth_test = false;
  bool depth_write = false;
  GLenum depth_func = GL_GREATER;  // reversed Z
  bool cull_back = false;
  bool framebuffer_srgb = false;
  bool blend_add = false;        // ONE, ONE: passes that add light
  bool blend_over = false;       // SRC_ALPHA, ONE_MINUS_SRC_ALPHA on colour, destination alpha kept
  bool reversed_z_clip = false;  // glClipControl(LOWER_LEFT, ZERO_TO_ONE)
};

void applyState(const PipelineState& s);

}  // namespace hv::render
