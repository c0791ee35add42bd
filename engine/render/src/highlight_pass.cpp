// Highlight of the picked object (post_stages.hpp, HighlightPass).
#include <algorithm>

#include <glm/gtc/type_ptr.hpp>

#include "halfvec/render/frame_data.hpp"
#include "pass_slots.hpp"
#include "pipeline_state.hpp"
#include "post_stages.hpp"

namespace hv::render {

namespace {
// The pixels (x0, y0, x1, y1; GL window coordinates) the object can cover, plus the outline's
// 2 pixels and a margin: the composite is scissored to them (a fullscreen composite costs as much
// as the tone map). The whole frame when a corner of the bounds is behind the camera.
glm::ivec4 screenRect(const Scene& scene, int object, int width, int height) {
  const Object& o = scene.objects[size_t(object)];
  glm::vec3 lo(1e30f), hi(-1e30f);
  for (int m : o.meshes) {
    for (const Vertex& v : scene.meshes[size_t(m)].vertices) {
      lo = glm::min(lo, v.position);
      hi = glm::max(hi, v.position);
    }
  }
  const glm::ivec4 all(0, 0, width, height);
  if (lo.x > hi.x) return all;
  const glm::mat4 vp = makeFrameBlock(scene, width, height).view_proj * o.transform;
  glm::vec2 a(1e30f), b(-1e30f);
  for (int c = 0; c < 8; ++c) {
    const glm::vec4 p =
        vp * glm::vec4(c & 1 ? hi.x : lo.x, c & 2 ? hi.y : lo.y, c & 4 ? hi.z : lo.z, 1.0f);
    if (p.w <= 1e-6f) return all;
    const glm::vec2 ndc = glm::vec2(p) / p.w;
    a = glm::min(a, ndc);
    b = glm::max(b, ndc);
  }
  const glm::vec2 size(width, height);
  const glm::ivec2 p0 = glm::ivec2(glm::floor((a * 0.5f + 0.5f) * size)) - 4;
  const glm::ivec2 p1 = glm::ivec2(glm::ceil((b * 0.5f + 0.5f) * size)) + 4;
  return {std::clamp(p0.x, 0, width), std::clamp(p0.y, 0, height), std::clamp(p1.x, 0, width),
          std::clamp(p1.y, 0, height)};
}
}  // namespace

HighlightPass::HighlightPass() {
  empty_vao_ = gl::createVertexArray("highlight fullscreen triangle");
}

void HighlightPass::run(gl::ProgramCache& programs, const GpuScene& gpu, const Scene& scene,
                        int object, GLuint depth, GLuint output_fbo, int width, int height) {
  if (object < 0 || size_t(object) >= scene.objects.size()) return;
  if (width != width_ || height != height_ || !mask_) {
    mask_ = gl::createTexture2D("highlight mask", GL_R8, width, height);
    mask_fbo_ = gl::createFramebuffer("highlight mask", {{&mask_}});
    width_ = width;
    height_ = height;
  }
  // 1. Mask: the object's triangles where they are what the G-buffer holds (highlight_mask.frag
  // compares depths), so the hidden parts stay out.
  PipelineState st;
  st.reversed_z_clip = true;  // the G-buffer pass's depth mapping
  applyState(st);
  glBindFramebuffer(GL_FRAMEBUFFER, mask_fbo_.id());
  glViewport(0, 0, width, height);
  const float zero[4] = {0, 0, 0, 0};
  glClearNamedFramebufferfv(mask_fbo_.id(), GL_COLOR, 0, zero);
  gl::PassBindings b(kPassSlots, "highlight");
  b.use(programs.get({"highlight mask",
                      {{GL_VERTEX_SHADER, "passes/highlight_mask.vert"},
                       {GL_FRAGMENT_SHADER, "passes/highlight_mask.frag"}},
                      {}}));
  glUniformMatrix4fv(0, 1, GL_FALSE, glm::value_ptr(scene.objects[size_t(object)].transform));
  b.texture(0, depth);  // t_depth (highlight_mask.frag)
  glBindVertexArray(gpu.vertexArray());
  for (const DrawItem& d : gpu.draws()) {
    if (d.object != object) continue;
    glDrawElementsBaseVertex(
        GL_TRIANGLES, GLsizei(d.index_count), GL_UNSIGNED_INT,
        reinterpret_cast<const void*>(size_t(d.first_index) * sizeof(uint32_t)), d.base_vertex);
  }
  // 2. Composite over the output: tint inside, outline around (alpha blended).
  applyState(PipelineState{});
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glBindFramebuffer(GL_FRAMEBUFFER, output_fbo);
  glViewport(0, 0, width, height);
  b.use(programs.get({"highlight composite",
                      {{GL_VERTEX_SHADER, "passes/fullscreen.vert"},
                       {GL_FRAGMENT_SHADER, "passes/highlight_composite.frag"}},
                      {}}));
  b.texture(0, mask_.id());  // t_mask (highlight_composite.frag)
  const glm::ivec4 r = screenRect(scene, object, width, height);
  glEnable(GL_SCISSOR_TEST);
  glScissor(r.x, r.y, std::max(r.z - r.x, 0), std::max(r.w - r.y, 0));
  glBindVertexArray(empty_vao_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
  glDisable(GL_SCISSOR_TEST);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  applyState(PipelineState{});  // blending off, blend function back to the default state's
}

}  // namespace hv::render
