// `halfvec accuracy`'s occlusion section (halfvec/eval/occlusion_accuracy.hpp).
#include <sstream>

#include "app/accuracy_markdown.hpp"

namespace hv::app {

std::string occlusionMarkdown(const eval::OcclusionAccuracy& a) {
  std::ostringstream md;
  md << "## Ambient and specular occlusion\n\n"
     << "Screen-space ambient occlusion (`settings.ao: gtao`, docs/ambient-occlusion.md) against "
        "the reference with environment visibility, environment light only: a sphere resting on "
        "a plane, a box corner and stairs under a uniform environment of radiance 1, "
        "DamagedHelmet under two HDRs. AO error: mean |engine - reference| over lit pixels, "
        "the engine's AO being its ambient diffuse over that of `ao: none`, the reference's its "
        "AO image within ao_distance = 1 m (the default ao_radius); ambient, diffuse, specular: "
        "sum|E - R| / sum R of the environment's light against the reference's, shadowed "
        "(occluders at any distance), bias likewise signed; the environment's light is the "
        "ambient terms plus, where `sky_sun` draws the environment's sun as a light (the "
        "HDR's sun of venice_sunset; docs/ibl.md), that light's direct terms, which the "
        "reference books apart. Shading alone: `ao none` against the reference without "
        "visibility, what the engine's own approximations leave. AO ms: the AO pass at this "
        "size ("
     << fmtNum("%.0f", a.seconds) << " s in all).\n\n";
  for (const auto& s : a.scenes) {
    md << "### " << s.name << "\n\n";
    if (!s.skipped.empty()) {
      md << "skipped: " << s.skipped << "\n\n";
      continue;
    }
    md << s.width << "x" << s.height << ", " << s.lit_pixels << " lit pixels, reference "
       << s.samples << " samples per pixel (its noise: " << pct(s.reference_noise)
       << " of the ambient); shading alone: " << pct(s.shading_only) << ".\n\n";
    md << headerRow({"configuration", "AO error", "AO bias", "ambient: rel. error", "bias",
                     "diffuse", "specular", "AO ms"});
    for (const auto& r : s.rows) {
      md << row({"`" + r.config + "`", fmtNum("%.3f", r.ao_mean_abs), fmtNum("%+.3f", r.ao_bias),
                 pct(r.ambient), spct(r.ambient_bias), pct(r.diffuse), pct(r.specular),
                 r.ms > 0.0 ? fmtNum("%.2f", r.ms) : std::string("-")});
    }
    md << "\n";
  }
  return md.str();
}

}  // namespace hv::app
