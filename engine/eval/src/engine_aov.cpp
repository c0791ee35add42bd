#include "halfvec/eval/engine_aov.hpp"

namespace hv::eval {

std::array<ImageRGBf, kReferenceAovCount> renderEngineAovs(render::Renderer& renderer, int width,
                                                           int height) {
  using render::DebugView;
  // Indexed by ReferenceAov.
  constexpr DebugView kViews[kReferenceAovCount] = {
      DebugView::DirectDiffuse, DebugView::DirectSpecular, DebugView::AmbientDiffuse,
      DebugView::AmbientSpecular};
  // The shading's terms only: no emitter geometry (view options are restored afterwards).
  const render::ViewOptions keep = renderer.viewOptions();
  renderer.setViewOptions({});
  std::array<ImageRGBf, kReferenceAovCount> aov;
  try {
    for (int k = 0; k < kReferenceAovCount; ++k) {
      renderer.render(width, height, kViews[k]);
      aov[size_t(k)] = renderer.readHdr();
    }
  } catch (...) {
    renderer.setViewOptions(keep);
    throw;
  }
  renderer.setViewOptions(keep);
  const GBufferReadback g = renderer.readGBuffer();
  for (auto& img : aov) {
    for (size_t i = 0; i < img.px.size(); ++i) {
      if (!isLit(ShadingModel(g.model[i]))) img.px[i] = glm::vec3(0.0f);
    }
  }
  return aov;
}

}  // namespace hv::eval
