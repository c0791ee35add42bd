// The engine's per-term images (`halfvec render --aov`, `halfvec accuracy`): direct diffuse,
// direct specular, ambient diffuse and ambient specular, named and ordered as the reference's
// AOVs (hv::ReferenceAov) so `halfvec compare` pairs them.
#pragma once

#include <array>

#include "halfvec/image/image.hpp"
#include "halfvec/reference/reference.hpp"
#include "halfvec/render/renderer.hpp"

namespace hv::eval {

// Renders the renderer's scene once per term through the Renderer's per-term debug views
// (render::DebugView::DirectDiffuse ... AmbientSpecular, render::termView: that one term, no
// emissive, black background; no emitter geometry whatever the renderer's ViewOptions) and
// reads back each HDR image; pixels that are not
// a lit model (isLit) are set to 0, as in the reference's AOVs. The next plain render()
// renders the normal image again.
std::array<ImageRGBf, kReferenceAovCount> renderEngineAovs(render::Renderer& renderer, int width,
                                                           int height);

}  // namespace hv::eval
