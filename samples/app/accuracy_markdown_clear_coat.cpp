// `halfvec accuracy`'s clear-coat section (halfvec/eval/accuracy_report.hpp, measureClearCoat).
#include <sstream>

#include "app/accuracy_markdown.hpp"

namespace hv::app {

std::string clearCoatMarkdown(const eval::ClearCoatAccuracy& a) {
  std::ostringstream md;
  md << "## Clear coat\n\n"
     << "A dielectric sphere (base color (0.6, 0.5, 0.4), roughness 0.6) under a full clear coat "
        "(weight 1, F0 0.04; "
        "shaders/common/clear_coat.glsl, docs/brdf.md \"Clear coat\") on a grey floor, lit by one "
        "light: a "
        "sphere light (radius 0.15 m), a tube (0.8 m by 0.05 m), the sun (a directional light of "
        "angular diameter "
     << fmtNum("%.4f", kSunAngularDiameter)
     << " rad) or the sky alone; physical falloff. The engine against the reference's integral "
        "of both lobes ("
     << a.samples << " samples per pixel, " << a.width << "x" << a.height
     << "), over the sphere's pixels: rel. RMSE and bias (sum(E - R) / sum R). Beside it, the "
        "same pixels of the same sphere without its coat, with the same method: what the coat's "
        "lobe adds to the base's error. Reference noise: the per-pixel standard errors over the "
        "sum (about 0.8 times the rel. RMSE noise alone would give). "
     << a.rows.size() << " configurations, " << fmtNum("%.0f", a.seconds) << " s.\n\n";
  md << headerRow({"light", "method", "coat roughness", "rel. RMSE", "bias", "reference noise",
                   "without the coat", "bias"});
  for (const auto& r : a.rows) {
    md << row({r.light, r.method, fmtNum("%.2f", r.coat_roughness), pct(r.coated.rel_rmse),
               spct(r.coated.bias), pct(r.coated.pixel_noise), pct(r.bare.rel_rmse),
               spct(r.bare.bias)});
  }
  md << "\n";
  return md.str();
}

}  // namespace hv::app
