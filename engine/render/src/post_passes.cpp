// The Renderer's optional stages (ViewOptions): emitter geometry after the ambient pass; after
// the tone map, the picked object's highlight and post-AA, then the copy to the caller's
// framebuffer. Each is timed as its own pass ("emitters", "highlight", "aa").
#include "halfvec/render/renderer.hpp"
#include "post_stages.hpp"
#include "targets.hpp"

namespace hv::render {

namespace {
// The views whose image is the shaded frame (the normal one and the per-term ones); G-buffer and
// culling views show data as stored and get no emitters and no AA.
bool shadedView(DebugView v) {
  return v == DebugView::None || termView(v).has_value();
}
}  // namespace

Renderer::PostStages& Renderer::postStages() {
  if (!post_) post_ = std::make_unique<PostStages>();
  return *post_;
}

void Renderer::emitterPass(DebugView view) {
  if (!view_options_.emitters || view != DebugView::None) return;
  PostStages& p = postStages();
  if (p.emitter_lights_version != lights_version_) {
    p.emitters.setLights(scene_->lights);
    p.emitter_lights_version = lights_version_;
  }
  if (p.emitters.count() == 0) return;
  gl::ScopedPass pass(timer_, "emitters");
  const Targets& t = *targets_;
  p.emitters.run(programs_, t.hdr.id(), t.depth.id(), t.width, t.height);
}

bool Renderer::postPassesActive(DebugView view) const {
  return view_options_.highlight_object >= 0 ||
         (view_options_.aa != PostAA::None && shadedView(view));
}

void Renderer::postPasses(DebugView view, std::optional<GLuint> present_fbo, int width,
                          int height) {
  PostStages& p = postStages();
  Targets& t = *targets_;
  GLuint final_fbo = t.output.id();
  final_ldr_ = t.ldr.id();
  if (view_options_.highlight_object >= 0) {
    gl::ScopedPass pass(timer_, "highlight");
    p.highlight.run(programs_, *gpu_, *scene_, view_options_.highlight_object, t.depth.id(),
                    t.output.id(), width, height);
  }
  if (view_options_.aa == PostAA::Fxaa && shadedView(view)) {
    if (p.aa_width != width || p.aa_height != height || !p.aa_out) {
      p.aa_out = gl::createTexture2D("anti-aliased output", GL_RGBA8, width, height);
      p.aa_fbo = gl::createFramebuffer("anti-aliased output", {{&p.aa_out}});
      p.aa_width = width;
      p.aa_height = height;
    }
    gl::ScopedPass pass(timer_, "aa");
    p.fxaa.run(programs_, t.ldr.id(), p.aa_fbo.id(), width, height);
    final_fbo = p.aa_fbo.id();
    final_ldr_ = p.aa_out.id();
  }
  if (present_fbo) {
    glBlitNamedFramebuffer(final_fbo, *present_fbo, 0, 0, width, height, 0, 0, width, height,
                           GL_COLOR_BUFFER_BIT, GL_NEAREST);
  }
}

}  // namespace hv::render
