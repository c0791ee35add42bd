// What the Renderer draws beyond the scene's shading: options of the output, not of the scene
// file, set by the application (Renderer::setViewOptions). None of them touches the HDR radiance
// of lit surfaces or the G-buffer, so accuracy comparisons are unaffected by them, and all are off
// in a Renderer until set: `halfvec render` and the viewer turn post-AA and emitters on.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace hv::render {

// Post-process anti-aliasing of the tone-mapped 8-bit image (post_aa.hpp).
enum class PostAA : uint8_t { None = 0, Fxaa = 1 };
std::optional<PostAA> postAAFromString(const std::string& s);  // "none", "fxaa"
const char* toString(PostAA aa);

struct ViewOptions {
  PostAA aa = PostAA::None;
  // Sphere and tube lights drawn as their emitting surfaces (emissive geometry of radiance
  // emitterRadiance, shaders/common/emitter.glsl) into the HDR target after the ambient pass,
  // depth-tested against the G-buffer: visible, never lit, not in the G-buffer. The HDR image then
  // differs from the CPU reference's (which does not draw lights) on those pixels.
  bool emitters = false;
  // Scene::objects index drawn with an outline and a tint in the output (the viewer's pick), or -1.
  int highlight_object = -1;
  bool operator==(const ViewOptions&) const = default;
};

}  // namespace hv::render
