// The numerical-stability sweep behind `halfvec stability`: renders extreme cases for every light
// type and every BRDF/light option (one option changed at a time from the defaults) and counts
// NaN, Inf and negative HDR pixels read back from the GPU.
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace hv::eval {

struct StabilityRow {
  std::string light;     // point / sphere / tube
  std::string geometry;  // the light configuration
  std::string option;    // the setting changed from the defaults ("default" = none)
  int nan = 0, inf = 0, negative = 0;
  float max_value = 0.0f;
  bool ok() const { return nan == 0 && inf == 0 && negative == 0; }
};

struct StabilityOptions {
  bool small = false;  // CI size: fewer options, all geometries
  int size = 48;       // image edge in pixels
};

// Needs a current GL context. `progress` gets one call per row (may be empty).
std::vector<StabilityRow> runStabilitySweep(
    const StabilityOptions& options, const std::function<void(const StabilityRow&)>& progress = {});

}  // namespace hv::eval
