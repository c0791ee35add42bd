// Shadow maps, the CPU side (docs/lights.md, "Shadows"): the atlas budget and which lights get a
// map. A light with `shadows: true` gets an omnidirectional map (six cube faces of linear
// distance) in one depth cube map array, the atlas, of settings.shadow_map_size texels a side;
// the atlas holds shadowAtlasCapacity(size) lights, the first shadowed lights in scene order, and
// the lights beyond it render unshadowed (the renderer warns, naming them). No GL here.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "halfvec/scene/scene.hpp"

namespace hv::render {

// The atlas budget, texels: six faces of 2048^2, 96 MiB at 32-bit depth (docs/lights.md).
constexpr size_t kShadowAtlasTexels = size_t(6) * 2048 * 2048;
// Lights the atlas holds at this face size (at least 1): 16 at 512, 4 at 1024, 1 at 2048.
size_t shadowAtlasCapacity(int map_size);
// Lights with a cube at this face size: the atlas's capacity, and with the shadow mask
// (settings.shadow_resolution half) at most the mask's HV_SHADOW_MASK_MAX_CUBES.
size_t shadowLightCapacity(int map_size, bool mask);

struct ShadowAssignment {
  std::vector<int> layer;           // per light: its cube in the atlas, -1 for none
  std::vector<size_t> maps;         // the lights with a map, in cube order
  std::vector<size_t> over_budget;  // shadowed lights beyond the atlas, unshadowed
  // Directional lights: an orthographic map each, layers 0, 1, ... of the sun map array (at most
  // kMaxDirectionalLights, which the loader enforces; any beyond are unshadowed).
  std::vector<int> sun_layer;  // per light: its layer, -1 for none
  std::vector<size_t> suns;    // the directional lights with a map, in layer order
  // GpuLight.shadow_cube of light i: its cube or its sun layer, + 1 (0: none).
  uint32_t shadowSlot(size_t i) const { return uint32_t(std::max(layer[i], sun_layer[i]) + 1); }
};
// The first `capacity` point, sphere, tube and spot lights with shadows get cubes 0, 1, ... in
// scene order; the shadowed directional lights get sun layers 0, 1, ...
ShadowAssignment assignShadowMaps(const std::vector<Light>& lights, size_t capacity);

// The warning for the lights beyond the atlas ("" when none), naming them.
// `mask_full`: the shadow mask's layers, not the atlas, set the capacity.
std::string overBudgetWarning(const std::vector<Light>& lights, const ShadowAssignment& a,
                              int map_size, bool mask_full = false);

// "light 3 (sphere at [1, 2.5, 0])": how warnings name a light (lights have no names).
std::string describeLight(const std::vector<Light>& lights, size_t index);

}  // namespace hv::render
