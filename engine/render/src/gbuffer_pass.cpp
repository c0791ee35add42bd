// G-buffer pass. In: the scene's geometry, materials, textures. Out: base color + cavity,
// metallic/roughness/model, octahedral normal, reversed-Z depth, and emissive in the HDR target.
// One program per material variant of the scene's VariantKey (docs/variants.md).
#include <glm/gtc/type_ptr.hpp>

#include "passes.hpp"
#include "pipeline_state.hpp"

namespace hv::render {

void runGBufferPass(const PassContext& ctx, const GBufferPassInput& in,
                    const GBufferPassOutput& out) {
  gl::ScopedPass pass(ctx.timer, "gbuffer");
  PipelineState st;
  st.depth_test = true;
  st.depth_write = true;
  st.depth_func = GL_GREATER;  // reversed Z: nearer is larger
  st.cull_back = true;
  st.framebuffer_srgb = true;  // base color target is sRGB-encoded on write
  st.reversed_z_clip = true;
  applyState(st);

  glBindFramebuffer(GL_FRAMEBUFFER, out.framebuffer);
  glViewport(0, 0, out.width, out.height);
  const float zero[4] = {0, 0, 0, 0};
  for (int i = 0; i < 4; ++i) glClearNamedFramebufferfv(out.framebuffer, GL_COLOR, i, zero);
  const float far_depth = 0.0f;  // reversed Z clears to 0 (infinity)
  glClearNamedFramebufferfv(out.framebuffer, GL_DEPTH, 0, &far_depth);
  // Per-term debug views: the HDR target (attachment 3) keeps its clear value, 0, instead of the
  // emissive (after the clear: the color mask also masks clears).
  if (!in.emissive) glColorMaski(3, GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);

  glBindVertexArray(in.gpu.vertexArray());
  gl::PassBindings b(kPassSlots, "gbuffer");
  int bound_material = -1;
  int bound_variant = -1;
  bool culling = true;
  const auto& draws = in.gpu.draws();
  // draw_order groups the draws by material variant: one program switch per variant.
  for (size_t di : in.draw_order) {
    const DrawItem& d = draws[di];
    const int variant = in.key.material_variant[size_t(d.material)];
    if (variant != bound_variant) {
      bound_variant = variant;
      b.use(ctx.programs.get(in.programs.at(size_t(variant))));
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
    if (d.material != bound_material) {
      bound_material = d.material;
      b.uniformRange(HV_UBO_MATERIAL, in.gpu.materialBuffer(),
                     GLintptr(size_t(d.material) * in.gpu.materialStride()),
                     GLsizeiptr(sizeof(GpuMaterial)));
      const auto tex = in.gpu.materialTextures(d.material);
      static_assert(std::tuple_size_v<decltype(tex)> == HV_MATERIAL_TEXTURE_COUNT);
      for (GLuint u = 0; u < tex.size(); ++u) {
        b.texture(HV_UNIT_MATERIAL_TEXTURES + u, tex[u].texture, tex[u].sampler);
      }
    }
    glDrawElementsBaseVertex(
        GL_TRIANGLES, GLsizei(d.index_count), GL_UNSIGNED_INT,
        reinterpret_cast<const void*>(size_t(d.first_index) * sizeof(uint32_t)), d.base_vertex);
  }
  glBindVertexArray(0);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glFrontFace(GL_CCW);
  if (!in.emissive) glColorMaski(3, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
}

}  // namespace hv::render
