// The fitted LTC table (halfvec/shading/ltc_table.hpp, layout in shaders/common/ltc.glsl) on the
// GPU: two RGBA32F textures and a linear, clamp-to-edge sampler, created on first use and bound
// only for a light pass whose program reads them (an LTC sphere or tube specular mode, or an
// error budget); and the error budget's table (halfvec/shading/error_table.hpp, layout in
// shaders/common/error_budget.glsl), one R32F 3D texture, likewise.
#pragma once

#include "halfvec/gl/bindings.hpp"
#include "halfvec/gl/objects.hpp"

namespace hv::render {

class LtcTextures {
 public:
  // Binds the two textures with the sampler to HV_LTC_TEXTURE_UNIT0 / UNIT1 in the pass's scope
  // (which releases them), uploading the table the first time.
  void bind(gl::PassBindings& b);
  // Binds the error budget's table with the same sampler to `unit` (HV_UNIT_ERROR_TABLE or
  // HV_UNIT_FORWARD_ERROR_TABLE), uploading it the first time.
  void bindErrorTable(gl::PassBindings& b, GLuint unit);

 private:
  void createSampler();
  gl::Texture tex_[2], error_table_;
  gl::Sampler sampler_;
};

}  // namespace hv::render
