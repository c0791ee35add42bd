// Post-process anti-aliasing after tone mapping, its own pass with explicit input and output:
// FXAA (Lottes 2009, "FXAA", NVIDIA whitepaper; the 3.11 "console" variant of 2011) in
// shaders/passes/fxaa.frag with its decisions in shaders/common/fxaa.glsl. The Renderer runs it
// when ViewOptions::aa is Fxaa and times it as the pass "aa".
#pragma once

#include "halfvec/gl/objects.hpp"
#include "halfvec/gl/program.hpp"
#include "halfvec/render/view_options.hpp"

namespace hv::render {

class FxaaPass {
 public:
  FxaaPass();  // needs a current GL context
  // In: `input`, a width x height RGBA8 texture of display-encoded color (sampled bilinearly,
  // clamped). Out: `output_fbo`'s color attachment 0 (width x height). Leaves the default state.
  void run(gl::ProgramCache& programs, GLuint input, GLuint output_fbo, int width, int height);

 private:
  gl::Sampler linear_;
  gl::VertexArray vao_;
};

}  // namespace hv::render
