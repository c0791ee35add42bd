// The fitted LTC table (halfvec/shading/ltc_table.hpp, layout in shaders/common/ltc.glsl) on the
// GPU: two RGBA32F textures and a linear, clamp-to-edge sampler, created on first use and bound
// only for a light pass whose program reads them (an LTC sphere or tube specular mode).
#pragma once

#include "halfvec/gl/bindings.hpp"
#include "halfvec/gl/objects.hpp"

namespace hv::render {

class LtcTextures {
 public:
  // Binds the two textures with the sampler to HV_LTC_TEXTURE_UNIT0 / UNIT1 in the pass's scope
  // (which releases them), uploading the table the first time.
  void bind(gl::PassBindings& b);

 private:
  gl::Texture tex_[2];
  gl::Sampler sampler_;
};

}  // namespace hv::render
