// `halfvec bench --methods` (table (e)): the light-pass cost of each sphere and tube method.
#include <algorithm>
#include <cstdio>

#include "app/commands.hpp"
#include "halfvec/eval/light_methods.hpp"
#include "halfvec/scene/enums.hpp"

namespace hv::app {

// Table (e): the light methods of each area-light type (eval/light_methods.hpp), frames
// interleaved; shading = the method's light ms minus the FetchOnly probe's.
void methodsTable(const std::function<Scene(LightType)>& scene, int n, int w, int h, int frames) {
  std::printf(
      "\n(e) light methods, %d lights of one type, constant density (median light ms of %d "
      "interleaved frames; shading = light - lists+fetch; ratio: to representative_point)\n",
      n, frames);
  std::printf("%8s %-32s %9s %9s %11s %12s %14s\n", "type", "method", "light ms", "Mevals/s",
              "shading ms", "light ratio", "shading ratio");
  for (LightType t : {LightType::Sphere, LightType::Tube}) {
    const Scene s = scene(t);
    const auto rows = eval::timeLightMethods(s, eval::lightMethodsFor(t, s.settings), w, h, frames);
    const double fetch = rows[0].light_ms, rp = rows[1].light_ms;
    for (size_t i = 1; i < rows.size(); ++i) {
      std::printf("%8s %-32s %9.2f %9.1f %11.2f %12.2f %14.2f\n", i == 1 ? toString(t).data() : "",
                  rows[i].name.c_str(), rows[i].light_ms, rows[i].mevals_per_s,
                  rows[i].light_ms - fetch, rows[i].light_ms / rp,
                  (rows[i].light_ms - fetch) / std::max(rp - fetch, 1e-9));
    }
    std::fflush(stdout);
  }
}

}  // namespace hv::app
