#include "ltc_textures.hpp"

#include <vector>

#include "halfvec/shading/error_table.hpp"
#include "halfvec/shading/ltc_table.hpp"
#include "halfvec/shading/shading.hpp"

namespace hv::render {

void LtcTextures::createSampler() {
  if (sampler_) return;
  sampler_ = gl::createSampler("LTC and error tables (linear clamp)");
  glSamplerParameteri(sampler_.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glSamplerParameteri(sampler_.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glSamplerParameteri(sampler_.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glSamplerParameteri(sampler_.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glSamplerParameteri(sampler_.id(), GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
}

void LtcTextures::bindErrorTable(gl::PassBindings& b, GLuint unit) {
  if (!error_table_) {
    constexpr int nx = HV_ERR_TEXELS_X;
    constexpr int ny = HV_ERR_SIN_CELLS, nz = HV_ERR_NOV_CELLS;
    GLuint id = 0;
    glCreateTextures(GL_TEXTURE_3D, 1, &id);
    error_table_ = gl::Texture(id, "error budget table (ln E_rp / R)");
    glTextureStorage3D(id, 1, GL_R32F, nx, ny, nz);
    glTextureSubImage3D(id, 0, 0, 0, 0, nx, ny, nz, GL_RED, GL_FLOAT, errorTableData().data());
  }
  createSampler();
  b.texture(unit, error_table_.id(), sampler_.id());
}

void LtcTextures::bind(gl::PassBindings& b) {
  if (!tex_[0]) {
    constexpr int n = HV_LTC_TABLE_SIZE;
    const std::span<const float> data = ltcTableData();
    const char* names[2] = {"LTC table 0 (a_x, a_y, s over alpha; d_x)",
                            "LTC table 1 (n_f, n_fresnel)"};
    for (int t = 0; t < 2; ++t) {
      // The cell's 8 floats hold both textures' texels: split them.
      std::vector<float> texels(size_t(n) * n * 4);
      for (size_t c = 0; c < size_t(n) * n; ++c) {
        for (int k = 0; k < 4; ++k) texels[c * 4 + k] = data[c * kLtcFloatsPerCell + t * 4 + k];
      }
      tex_[t] = gl::createTexture2D(names[t], GL_RGBA32F, n, n);
      glTextureSubImage2D(tex_[t].id(), 0, 0, 0, n, n, GL_RGBA, GL_FLOAT, texels.data());
    }
  }
  createSampler();
  const GLuint units[2] = {HV_LTC_TEXTURE_UNIT0, HV_LTC_TEXTURE_UNIT1};
  for (int t = 0; t < 2; ++t) b.texture(units[t], tex_[t].id(), sampler_.id());
}

}  // namespace hv::render
