#include "halfvec/eval/engine_aov.hpp"

namespace hv::eval {

std::array<ImageRGBf, kReferenceAovCount> renderEngineAovs(render::Renderer& renderer, Scene& scene,
                                                           int width, int height) {
  RenderSettings& s = scene.settings;
  const uint8_t keep_direct = s.direct_terms, keep_ambient = s.ambient_terms;
  // {direct mask, ambient mask} per ReferenceAov (bit 1 diffuse, bit 2 specular).
  constexpr uint8_t kMasks[kReferenceAovCount][2] = {{1, 0}, {2, 0}, {0, 1}, {0, 2}};
  std::array<ImageRGBf, kReferenceAovCount> aov;
  try {
    for (int k = 0; k < kReferenceAovCount; ++k) {
      s.direct_terms = kMasks[k][0];
      s.ambient_terms = kMasks[k][1];
      renderer.render(width, height);
      aov[size_t(k)] = renderer.readHdr();
    }
    s.direct_terms = 0;
    s.ambient_terms = 0;
    renderer.render(width, height);
  } catch (...) {
    s.direct_terms = keep_direct;
    s.ambient_terms = keep_ambient;
    throw;
  }
  s.direct_terms = keep_direct;
  s.ambient_terms = keep_ambient;
  const ImageRGBf base = renderer.readHdr();  // emissive (+ background): in every render
  const GBufferReadback g = renderer.readGBuffer();
  for (auto& img : aov) {
    for (size_t i = 0; i < img.px.size(); ++i) {
      const bool lit = g.model[i] == static_cast<uint32_t>(ShadingModel::DefaultLit);
      img.px[i] = lit ? img.px[i] - base.px[i] : glm::vec3(0.0f);
    }
  }
  return aov;
}

}  // namespace hv::eval
