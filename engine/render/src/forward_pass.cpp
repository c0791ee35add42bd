// The forward pass of blended surfaces (glTF alphaMode BLEND). In: the blended draws, the lights,
// the environment, the shadow atlas, the G-buffer's depth (tested, not written). Out: the blended
// surfaces composited over the HDR target.
#include <algorithm>
#include <functional>

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

std::vector<uint32_t> ForwardPass::lightsReaching(const Scene& scene, const GpuScene& gpu,
                                                  size_t draw) {
  const DrawItem& d = gpu.draws().at(draw);
  const glm::mat4& m = scene.objects[size_t(d.object)].transform;
  // The world box around the transformed object box: centre and half extents (|M| h).
  const glm::vec3 c = glm::vec3(m * glm::vec4(d.center, 1.0f));
  const glm::mat3 a = glm::mat3(m);
  glm::vec3 h(0.0f);
  for (int i = 0; i < 3; ++i) h += glm::abs(a[i]) * d.half_extent[i];
  std::vector<uint32_t> out;
  const auto& spheres = gpu.lightCullSpheres();
  for (size_t i = 0; i < spheres.size(); ++i) {
    // A directional light reaches every surface (it has no culling sphere); past the scene's
    // lights is the sky's sun (renderedLights), a directional light.
    if (i >= scene.lights.size() || scene.lights[i].type == LightType::Directional) {
      out.push_back(uint32_t(i));
      continue;
    }
    const glm::vec3 q = glm::clamp(glm::vec3(spheres[i]), c - h, c + h);  // nearest box point
    const glm::vec3 to = q - glm::vec3(spheres[i]);
    if (glm::dot(to, to) <= spheres[i].w * spheres[i].w) out.push_back(uint32_t(i));
  }
  return out;
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
  // Per draw, the lights that reach its bounds (the tile lists are built from the opaque depth,
  // which a blended surface in front of it is not part of).
  std::vector<uint32_t> lists;
  std::vector<glm::uvec2> ranges(in.gpu.draws().size());
  for (size_t di : order) {
    const std::vector<uint32_t> l = lightsReaching(in.scene, in.gpu, di);
    ranges[di] = glm::uvec2(uint32_t(lists.size()), uint32_t(l.size()));
    lists.insert(lists.end(), l.begin(), l.end());
  }
  if (lists.empty()) lists.push_back(0u);  // a bound buffer is never empty
  if (lists.size() > draw_lights_capacity_) {
    draw_lights_capacity_ = std::max(lists.size(), 2 * draw_lights_capacity_);
    draw_lights_ =
        gl::createBuffer("forward pass: lights per blended draw", draw_lights_capacity_ * 4);
  }
  glNamedBufferSubData(draw_lights_.id(), 0, GLsizeiptr(lists.size() * 4), lists.data());

  gl::PassBindings b(kPassSlots, "forward");
  b.storage(HV_BINDING_LIGHTS, in.gpu.lightBuffer());
  b.storage(HV_BINDING_FORWARD_LIGHTS, draw_lights_.id());
  const GLuint fallback_2d = in.gpu.materialTextures(in.gpu.draws()[order[0]].material)[0].texture;
  in.environment.bind(
      b, fallback_2d,
      {HV_UNIT_FORWARD_RADIANCE, HV_UNIT_FORWARD_ENV_BRDF, HV_UNIT_FORWARD_IRRADIANCE});
  bindLightTables(b, in.ltc ? &ltc_ : nullptr, in.error_table ? HV_UNIT_FORWARD_ERROR_TABLE : 0,
                  in.shadows);
  const std::function<void(size_t)> set_lights = [&](size_t di) {
    glUniform2ui(HV_LOC_FORWARD_LIGHTS, ranges[di].x, ranges[di].y);
  };
  drawScene(
      ctx, b,
      {in.scene, in.gpu, in.key, in.programs, order, &set_lights, HV_FORWARD_MATERIAL_TEXTURES});
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  applyState(PipelineState{});
}

}  // namespace hv::render
