// Helpers the passes share (passes.hpp).
#include "passes.hpp"

namespace hv::render {

void FrameUniforms::upload() const {
  glNamedBufferSubData(ubo, 0, sizeof block, &block);
}

void bindGBuffer(gl::PassBindings& b, const GBufferView& g, GLuint sampler) {
  const GLuint units[4] = {HV_UNIT_BASE_CAVITY, HV_UNIT_MATERIAL, HV_UNIT_NORMAL, HV_UNIT_DEPTH};
  const GLuint textures[4] = {g.base_cavity, g.material, g.normal, g.depth};
  for (int i = 0; i < 4; ++i) b.texture(units[i], textures[i], sampler);
  if (g.coat != 0) b.texture(HV_UNIT_COAT, g.coat, sampler);
}

}  // namespace hv::render
