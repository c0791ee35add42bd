// The shadows section of docs/accuracy.md (eval/shadow_accuracy.hpp's data).
#include <algorithm>
#include <cmath>
#include <sstream>

#include "app/accuracy_markdown.hpp"
#include "halfvec/scene/enums.hpp"

namespace hv::app {

namespace {

std::string cm(double metres) {
  return std::isfinite(metres) ? fmtNum("%.1f", 100.0 * metres) : std::string("n/a");
}

std::string lightName(const eval::ShadowCase& c) {
  const std::string off =
      c.light_offset > 0.0f ? ", " + num(c.light_offset) + " m off (contact)" : std::string();
  if (c.light_length > 0.0f) {
    return "capsule r " + num(c.light_radius) + ", len " + num(c.light_length) + ", axis " +
           (std::abs(c.axis.x) > 0.5f ? "along" : "across") + off;
  }
  return "sphere r " + num(c.light_radius) + off;
}

}  // namespace

std::string shadowsMarkdown(const eval::ShadowAccuracy& a) {
  std::ostringstream md;
  const auto& o = a.options;
  md << "## Shadows\n\n"
     << "The engine's shadowed direct diffuse against the reference with visibility rays "
        "(Embree), per shadow filter (eval/shadow_accuracy.cpp; test: "
        "tests/eval/test_shadow_accuracy.cpp). A sphere occluder (radius "
     << num(eval::kShadowOccluderRadius) << " m, center at height h) over a white matte floor, lit "
     << "by a sphere light or a capsule light centered " << num(eval::kShadowLightHeight)
     << " m above the floor over the occluder, or (contact rows) off to -x by the given distance "
        "with the occluder resting on the floor (h = its radius), the shadow running along +x "
        "from under it; the frame ("
     << o.size << "x" << o.size << ", " << o.samples
     << " reference samples per pixel, shadow maps of " << o.map_size
     << "^2 texels per face) looks down at the +x half of the shadow. Pixels: the floor's, "
        "except the umbra (the engine below 2% of its frame without shadows and the reference "
        "below 2% of its value without visibility). Mean = sum |E - R| / sum R over them; "
        "penumbra = the same over the pixels where either is between 2% and 98%; worst = the "
        "largest |E - R| / R of the profile along +x (bins one pixel wide of the distance from "
        "the shadow's center, floor pixels within 25 degrees of +x) where R is at least 10% of "
        "the unshadowed value, with its distance from the shadow's center. Width: the penumbra's "
        "10%-90% width along that profile (shadowed over unshadowed: the engine's over its frame "
        "without shadows, the reference's over the same samples without visibility). "
        "Unshadowed: the engine without shadows against the reference without visibility over "
        "the floor pixels (the shading's own error; the engine uses its most accurate diffuse "
        "methods, sphere_diffuse horizon_correct and tube_diffuse ltc). Capsule: along = axis "
        "along +x, the measured direction; 4x the reference samples. Reference noise: the sum of "
        "the per-pixel standard errors over the sum of the reference (per-pixel noise adds about "
        "0.8 times it to a mean error). Measured in "
     << fmtNum("%.0f", a.seconds) << " s.\n\n"
     << headerRow({"light", "h (m)", "pixels (penumbra)", "ref. noise", "unshadowed",
                   "hard: mean / penumbra / worst (at cm)", "pcf: mean / penumbra / worst (at cm)",
                   "pcss: mean / penumbra / worst (at cm)",
                   "pcss, shadow_quality high: mean / penumbra / worst (at cm)",
                   "pcss, shadow_resolution half: mean / penumbra / worst (at cm)",
                   "width (cm): ref / hard / pcf / pcss / pcss high / pcss half"});
  double pcss_sum = 0.0, pcss_max = 0.0, half_sum = 0.0, half_max = 0.0, high_sum = 0.0,
         high_max = 0.0;
  for (const eval::ShadowCaseResult& r : a.rows) {
    std::vector<std::string> cells = {
        lightName(r.c), num(r.c.occluder_height),
        std::to_string(r.pixels) + " (" + std::to_string(r.penumbra_pixels) + ")",
        pct(r.reference_noise), pct(r.unshadowed_mean_rel)};
    std::string widths = cm(r.reference_width);
    for (const eval::ShadowFilterError& f : r.filters) {
      cells.push_back(pct(f.mean_rel) + " / " + pct(f.penumbra_mean_rel) + " / " +
                      pct(f.worst_rel) + " (" + cm(f.worst_rho) + ")");
      widths += " / " + cm(f.width);
      const bool half = f.resolution == ShadowResolution::Half;
      const bool high = f.quality == ShadowQuality::High;
      if (f.filter == ShadowFilter::Pcss) {
        (half ? half_sum : high ? high_sum : pcss_sum) += f.mean_rel;
        double& m = half ? half_max : high ? high_max : pcss_max;
        m = std::max(m, f.mean_rel);
      }
    }
    cells.push_back(widths);
    md << row(cells);
  }
  const auto verdict = [](double mean, double max) {
    return max <= 0.10 ? "met in every row" : mean <= 0.10 ? "met on average" : "missed";
  };
  const double rows = double(std::max<size_t>(a.rows.size(), 1));
  md << "\nGoal: pcss within 10% mean relative error over the grid: mean of the rows "
     << pct(pcss_sum / rows) << ", worst row " << pct(pcss_max) << " ("
     << verdict(pcss_sum / rows, pcss_max) << "); with shadow_resolution half (the visibility "
     << "once per 2x2 pixels, upsampled: docs/lights.md, \"Shadows\") mean " << pct(half_sum / rows)
     << ", worst row " << pct(half_max) << " (" << verdict(half_sum / rows, half_max)
     << "); with shadow_quality high (32 gathers in the blocker search: docs/lights.md, \"Shadow "
     << "quality\") mean " << pct(high_sum / rows) << ", worst row " << pct(high_max) << " ("
     << verdict(high_sum / rows, high_max) << ").\n\n";
  return md.str();
}

}  // namespace hv::app
