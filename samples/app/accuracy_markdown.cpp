#include "app/accuracy_markdown.hpp"

#include <algorithm>
#include <cstdio>
#include <sstream>

namespace hv::app {

std::string fmtNum(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}
std::string pct(double v) {
  return fmtNum("%.1f%%", 100.0 * v);
}
std::string spct(double v) {
  return fmtNum("%+.1f%%", 100.0 * v);
}
std::string num(double v) {
  return fmtNum("%g", v);
}

std::string row(const std::vector<std::string>& cells) {
  std::string s = "|";
  for (const std::string& c : cells) s += " " + c + " |";
  return s + "\n";
}

std::string headerRow(const std::vector<std::string>& cells) {
  std::string s = row(cells) + "|";
  for (size_t i = 0; i < cells.size(); ++i) s += "---|";
  return s + "\n";
}

std::string goalRow(const std::string& goal, const eval::GoalCheck& c, double tol, int need) {
  const bool met = c.count > 0 && c.within >= (need < 0 ? c.count : need);
  return row({goal, std::to_string(c.within) + " of " + std::to_string(c.count),
              c.worst_peak_where.empty() ? std::string("-")  // bias-only goal (diffuse)
                                         : pct(c.worst_peak) + " (" + c.worst_peak_where + ")",
              pct(c.worst_bias) + " (" + c.worst_bias_where + ")",
              met ? "met"
                  : (c.worst_peak <= 2.0 * tol && c.worst_bias <= 2.0 * tol ? "missed (within 2x)"
                                                                            : "missed")});
}

namespace {

std::string summaryRow(const eval::MethodSummary& m) {
  return row({m.light + " " + m.term, m.method, std::to_string(m.count), pct(m.median),
              pct(m.worst) + " (" + spct(m.worst_bias) + ")", fmtNum("%.2f", m.peak_worst),
              m.where});
}

// The summary lines of the methods a reader compares first.
bool headline(const eval::MethodSummary& m) {
  return m.method.find("V schlick") == std::string::npos &&
         m.method.find("D beckmann") == std::string::npos;
}

std::string straddlingGoalRows(const eval::SphereAccuracy& sphere) {
  return goalRow("sphere `ltc` specular straddling the horizon, within 15% (bias)",
                 eval::checkStraddlingGoal(sphere, eval::kSphereLtc, 0.15), 0.15) +
         goalRow("sphere `ltc` specular straddling the horizon, within 10% (bias), at least 120",
                 eval::checkStraddlingGoal(sphere, eval::kSphereLtc, 0.10), 0.10, 120) +
         goalRow("sphere `representative_point` (default) straddling, within 15% (bias)",
                 eval::checkStraddlingGoal(sphere, eval::kSphereRp, 0.15), 0.15);
}

}  // namespace

std::string sphereGoalsMarkdown(const eval::SphereAccuracy& sphere) {
  std::ostringstream md;
  md << "## Sphere lights: goals\n\n"
     << headerRow({"goal", "configurations within", "worst peak", "worst bias", ""})
     << goalRow(
            "sphere `ltc` specular within 5%, roughness 0.05-1, r/d 0.01-0.5, above the horizon",
            eval::checkSphereGoal(sphere, eval::kSphereLtc, 0.05, 0.5f), 0.05)
     << straddlingGoalRows(sphere) << "\n";
  return md.str();
}

std::string summaryMarkdown(const eval::SphereAccuracy& sphere, const eval::TubeAccuracy& tube,
                            const eval::PointLightAccuracy& point,
                            const eval::AmbientAccuracy& ambient) {
  std::ostringstream md;
  md << "## Summary\n\n"
     << "Rel. error = sum over a configuration's views of |engine - reference| / sum of the "
        "reference (the whole highlight); peak = engine / reference at the mirror view. Per "
        "method: "
        "configurations, median and worst rel. error (with that configuration's bias), the peak "
        "ratio farthest from 1. Spheres: entirely above the horizon (straddling ones in their own "
        "section); each method against the reference of its own BRDF terms (`ltc` is fitted to "
        "GGX x height-correlated Smith, its row is measured with that V; the default V "
        "Schlick-GGX: section \"Other BRDF choices\").\n\n"
     << headerRow({"light, term", "method", "configurations", "median", "worst (bias)",
                   "peak farthest from 1", "worst at"});
  for (const auto& m : eval::summarizeSphere(sphere, false)) {
    if (headline(m)) md << summaryRow(m);
  }
  for (const auto& m : eval::summarizeTube(tube)) {
    if (headline(m)) md << summaryRow(m);
  }
  md << "\nPoint lights: " << pct(point.worst)
     << " largest relative error (the half-float target's rounding). Ambient: see its section ("
     << ambient.envs.size() << " environments).\n\n";
  md << "Accuracy targets of the `ltc` modes (peak = |E/R - 1| at the mirror view, bias = |sum (E "
        "- R)| / sum R "
        "over the views):\n\n"
     << headerRow({"goal", "configurations within", "worst peak", "worst bias", ""})
     << goalRow(
            "sphere `ltc` specular within 5%, roughness 0.05-1, r/d 0.01-0.5, above the horizon",
            eval::checkSphereGoal(sphere, eval::kSphereLtc, 0.05, 0.5f), 0.05)
     << goalRow("sphere `representative_point` (default), same grid",
                eval::checkSphereGoal(sphere, eval::kSphereRp, 0.05, 0.5f), 0.05)
     << straddlingGoalRows(sphere)
     << goalRow("tube `ltc` specular within 10%, length 0.25-2, radius 0.01-0.2, both orientations",
                eval::checkTubeGoal(tube, eval::kTubeLtc, false, 0.10), 0.10)
     << goalRow("tube eq. 19 + normalization (default), same grid",
                eval::checkTubeGoal(tube, eval::kTubeRp, false, 0.10), 0.10)
     << goalRow("tube `ltc` diffuse within 2% (bias)",
                eval::checkTubeGoal(tube, eval::kTubeDiffuseLtc, true, 0.02), 0.02)
     << goalRow("tube `karis_eq16` diffuse (default), within 2% (bias)",
                eval::checkTubeGoal(tube, eval::kTubeDiffuseKaris, true, 0.02), 0.02)
     << "\n";
  return md.str();
}

std::string pointLightMarkdown(const eval::PointLightAccuracy& a) {
  std::ostringstream md;
  md << "## Point lights\n\n"
     << "Three point lights on a sphere and a floor (" << a.width << "x" << a.height
     << ", physical falloff), engine (GPU, RGBA16F target) vs reference. The reference "
        "evaluates point lights in closed form, so its noise is exactly 0 (its reported "
        "standard error: "
     << num(a.reference_error)
     << "); the only expected difference is the engine's half-float target, whose rounding "
        "is 2^-11 = 0.049% relative.\n\n"
     << headerRow({"term", "lit pixels", "max relative error", "rel. RMSE", "bias"});
  for (const auto& t : a.terms) {
    md << row({t.name, std::to_string(t.pixels), pct(t.max_rel), pct(t.rel_rmse), spct(t.bias)});
  }
  md << "\nMax relative error (pixels with reference > 1e-3): " << pct(a.worst)
     << ": the point light agrees with the reference to the precision of the half-float "
        "target (tests/reference/test_engine_vs_reference.cpp asserts 0.4% + 1e-5 per "
        "channel).\n\n";
  return md.str();
}

std::string otherBrdfMarkdown(const eval::SphereAccuracy& sphere, const eval::TubeAccuracy& tube) {
  std::ostringstream md;
  md << "## Other BRDF choices (the `ltc` modes with another V or D)\n\n"
     << "The LTC table is fitted to GGX x height-correlated Smith (docs/lights.md). With another "
        "V term (the default is Schlick-GGX with the Disney remap), `ltc` keeps the fitted shape "
        "and scales its magnitude by the scene's V over Smith's at the mirror direction (the \"V "
        "ratio\", HV_LTC_V_RATIO); the light correction of spheres and tubes evaluates the "
        "scene's own lobe. With Beckmann D the shape stays GGX. Each row against the reference "
        "of its own BRDF (spheres above the horizon; tubes: every configuration):\n\n"
     << headerRow({"light, term", "method", "configurations", "median", "worst (bias)",
                   "peak farthest from 1", "worst at"});
  for (const auto& m : eval::summarizeSphere(sphere, false)) {
    if (m.term == "specular" &&
        (m.method.find("ltc") == 0 || m.method.find("smith") != std::string::npos))
      md << summaryRow(m);
  }
  for (const auto& m : eval::summarizeTube(tube)) {
    if (m.term == "specular" &&
        (m.method.find("ltc") == 0 || m.method.find("smith") != std::string::npos))
      md << summaryRow(m);
  }
  md << "\n";
  return md.str();
}

std::string ambientMarkdown(const eval::AmbientAccuracy& a) {
  std::ostringstream md;
  md << "## Ambient (image-based) light\n\n"
     << "A row of metallic spheres (base color 1, so f0 = 1 and no diffuse) above a row of white "
        "dielectric spheres, one roughness per column, lit by the environment alone, "
     << a.width << "x" << a.height << ". Engine AOVs (`halfvec render --aov`) vs the reference's ("
     << a.samples
     << " samples per pixel: cosine, GGX-VNDF and luminance sampling with MIS against the "
        "full-resolution environment). Per roughness: ambient specular over the metallic sphere's "
        "pixels (split sum with the 2D table, and with EnvBRDFApprox), ambient diffuse (SH9 "
        "irradiance) over the dielectric sphere's; rel. error = sum|E - R| / sum R over pixels "
        "and channels, bias likewise signed, noise = the reference's relative standard error "
        "of the sum (the floor for the bias) / sum of its per-pixel standard errors over sum R "
        "(the floor for the rel. error, which adds per-pixel noise). Where `sky_sun` (default "
        "`light`) draws the environment's sun as a directional light (venice_sunset's; "
        "docs/ibl.md, \"An HDR's sun as a light\"), both sides' ambient terms are without it: "
        "the reference books the sun's part under the direct terms, which this section leaves "
        "out.\n\n";
  auto noise = [](const eval::LitStats& l) { return pct(l.noise) + " / " + pct(l.pixel_noise); };
  for (const auto& e : a.envs) {
    md << "### " << e.name << "\n\n";
    if (!e.skipped.empty()) {
      md << "skipped: " << e.skipped << "\n\n";
      continue;
    }
    md << headerRow({"roughness", "specular (table): rel. error", "bias", "noise",
                     "specular (EnvBRDFApprox): rel. error", "bias", "diffuse (SH9): rel. error",
                     "bias", "noise"});
    for (const auto& r : e.rows) {
      md << row({num(r.roughness), pct(r.specular_table.rel_error), spct(r.specular_table.bias),
                 noise(r.specular_table), pct(r.specular_approx.rel_error),
                 spct(r.specular_approx.bias), pct(r.diffuse.rel_error), spct(r.diffuse.bias),
                 noise(r.diffuse)});
    }
    md << "\n";
  }
  md << "### EnvBRDFApprox vs the table\n\n"
     << "Karis 2014's analytic fit against the engine's " << a.table_size << "x" << a.table_size
     << " table (Karis 2013 eq. 8, integrated as the bake does), at every texel center; the "
        "specular reflectance f0 scale + bias:\n\n"
     << headerRow({"f0", "mean abs. error", "max abs. error", "where"})
     << row({"0.04", fmtNum("%.4f", a.mean_abs[0]), fmtNum("%.4f", a.max_abs[0]), a.where_abs[0]})
     << row({"1", fmtNum("%.4f", a.mean_abs[1]), fmtNum("%.4f", a.max_abs[1]), a.where_abs[1]})
     << "\nLargest relative error (f0 = 1): " << pct(a.max_rel) << " at " << a.where_rel << ".\n\n";
  return md.str();
}

std::string scenesMarkdown(const std::vector<eval::SceneAccuracy>& scenes,
                           const std::string& heat_dir) {
  std::ostringstream md;
  md << "## Sample scenes\n\n"
     << "Each scene of samples/scenes with `settings.falloff_plus_one=false` (the physical "
        "falloff the reference integrates), engine vs reference, lit pixels only (emissive "
        "excluded). Heat maps: relative error per pixel (metrics.hpp relativeError), 0 to 50%. "
        "`many_lights` is not included: its 1536 lights make the reference take hours on this "
        "machine.\n\n";
  for (const auto& s : scenes) {
    md << "### " << s.name << "\n\n"
       << "![relative error, " << s.name << "](" << heat_dir << "/" << s.name << ".png)\n\n"
       << s.width << "x" << s.height << ", reference " << s.samples
       << " samples per pixel: " << s.lit_pixels << " lit pixels, relative standard error mean "
       << pct(s.reference_mean_rel) << ", max " << pct(s.reference_max_rel) << ".\n\n"
       << headerRow(
              {"term", "rel. error", "bias", "noise (sum / per pixel)", "rel. RMSE", "p99 rel."});
    auto line = [&](const std::string& name, const eval::LitStats& t) {
      md << row({name, pct(t.rel_error), spct(t.bias), pct(t.noise) + " / " + pct(t.pixel_noise),
                 pct(t.rel_rmse), pct(t.p99_rel)});
    };
    line("all", s.all);
    for (const auto& [name, t] : s.terms) line(name, t);
    md << "\n";
  }
  return md.str();
}

}  // namespace hv::app
