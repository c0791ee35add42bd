// The draw loop of the passes that draw the scene's geometry with its materials (the G-buffer
// pass and the forward pass of blended surfaces).
#include <algorithm>

#include <glm/gtc/type_ptr.hpp>

#include "passes.hpp"

namespace hv::render {

void drawScene(const PassContext& ctx, gl::PassBindings& b, const SceneDraws& in) {
  glBindVertexArray(in.gpu.vertexArray());
  int bound_material = -1;
  int bound_variant = -1;
  bool culling = true;
  glEnable(GL_CULL_FACE);
  const auto& draws = in.gpu.draws();
  for (size_t di : in.order) {
    const DrawItem& d = draws[di];
    const int variant = in.key.material_variant[size_t(d.material)];
    if (variant != bound_variant) {
      bound_variant = variant;
      b.use(ctx.programs.get(in.programs.at(size_t(variant))));
      if (in.before_variant) (*in.before_variant)(variant);
    }
    const glm::mat4& model = in.scene.objects[d.object].transform;
    const glm::mat4 normal_matrix = glm::transpose(glm::inverse(model));
    glUniformMatrix4fv(HV_LOC_MODEL, 1, GL_FALSE, glm::value_ptr(model));
    glUniformMatrix4fv(HV_LOC_NORMAL_MATRIX, 1, GL_FALSE, glm::value_ptr(normal_matrix));
    // A mirroring transform flips the winding: cull the other face.
    const bool mirrored = glm::determinant(glm::mat3(model)) < 0.0f;
    glFrontFace(mirrored ? GL_CW : GL_CCW);
    if (d.double_sided == culling) {
      culling = !d.double_sided;
      culling ? glEnable(GL_CULL_FACE) : glDisable(GL_CULL_FACE);
    }
    if (in.before_draw) (*in.before_draw)(di);
    if (d.material != bound_material) {
      bound_material = d.material;
      b.uniformRange(HV_UBO_MATERIAL, in.gpu.materialBuffer(),
                     GLintptr(size_t(d.material) * in.gpu.materialStride()),
                     GLsizeiptr(sizeof(GpuMaterial)));
      const auto tex = in.gpu.materialTextures(d.material);
      static_assert(std::tuple_size_v<decltype(tex)> == HV_MATERIAL_TEXTURE_COUNT);
      for (GLuint u = 0; u < std::min<GLuint>(in.material_textures, GLuint(tex.size())); ++u) {
        b.texture(HV_UNIT_MATERIAL_TEXTURES + u, tex[u].texture, tex[u].sampler);
      }
    }
    glDrawElementsBaseVertex(
        GL_TRIANGLES, GLsizei(d.index_count), GL_UNSIGNED_INT,
        reinterpret_cast<const void*>(size_t(d.first_index) * sizeof(uint32_t)), d.base_vertex);
  }
  glBindVertexArray(0);
  glFrontFace(GL_CCW);
}

}  // namespace hv::render
