// Highlight of the picked object (post_stages.hpp, HighlightPass).
#include <glm/gtc/type_ptr.hpp>

#include "pipeline_state.hpp"
#include "post_stages.hpp"

namespace hv::render {

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
  glUseProgram(programs.get({"highlight mask",
                             {{GL_VERTEX_SHADER, "passes/highlight_mask.vert"},
                              {GL_FRAGMENT_SHADER, "passes/highlight_mask.frag"}},
                             {}}));
  glUniformMatrix4fv(0, 1, GL_FALSE, glm::value_ptr(scene.objects[size_t(object)].transform));
  glBindTextureUnit(0, depth);
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
  glUseProgram(programs.get({"highlight composite",
                             {{GL_VERTEX_SHADER, "passes/fullscreen.vert"},
                              {GL_FRAGMENT_SHADER, "passes/highlight_composite.frag"}},
                             {}}));
  glBindTextureUnit(0, mask_.id());
  glBindVertexArray(empty_vao_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
  glBindTextureUnit(0, 0);
  glUseProgram(0);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  applyState(PipelineState{});  // blending off, blend function back to the default state's
}

}  // namespace hv::render
