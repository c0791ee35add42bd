// `halfvec stability`: the numerical-stability sweep (see stability.hpp).
#include <cstdio>

#include "app/commands.hpp"
#include "halfvec/eval/stability.hpp"
#include "halfvec/platform/context.hpp"

namespace hv::app {

namespace {
constexpr const char* kHelp = R"(Usage: halfvec stability [--small] [--size N]

Renders every light type in extreme configurations (shading point at or inside the light,
radius/length 0, distance 1e-6 and 1e6, intensity 1e6, grazing N.L and N.V) on spheres of
roughness 0 and 1, metallic 0 and 1, base color black and white, for the default settings and
each BRDF/light option changed one at a time, and prints per case the NaN, Inf and negative HDR
pixel counts and the largest value. Exit code 1 if any case has a bad pixel.

Options:
  --small     the CI subset of options (all light types and configurations)
  --size N    image edge in pixels (default 48)
)";
}  // namespace

int cmdStability(const Args& args) {
  eval::StabilityOptions o;
  for (size_t i = 0; i < args.size(); ++i) {
    if (args[i] == "--help" || args[i] == "-h") {
      std::fputs(kHelp, stdout);
      return 0;
    } else if (args[i] == "--small") {
      o.small = true;
    } else if (args[i] == "--size") {
      const std::string option = args[i];
      o.size = intInRange(option, optionValue(args, i), 8, 1024);
    } else {
      throw UsageError{"unknown option '" + args[i] + "'"};
    }
  }
  auto ctx = createHeadlessContext();
  std::printf("%-7s %-28s %-36s %6s %6s %6s %12s\n", "light", "geometry", "option", "NaN", "Inf",
              "neg", "max");
  int bad = 0, total = 0;
  eval::runStabilitySweep(o, [&](const eval::StabilityRow& r) {
    ++total;
    bad += !r.ok();
    std::printf("%-7s %-28s %-36s %6d %6d %6d %12.4g%s\n", r.light.c_str(), r.geometry.c_str(),
                r.option.c_str(), r.nan, r.inf, r.negative, r.max_value, r.ok() ? "" : "  <-- BAD");
    std::fflush(stdout);
  });
  std::printf("%d cases, %d with NaN/Inf/negative pixels\n", total, bad);
  return bad == 0 ? 0 : 1;
}

}  // namespace hv::app
