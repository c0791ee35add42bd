// The forward pass of blended surfaces (glTF alphaMode BLEND). In: the blended draws, the lights,
// the environment, the shadow atlas, the G-buffer's depth (tested, not written). Out: the blended
// surfaces composited over the HDR target.
#include <algorithm>

#include "passes.hpp"
#include "pipeline_state.hpp"
#include "shadow_pass.hpp"

namespace hv::render {

std::vector<size_t> ForwardPass::backToFront(const Scene& scene, const GpuScene& gpu,
                                             const glm::vec3& camera_pos) {
  const auto& draws = gpu.draws();
  std::vector<std::pair<float, size_t>> keyed;
  for (size_t i = 0; i < draws.size(); ++i) {
    const DrawItem& d = draws[i];
    if (scene.materials[size_t(d.material)].alpha_mode != AlphaMode::Blend) continue;
    const glm::vec3 c =
        glm::vec3(scene.objects[size_t(d.object)].transform * glm::vec4(d.center, 1));
    const glm::vec3 to = c - camera_pos;
    keyed.emplace_back(glm::dot(to, to), i);
  }
  // Farthest first; equal distances keep the scene's order (a stable order frame to frame).
  std::stable_sort(keyed.begin(), keyed.end(),
                   [](const auto& a, const auto& b) { return a.first > b.first; });
  std::vector<size_t> order;
  order.reserve(keyed.size());
  for (const auto& k : keyed) order.push_back(k.second);
  return order;
}

void ForwardPass::run(const PassContext& ctx, const Input& in, const Output& out) {
  gl::ScopedPass pass(ctx.timer, "forward");
  PipelineState st;
  st.depth_test = true;
  st.depth_write = false;      // blended surfaces do not hide one another: all of them composite
  st.depth_func = GL_GREATER;  // reversed Z: nearer than the opaque surface
  st.blend_over = true;
  st.reversed_z_clip = true;
  applyState(st);
  const std::vector<size_t> order = backToFront(in.scene, in.gpu, in.scene.camera.position);
  if (order.empty()) return;

  glBindFramebuffer(GL_FRAMEBUFFER, out.framebuffer);
  glViewport(0, 0, out.width, out.height);
  gl::PassBindings b(kPassSlots, "forward");
  b.storage(HV_BINDING_LIGHTS, in.gpu.lightBuffer());
  const GLuint fallback_2d = in.gpu.materialTextures(in.gpu.draws()[order[0]].material)[0].texture;
  in.environment.bind(
      b, fallback_2d,
      {HV_UNIT_FORWARD_RADIANCE, HV_UNIT_FORWARD_ENV_BRDF, HV_UNIT_FORWARD_IRRADIANCE});
  if (in.ltc) {
    if (!ltc_) ltc_ = std::make_unique<LtcTextures>();
    ltc_->bind(b);
  }
  if (in.shadows) {  // ShadowMaps binds its two units itself (shadow_pass.cpp): declared here
    in.shadows->bind();
    b.declareTexture(HV_UNIT_SHADOW_DEPTH);
    b.declareTexture(HV_UNIT_SHADOW_COMPARE);
  }
  drawScene(ctx, b, {in.scene, in.gpu, in.key, in.programs, order});
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  applyState(PipelineState{});
}

}  // namespace hv::render
