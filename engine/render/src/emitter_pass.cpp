// Emitter geometry pass (post_stages.hpp, EmitterPass).
#include <cmath>

#include "halfvec/shaders/common/bindings.glsl"
#include "pass_slots.hpp"
#include "pipeline_state.hpp"
#include "post_stages.hpp"

namespace hv::render {

namespace {

// The capsule templates, finest first: (segments around the axis, rings per hemisphere from pole
// to equator); 816, 216, 80 and 24 triangles. emitter_cull.comp picks one per emitter from its
// projected radius, so that the outline stays within 0.12 pixel of the finest one's
// (docs/hostile-input.md, "Light budget").
struct Lod {
  int segments, rings;
};
constexpr Lod kLods[kEmitterLods] = {{24, 8}, {12, 4}, {8, 2}, {4, 1}};

constexpr GLuint kCullGroup = 256;  // emitter_cull.comp's GROUP

// glDrawElementsIndirect's command (GL 4.5, 10.4).
struct DrawCommand {
  uint32_t count, instance_count, first_index;
  int32_t base_vertex;
  uint32_t base_instance;
};

struct Instance {
  glm::vec4 center_radius;
  glm::vec4 axis_half_length;
  glm::vec4 color_intensity;  // color * intensity (W/sr)
};
static_assert(sizeof(Instance) == 48);

// The capsule template: per vertex (direction on the unit sphere with the axis along +Y, side: +1
// for the upper hemisphere, -1 for the lower; the equator appears once per side, so the band
// between the two equators becomes the cylinder), triangles wound counterclockwise from outside.
void capsuleTemplate(int segments, int rings, std::vector<glm::vec4>& v,
                     std::vector<uint32_t>& idx) {
  const uint32_t first_vertex = uint32_t(v.size());
  const size_t first_index = idx.size();
  const float pi = 3.14159265358979f;
  for (int side = 0; side < 2; ++side) {
    const float s = side == 0 ? 1.0f : -1.0f;
    for (int r = 0; r <= rings; ++r) {  // r = 0: pole, r = rings: equator
      const float theta = 0.5f * pi * float(r) / float(rings);
      for (int k = 0; k <= segments; ++k) {
        const float phi = 2.0f * pi * float(k) / float(segments);
        v.push_back({std::sin(theta) * std::cos(phi), s * std::cos(theta),
                     std::sin(theta) * std::sin(phi), s});
      }
    }
  }
  const uint32_t row = segments + 1, half = row * (rings + 1);
  auto quad = [&](uint32_t a, uint32_t b, uint32_t c, uint32_t d) {
    idx.insert(idx.end(), {a, b, c, a, c, d});
  };
  for (uint32_t side = 0; side < 2; ++side) {
    for (uint32_t r = 0; r < uint32_t(rings); ++r) {
      for (uint32_t k = 0; k < uint32_t(segments); ++k) {
        const uint32_t a = first_vertex + side * half + r * row + k;
        quad(a, a + 1, a + row + 1, a + row);
      }
    }
  }
  for (uint32_t k = 0; k < uint32_t(segments); ++k) {  // the cylinder: equator to equator
    const uint32_t top = first_vertex + uint32_t(rings) * row + k,
                   bottom = first_vertex + half + uint32_t(rings) * row + k;
    quad(top, top + 1, bottom + 1, bottom);
  }
  // Orient every triangle outward, judged on a capsule of half length 1 (so the cylinder's
  // triangles are judged too).
  auto place = [&](uint32_t i) { return glm::vec3(v[i]) + glm::vec3(0.0f, v[i].w, 0.0f); };
  for (size_t t = first_index; t < idx.size(); t += 3) {
    const glm::vec3 a = place(idx[t]), b = place(idx[t + 1]), c = place(idx[t + 2]);
    const glm::vec3 n = glm::cross(b - a, c - a);
    if (glm::dot(n, a + b + c) < 0.0f) std::swap(idx[t + 1], idx[t + 2]);
  }
}

}  // namespace

EmitterPass::EmitterPass() {
  std::vector<glm::vec4> v;
  std::vector<uint32_t> idx;
  for (size_t k = 0; k < kEmitterLods; ++k) {
    first_index_[k] = idx.size();
    capsuleTemplate(kLods[k].segments, kLods[k].rings, v, idx);
    index_count_[k] = idx.size() - first_index_[k];
  }
  template_vertices_ =
      gl::createBuffer("emitter template vertices", v.size() * sizeof(glm::vec4), v.data(), 0);
  template_indices_ =
      gl::createBuffer("emitter template indices", idx.size() * sizeof(uint32_t), idx.data(), 0);
  vao_ = gl::createVertexArray("emitters");
  const GLuint vao = vao_.id();
  glVertexArrayVertexBuffer(vao, 0, template_vertices_.id(), 0, sizeof(glm::vec4));
  glVertexArrayElementBuffer(vao, template_indices_.id());
  glEnableVertexArrayAttrib(vao, 0);
  glVertexArrayAttribFormat(vao, 0, 4, GL_FLOAT, GL_FALSE, 0);
  glVertexArrayAttribBinding(vao, 0, 0);
  for (GLuint a = 1; a <= 3; ++a) {  // per instance, binding 1 (attached in setLights)
    glEnableVertexArrayAttrib(vao, a);
    glVertexArrayAttribFormat(vao, a, 4, GL_FLOAT, GL_FALSE, (a - 1) * sizeof(glm::vec4));
    glVertexArrayAttribBinding(vao, a, 1);
  }
  glVertexArrayBindingDivisor(vao, 1, 1);
  draw_ = gl::createBuffer("emitter draw commands", kEmitterLods * sizeof(DrawCommand), nullptr,
                           GL_DYNAMIC_STORAGE_BIT);
}

void EmitterPass::setLights(const std::vector<Light>& lights) {
  std::vector<Instance> inst;
  for (const Light& l : lights) {
    // A spot's sphere is not drawn: its surface radiance would depend on the direction it is
    // seen from, which the capsule shader (emitter.glsl) does not model (docs/lights.md).
    if (l.type == LightType::Point || l.type == LightType::Spot || l.radius <= 0.0f) continue;
    const float half = l.type == LightType::Tube ? 0.5f * l.length : 0.0f;
    inst.push_back({glm::vec4(l.position, l.radius), glm::vec4(glm::normalize(l.axis), half),
                    glm::vec4(l.color * l.intensity, 0.0f)});
  }
  count_ = inst.size();
  if (count_ == 0) return;
  if (count_ > capacity_) {
    capacity_ = count_;
    instances_ = gl::createBuffer("emitter instances", capacity_ * sizeof(Instance));
    visible_ = gl::createBuffer("visible emitter instances", capacity_ * sizeof(Instance));
    groups_ =
        gl::createBuffer("emitter culling groups", ((capacity_ + kCullGroup - 1) / kCullGroup) *
                                                       kEmitterLods * sizeof(uint32_t));
    glVertexArrayVertexBuffer(vao_.id(), 1, visible_.id(), 0, sizeof(Instance));
  }
  glNamedBufferSubData(instances_.id(), 0, GLsizeiptr(count_ * sizeof(Instance)), inst.data());
}

void EmitterPass::run(gl::ProgramCache& programs, GLuint hdr, GLuint depth, int width, int height) {
  if (count_ == 0) return;
  if (!fbo_ || fbo_hdr_ != hdr || fbo_depth_ != depth) {
    GLuint id = 0;
    glCreateFramebuffers(1, &id);
    gl::Framebuffer f(id, "emitters (hdr + gbuffer depth)");
    glNamedFramebufferTexture(id, GL_COLOR_ATTACHMENT0, hdr, 0);
    glNamedFramebufferTexture(id, GL_DEPTH_ATTACHMENT, depth, 0);
    if (glCheckNamedFramebufferStatus(id, GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
      throw gl::GlError("emitters framebuffer incomplete");
    }
    fbo_ = std::move(f);
    fbo_hdr_ = hdr;
    fbo_depth_ = depth;
  }
  // Culling: the emitters that can cover a pixel center, counted into the draw's instances.
  DrawCommand reset[kEmitterLods];
  for (size_t k = 0; k < kEmitterLods; ++k) {
    // Coarsest first (emitter_cull.comp): the finer, larger on screen, are drawn over them.
    reset[kEmitterLods - 1 - k] = {uint32_t(index_count_[k]), 0, uint32_t(first_index_[k]), 0, 0};
  }
  glNamedBufferSubData(draw_.id(), 0, sizeof reset, reset);
  const GLuint groups = GLuint((count_ + kCullGroup - 1) / kCullGroup);
  gl::PassBindings b(kPassSlots, "emitters");
  b.storage(HV_BINDING_EMITTERS, instances_.id());
  b.storage(HV_BINDING_VISIBLE_EMITTERS, visible_.id());
  b.storage(HV_BINDING_EMITTER_DRAW, draw_.id());
  b.storage(HV_BINDING_EMITTER_GROUPS, groups_.id());
  for (const char* stage : {"0", "1", "2"}) {  // count, scan, write (emitter_cull.comp)
    const GLuint cull = programs.get({"emitter_cull",
                                      {{GL_COMPUTE_SHADER, "passes/emitter_cull.comp"}},
                                      {{"HV_EMITTER_CULL_STAGE", stage}}});
    b.use(cull);
    glProgramUniform1ui(cull, 0, GLuint(count_));
    glDispatchCompute(stage[0] == '1' ? 1 : groups, 1, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  }
  glMemoryBarrier(GL_COMMAND_BARRIER_BIT | GL_VERTEX_ATTRIB_ARRAY_BARRIER_BIT);

  PipelineState st;
  st.depth_test = true;
  st.depth_write = false;      // the G-buffer's depth stays the scene's
  st.depth_func = GL_GREATER;  // reversed Z
  st.cull_back = true;
  st.reversed_z_clip = true;
  applyState(st);
  const GLuint prog = programs.get(
      {"emitters",
       {{GL_VERTEX_SHADER, "passes/emitter.vert"}, {GL_FRAGMENT_SHADER, "passes/emitter.frag"}},
       {}});
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
  glViewport(0, 0, width, height);
  b.use(prog);
  glBindVertexArray(vao_.id());
  glBindBuffer(GL_DRAW_INDIRECT_BUFFER, draw_.id());
  glMultiDrawElementsIndirect(GL_TRIANGLES, GL_UNSIGNED_INT, nullptr, GLsizei(kEmitterLods), 0);
  glBindBuffer(GL_DRAW_INDIRECT_BUFFER, 0);
  glBindVertexArray(0);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  applyState(PipelineState{});
}

}  // namespace hv::render
