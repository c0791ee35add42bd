// Markdown writers of `halfvec accuracy` (docs/accuracy.md): one function per section, each
// formatting measured data (halfvec/eval/accuracy_report.hpp). No measurement here.
#pragma once

#include <string>
#include <vector>

#include "halfvec/eval/accuracy_report.hpp"
#include "halfvec/eval/occlusion_accuracy.hpp"
#include "halfvec/eval/shadow_accuracy.hpp"

namespace hv::app {

// Formatting shared by the writers.
std::string fmtNum(const char* f, double v);
// A goals table's row: configurations within tol, the worst peak and bias, met or missed.
// `need`: how many configurations the goal asks to be within (all of them where negative).
std::string goalRow(const std::string& goal, const eval::GoalCheck& c, double tol, int need = -1);
std::string pct(double v);   // "12.3%"
std::string spct(double v);  // "+12.3%"
std::string num(double v);   // "%g"
std::string row(const std::vector<std::string>& cells);
std::string headerRow(const std::vector<std::string>& cells);

// The one-screen summary at the top: worst and typical error of every method per light type and
// term, and the goals checked.
std::string summaryMarkdown(const eval::SphereAccuracy& sphere, const eval::TubeAccuracy& tube,
                            const eval::PointLightAccuracy& point,
                            const eval::AmbientAccuracy& ambient);
std::string pointLightMarkdown(const eval::PointLightAccuracy& a);
std::string sphereMarkdown(const eval::SphereAccuracy& a);
// The sphere goals alone (`halfvec accuracy --only spheres`): above the horizon and straddling it.
std::string sphereGoalsMarkdown(const eval::SphereAccuracy& sphere);
std::string tubeMarkdown(const eval::TubeAccuracy& a);
// Capsules straddling the horizon (`halfvec accuracy --only tubes` and the full report).
std::string tubeStraddlingMarkdown(const eval::TubeStraddlingAccuracy& a);
std::string directionalMarkdown(const eval::SphereAccuracy& a);
// The error budget: the table's prediction and the budget's choices over the sphere sweep.
std::string budgetMarkdown(const eval::BudgetAccuracy& a);
// The LTC modes when the scene's V or D differs from the fitted lobe.
std::string otherBrdfMarkdown(const eval::SphereAccuracy& sphere, const eval::TubeAccuracy& tube);
std::string ambientMarkdown(const eval::AmbientAccuracy& a);
// The shadows section: each filter against the reference with visibility rays.
std::string shadowsMarkdown(const eval::ShadowAccuracy& a);
// `heat_dir`: the folder name of the heat maps relative to the document.
std::string scenesMarkdown(const std::vector<eval::SceneAccuracy>& scenes,
                           const std::string& heat_dir);
// Screen-space ambient and specular occlusion against the reference with visibility.
std::string occlusionMarkdown(const eval::OcclusionAccuracy& a);
std::string clearCoatMarkdown(const eval::ClearCoatAccuracy& a);

}  // namespace hv::app
