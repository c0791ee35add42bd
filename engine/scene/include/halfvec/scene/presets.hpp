// Render-settings presets `fast`, `balanced`, `accurate`: named bundles of the accuracy/speed
// options of RenderSettings, chosen from what `halfvec trade` measures on the sample scenes
// (docs/trade.md, README "Presets"). A scene file selects one with "settings": {"preset": ...};
// the preset is applied first and the file's explicit settings override it.
#pragma once

#include <span>
#include <string_view>

#include "halfvec/scene/scene.hpp"

namespace hv {

// "fast", "balanced", "accurate", in that order.
std::span<const std::string_view> settingsPresetNames();

// Sets the fields the preset `name` defines (the BRDF V term and roughness remap, the falloff,
// the sphere and tube light methods, the environment BRDF and the irradiance representation) and
// leaves every other field (size, tone mapping, D/F/diffuse terms, culling, energy compensation,
// specular occlusion) as it is. Returns false, changing nothing, for an unknown name.
bool applySettingsPreset(std::string_view name, RenderSettings& settings);

}  // namespace hv
