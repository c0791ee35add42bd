// The Renderer's optional stages beyond the deferred frame (ViewOptions): emitter geometry into
// the HDR target, the picked object's highlight and post-AA on the 8-bit output. Each pass is its
// own class with explicit inputs and outputs; Renderer::emitterPass / postPasses
// (post_passes.cpp) wire them to the frame's targets and time them.
#pragma once

#include <vector>

#include "halfvec/gl/objects.hpp"
#include "halfvec/gl/program.hpp"
#include "halfvec/render/gpu_scene.hpp"
#include "halfvec/render/post_aa.hpp"
#include "halfvec/render/renderer.hpp"
#include "halfvec/scene/scene.hpp"

namespace hv::render {

// Sphere and tube lights as capsules of their emitting radiance (shaders/passes/emitter.vert):
// one instanced draw of a capsule template (a unit sphere split at its equator, the halves moved
// apart along the axis by the tube's half length), of the emitters that can cover a pixel
// center (shaders/passes/emitter_cull.comp: an indirect draw whose instance count the GPU counts).
constexpr size_t kEmitterLods = 4;  // EmitterPass's capsule templates, finest first

class EmitterPass {
 public:
  EmitterPass();
  // Rebuilds the instances from the lights (point lights and zero radii have nothing to draw).
  void setLights(const std::vector<Light>& lights);
  size_t count() const { return count_; }
  // In: the instances, the frame block (binding 0), `depth` (the G-buffer's reversed-Z depth,
  // tested, not written). Out: `hdr` (RGBA16F), overwritten where an emitter is in front.
  void run(gl::ProgramCache& programs, GLuint hdr, GLuint depth, int width, int height);

 private:
  gl::Buffer template_vertices_, template_indices_, instances_;
  gl::Buffer visible_;  // the instances emitter_cull.comp keeps, grouped by template
  gl::Buffer groups_;   // emitter_cull.comp's per-workgroup counts and offsets
  gl::Buffer draw_;     // a DrawElementsIndirectCommand per template, counted by the culling
  gl::VertexArray vao_;
  gl::Framebuffer fbo_;
  GLuint fbo_hdr_ = 0, fbo_depth_ = 0;  // what fbo_ is built on
  size_t index_count_[kEmitterLods] = {}, first_index_[kEmitterLods] = {};
  size_t count_ = 0, capacity_ = 0;
};

// The picked object: its visible pixels (its triangles drawn again, kept where their depth matches
// the G-buffer's) into a mask, then a tint over them and an outline around them on the output.
class HighlightPass {
 public:
  HighlightPass();
  // In: the object's draws in `gpu`, the frame block (binding 0), the G-buffer `depth`.
  // Out: blended over `output_fbo` (RGBA8, width x height).
  void run(gl::ProgramCache& programs, const GpuScene& gpu, const Scene& scene, int object,
           GLuint depth, GLuint output_fbo, int width, int height);

 private:
  gl::Texture mask_;
  gl::Framebuffer mask_fbo_;
  gl::VertexArray empty_vao_;
  int width_ = 0, height_ = 0;
};

struct Renderer::PostStages {
  EmitterPass emitters;
  size_t emitter_lights_version = size_t(-1);
  HighlightPass highlight;
  FxaaPass fxaa;
  gl::Texture aa_out;  // RGBA8: the anti-aliased output
  gl::Framebuffer aa_fbo;
  int aa_width = 0, aa_height = 0;
};

}  // namespace hv::render
