// Click-to-pick (the viewer's material panel): which object and material are visible at a pixel
// of the frame the Renderer draws for a scene, without a GL context.
//
// Why a CPU ray cast and not a GPU pass that renders draw or material IDs: it needs no context,
// target or program (testable headless, and it still works while a shader error stops the
// renderer); the G-buffer has no room for a material index (16 B/px, docs/gbuffer.md) and an extra
// ID target would cost every frame to serve an occasional click. A click costs one pass over the
// triangles of the meshes whose bounding box the ray meets (all 1.04M triangles of the
// dense_geometry sample in the worst case: tens of ms, once per click).
// It follows the G-buffer pass's rules so it picks what the frame shows: the camera is
// makeFrameBlock's (same projection, same aspect), back faces of single-sided materials are not
// hit (a mirroring transform flips the winding there and here alike), nothing nearer than the
// near plane is hit, the nearest hit wins. Not followed: alpha-mask cut-outs (no texture is
// sampled here), so a click through a hole in a masked material picks that material.
#pragma once

#include <optional>

#include <glm/glm.hpp>

#include "halfvec/scene/scene.hpp"

namespace hv::render {

struct PickHit {
  int object = -1;           // index into Scene::objects
  int mesh = -1;             // index into Scene::meshes
  int material = -1;         // Scene::meshes[mesh].material
  float distance = 0.0f;     // from the camera, world units
  glm::vec3 position{0.0f};  // world
};

// The surface seen through pixel (x, y) of a width x height frame (pixels from the top-left
// corner, as window cursor coordinates; the pixel's center is at +0.5); nullopt on background.
std::optional<PickHit> pick(const Scene& scene, int width, int height, glm::vec2 pixel);

// Lights whose bound (the range sphere, around the whole segment for a tube) meets the view
// frustum of a width x height frame: the lights that can light something on screen (the viewer's
// stats "lights in view"). On the CPU from the scene, so it does not depend on the culling
// pass's buffers; the tiled culling then keeps, per tile, the subset that reaches the tile's
// surfaces (FrameStats::tile_light_entries).
size_t countLightsInView(const Scene& scene, int width, int height);

}  // namespace hv::render
