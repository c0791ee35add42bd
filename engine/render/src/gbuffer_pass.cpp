// G-buffer pass. In: the scene's geometry, materials, textures. Out: base color + cavity,
// metallic/roughness/model, octahedral normal, reversed-Z depth, and emissive in the HDR target.
// One program per material variant of the scene's VariantKey (docs/variants.md).
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
  for (int i = 0; i < (out.coat ? 5 : 4); ++i) {
    glClearNamedFramebufferfv(out.framebuffer, GL_COLOR, i, zero);
  }
  const float far_depth = 0.0f;  // reversed Z clears to 0 (infinity)
  glClearNamedFramebufferfv(out.framebuffer, GL_DEPTH, 0, &far_depth);
  // The HDR target (attachment 3) keeps its clear value, 0, under the draws of a material variant
  // without emissive (HV_MAT_EMISSIVE 0: its shader writes 0 there) and in the per-term debug
  // views: the write is masked off (after the clear: the color mask also masks clears), which
  // saves its 8 B/px store where the scene has no emissive surface (docs/performance.md, "The
  // emissive write").
  const std::function<void(int)> hdr_write = [&](int variant) {
    const GLboolean w =
        in.emissive && in.key.material_variants.at(size_t(variant)).emissive ? GL_TRUE : GL_FALSE;
    glColorMaski(3, w, w, w, w);
  };

  gl::PassBindings b(kPassSlots, "gbuffer");
  // draw_order groups the draws by material variant: one program switch per variant.
  SceneDraws draws{in.scene, in.gpu, in.key, in.programs, in.draw_order};
  draws.before_variant = &hdr_write;
  drawScene(ctx, b, draws);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glColorMaski(3, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
}

}  // namespace hv::render
