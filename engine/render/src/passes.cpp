// Helpers the passes share (passes.hpp).
#include "passes.hpp"

namespace hv::render {

void FrameUniforms::upload() const {
  glNamedBufferSubData(ubo, 0, sizeof block, &block);
}

void bindGBuffer(const GBufferView& g, GLuint sampler) {
  const GLuint units[4] = {HV_UNIT_BASE_CAVITY, HV_UNIT_MATERIAL, HV_UNIT_NORMAL, HV_UNIT_DEPTH};
  const GLuint textures[4] = {g.base_cavity, g.material, g.normal, g.depth};
  for (int i = 0; i < 4; ++i) {
    glBindTextureUnit(units[i], textures[i]);
    glBindSampler(units[i], sampler);
  }
}

void unbindGBuffer() {
  for (GLuint u : {HV_UNIT_BASE_CAVITY, HV_UNIT_MATERIAL, HV_UNIT_NORMAL, HV_UNIT_DEPTH}) {
    glBindSampler(u, 0);
  }
}

}  // namespace hv::render
