// The engine's per-term images (`halfvec render --aov`, `halfvec accuracy`): direct diffuse,
// direct specular, ambient diffuse and ambient specular, named and ordered as the reference's
// AOVs (hv::ReferenceAov) so `halfvec compare` pairs them.
#pragma once

#include <array>

#include "halfvec/image/image.hpp"
#include "halfvec/reference/reference.hpp"
#include "halfvec/render/renderer.hpp"
#include "halfvec/scene/scene.hpp"

namespace hv::eval {

// Renders `scene` (already set on `renderer`) once per term with the term masks of
// RenderSettings (HV_DIRECT_TERMS / HV_AMBIENT_TERMS: that one term, the others 0) and once with
// every term masked; each AOV is its render minus the all-masked one, which removes the emissive
// the G-buffer pass writes. Pixels that are not ShadingModel::DefaultLit are 0, as in the
// reference's AOVs. The scene's masks are restored afterwards; the renderer's HDR target holds
// the last (all-masked) frame.
std::array<ImageRGBf, kReferenceAovCount> renderEngineAovs(render::Renderer& renderer, Scene& scene,
                                                           int width, int height);

}  // namespace hv::eval
