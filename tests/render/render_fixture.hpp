#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include "halfvec/platform/context.hpp"
#include "halfvec/render/renderer.hpp"
#include "halfvec/scene/primitives.hpp"
#include "halfvec/scene/scene.hpp"

// One headless context per test binary.
inline hv::Context& testContext() {
  static std::unique_ptr<hv::Context> ctx = hv::createHeadlessContext();
  return *ctx;
}

// One frame of scene `s` at w x h in a renderer of its own (in the binary's context): its HDR
// image, its G-buffer read back and the variant key it was drawn with.
struct RenderedFrame {
  hv::ImageRGBf hdr;
  hv::GBufferReadback g;
  hv::render::VariantKey key;
};
inline RenderedFrame renderFrame(const hv::Scene& s, int w, int h) {
  testContext();
  hv::render::Renderer r;
  r.setScene(s);
  r.render(w, h);
  return {r.readHdr(), r.readGBuffer(), r.variantKey()};
}

// How far two G-buffers' base colors are apart at pixel i, channel k, as a relative difference
// (0 where they are equal). Two programs that compute the same base color may round it to
// adjacent codes of the 8-bit sRGB target where it falls on a rounding boundary (linear 0.5 is
// code 187.52): the GL allows each its own arithmetic, and the NVIDIA driver's uber and
// specialized G-buffer programs do differ there while llvmpipe's do not. The lit radiance is at
// most linear in the base color (diffuse color and F0 scale with it), so an image computed from
// either is within |out| times this of the other.
inline double baseColorStep(const hv::GBufferReadback& a, const hv::GBufferReadback& b, size_t i,
                            int k) {
  const double x = a.base_color[i][k], y = b.base_color[i][k];
  return x == y ? 0.0 : std::abs(x - y) / std::max(std::min(x, y), 1e-6);
}

// A plane at y = 0 seen straight from above (camera at height 2 looking down -y), one material.
inline hv::Scene planeScene(const hv::Material& m, float size = 10.0f) {
  hv::Scene s;
  s.camera.position = {0.0f, 2.0f, 0.0f};
  s.camera.target = {0.0f, 0.0f, 0.0f};
  s.camera.up = {0.0f, 0.0f, -1.0f};
  s.camera.fov_y_deg = 60.0f;
  s.materials.push_back(m);
  s.meshes.push_back(hv::makePlane(size, size));
  s.meshes.back().material = 0;
  hv::Object o;
  o.meshes = {0};
  s.objects.push_back(o);
  s.environment.kind = hv::EnvironmentKind::Uniform;
  s.environment.color = glm::vec3(0.0f);
  return s;
}

// planeScene of a rough grey metal (roughness 0.35) seen low over the plane (grazing views), and
// a light centred 0.05 m over it with radius 0.3 (a capsule of length 0.6 along the plane): it
// straddles the horizon of every floor pixel outside it (the horizon-cut tests).
inline hv::Scene straddlingLightScene(hv::LightType type) {
  hv::Material m;
  m.base_color = {0.9f, 0.9f, 0.9f};
  m.metallic = 1.0f;
  m.roughness = 0.35f;
  hv::Scene s = planeScene(m);
  s.camera.position = {0.0f, 0.5f, 1.6f};
  s.camera.target = {0.0f, 0.0f, -1.0f};
  s.camera.up = {0.0f, 1.0f, 0.0f};
  hv::Light l;
  l.type = type;
  l.position = {0.1f, 0.05f, -0.6f};
  l.intensity = 3.0f;
  l.radius = 0.3f;
  l.length = type == hv::LightType::Tube ? 0.6f : 0.0f;
  l.axis = glm::normalize(glm::vec3(1, 0, 0.5f));  // parallel to the plane
  l.range = 8.0f;
  s.lights = {l};
  return s;
}
