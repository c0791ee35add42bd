// The error-budget section of docs/accuracy.md: the table's prediction of the representative
// point's error, and the budget's choices, over the sphere sweep.
#include <algorithm>
#include <cmath>
#include <sstream>

#include "app/accuracy_markdown.hpp"
#include "halfvec/shading/error_table.hpp"

namespace hv::app {

namespace {

// Whether the prediction agrees with the measurement: within a factor 1.5, or both within the
// reference's noise of each other (twice its relative standard error), which a factor cannot
// resolve.
bool predictionAgrees(const eval::BudgetSweepRow& r) {
  const double m = r.rp.rel_error, p = r.predicted;
  if (std::abs(m - p) <= 2.0 * r.rp.noise) return true;
  return p <= 1.5 * m && m <= 1.5 * p;
}

std::string budgetChoiceMarkdown(const eval::BudgetAccuracy& a);

}  // namespace

std::string budgetMarkdown(const eval::BudgetAccuracy& a) {
  std::ostringstream md;
  const auto& rows = a.sweep.rows;
  md << "## Error budget (`max_error`)\n\n"
     << "With `settings.max_error` = b, a sphere or directional light shaded with the "
        "representative point takes the LTC where the point's predicted error for that pixel and "
        "light exceeds b times the pair's radiance (shaders/common/error_budget.glsl; "
        "docs/lights.md, \"Error budget\"). The prediction is a table of ln(E_rp / R) over "
        "roughness x sin(sigma) x N.V x the light's angle from R in footprints x its azimuth "
        "around R, measured against the reference by `"
     << errorTableProvenance()
     << "` (engine/shading/src/error_table.cpp). Here: the sphere sweep above (its grid, views "
        "and reference, "
     << a.grid.samples << " samples per view), specular alone, V Schlick-GGX (the engine's "
     << "default; `ltc` with the V ratio), " << rows.size() << " configurations, "
     << fmtNum("%.1f", a.seconds) << " s.\n\n";

  // Calibration.
  int above = 0, agree = 0;
  std::vector<double> ratios;
  for (const auto& r : rows) {
    if (!r.above || !r.rp.valid) continue;
    ++above;
    agree += predictionAgrees(r);
    if (r.rp.rel_error > 0.0) ratios.push_back(r.predicted / r.rp.rel_error);
  }
  std::sort(ratios.begin(), ratios.end());
  auto quantile = [&](double q) {
    return ratios.empty() ? 0.0 : ratios[size_t(q * double(ratios.size() - 1) + 0.5)];
  };
  md << "### The table's prediction against the measured error of the representative point\n\n"
     << "Predicted = sum over the views of |E_v - E_v e^-t_v| / sum of E_v e^-t_v (what the "
        "engine knows), measured = the sweep's rel. error. Spheres above the horizon: "
     << agree << " of " << above
     << " configurations agree (within a factor 1.5, or within twice the reference's noise of "
        "each other); predicted / measured: median "
     << fmtNum("%.2f", quantile(0.5)) << ", 10th percentile " << fmtNum("%.2f", quantile(0.1))
     << ", 90th " << fmtNum("%.2f", quantile(0.9)) << ".\n\n"
     << "Measured / predicted, the configuration of largest measured error over the elevations "
        "above the horizon:\n\n";
  std::vector<std::string> head{"roughness \\ r/d"};
  for (float rad : a.grid.radius) head.push_back(num(rad));
  md << headerRow(head);
  for (float rough : a.grid.roughness) {
    std::vector<std::string> cells{num(rough)};
    for (float rad : a.grid.radius) {
      const eval::BudgetSweepRow* worst = nullptr;
      for (const auto& r : rows) {
        if (r.roughness != rough || r.radius != rad || !r.above || !r.rp.valid) continue;
        if (!worst || r.rp.rel_error > worst->rp.rel_error) worst = &r;
      }
      cells.push_back(worst ? pct(worst->rp.rel_error) + " / " + pct(worst->predicted) +
                                  " (elevation " + num(worst->elevation_deg) +
                                  (predictionAgrees(*worst) ? ")" : ", off)")
                            : "straddles");
    }
    md << row(cells);
  }

  md << budgetChoiceMarkdown(a);
  return md.str();
}

namespace {

// Per budget: the configurations met, against `ltc`'s and the representative point's.
std::string budgetChoiceMarkdown(const eval::BudgetAccuracy& a) {
  std::ostringstream md;
  const auto& rows = a.sweep.rows;
  md << "\n### The budget's choice\n\n"
     << "Per budget b: the configurations where `ltc` alone is within b (rel. error), how many "
        "of them the budget also meets (within b plus twice the reference's noise), the worst "
        "budget error among them, the representative point's count for comparison, and the "
        "share of the views that took the LTC (spheres above the horizon / straddling it, where "
        "the budget always takes it).\n\n"
     << headerRow({"max_error", "ltc within", "budget within", "worst budget error",
                   "representative point within", "views taking the LTC (above / straddling)"});
  for (size_t b = 0; b < a.sweep.budgets.size(); ++b) {
    const double bud = a.sweep.budgets[b];
    int ltc_in = 0, budget_in = 0, rp_in = 0, n_above = 0, n_straddle = 0;
    double worst = 0.0, share_above = 0.0, share_straddle = 0.0;
    for (const auto& r : rows) {
      if (!r.ltc.valid) continue;
      (r.above ? share_above : share_straddle) += r.ltc_share[b];
      (r.above ? n_above : n_straddle) += 1;
      rp_in += r.rp.rel_error <= bud;
      if (r.ltc.rel_error > bud) continue;
      ++ltc_in;
      budget_in += r.budget[b].rel_error <= bud + 2.0 * r.budget[b].noise;
      worst = std::max(worst, r.budget[b].rel_error);
    }
    md << row({num(bud), std::to_string(ltc_in), std::to_string(budget_in), pct(worst),
               std::to_string(rp_in),
               pct(n_above ? share_above / n_above : 0.0) + " / " +
                   pct(n_straddle ? share_straddle / n_straddle : 0.0)});
  }
  md << "\n";
  return md.str();
}

}  // namespace

}  // namespace hv::app
