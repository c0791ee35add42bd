#include "halfvec/render/shadows.hpp"

#include <algorithm>
#include <cstdio>

#include "halfvec/gl/log.hpp"
#include "halfvec/shaders/common/bindings.glsl"
#include "halfvec/scene/enums.hpp"
#include "shadow_pass.hpp"

namespace hv::render {

size_t shadowAtlasCapacity(int map_size) {
  const size_t s = size_t(std::max(map_size, 1));
  return std::max<size_t>(1, kShadowAtlasTexels / (6 * s * s));
}

size_t shadowLightCapacity(int map_size, bool mask) {
  const size_t atlas = shadowAtlasCapacity(map_size);
  return mask ? std::min<size_t>(atlas, HV_SHADOW_MASK_MAX_CUBES) : atlas;
}

ShadowAssignment assignShadowMaps(const std::vector<Light>& lights, size_t capacity) {
  ShadowAssignment a;
  a.layer.assign(lights.size(), -1);
  a.sun_layer.assign(lights.size(), -1);
  for (size_t i = 0; i < lights.size(); ++i) {
    if (!lights[i].shadows) continue;
    if (lights[i].type == LightType::Directional) {
      if (a.suns.size() < kMaxDirectionalLights) {
        a.sun_layer[i] = int(a.suns.size());
        a.suns.push_back(i);
      }
      continue;
    }
    if (a.maps.size() < capacity) {
      a.layer[i] = int(a.maps.size());
      a.maps.push_back(i);
    } else {
      a.over_budget.push_back(i);
    }
  }
  return a;
}

std::string overBudgetWarning(const std::vector<Light>& lights, const ShadowAssignment& a,
                              int map_size, bool mask_full) {
  if (a.over_budget.empty()) return "";
  const std::string full =
      mask_full ? "shadow mask full (" + std::to_string(a.maps.size()) +
                      " lights with a cube map, settings.shadow_resolution half)"
                : "shadow atlas full (" + std::to_string(a.maps.size()) + " cube maps of " +
                      std::to_string(map_size) + "^2 texels, settings.shadow_map_size)";
  std::string msg = full + ": " + std::to_string(a.over_budget.size()) + " shadowed light" +
                    (a.over_budget.size() == 1 ? "" : "s") + " rendered unshadowed: ";
  for (size_t k = 0; k < a.over_budget.size(); ++k) {
    msg += (k ? ", " : "") + describeLight(lights, a.over_budget[k]);
  }
  return msg;
}

void logShadowWarning(const std::string& message) {
  log::warn(message);
}

std::string describeLight(const std::vector<Light>& lights, size_t index) {
  const Light& l = lights.at(index);
  char pos[96];
  if (l.type == LightType::Directional) {
    std::snprintf(pos, sizeof pos, "[%g, %g, %g]", double(l.direction.x), double(l.direction.y),
                  double(l.direction.z));
    return "light " + std::to_string(index) + " (directional along " + pos + ")";
  }
  std::snprintf(pos, sizeof pos, "[%g, %g, %g]", double(l.position.x), double(l.position.y),
                double(l.position.z));
  return "light " + std::to_string(index) + " (" + std::string(toString(l.type)) + " at " + pos +
         ")";
}

}  // namespace hv::render
