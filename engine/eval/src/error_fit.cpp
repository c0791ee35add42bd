#include "halfvec/eval/error_fit.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "halfvec/core/parallel.hpp"
#include "halfvec/shading/shading.hpp"

// error_budget.glsl with the budget compiled in (hv::glsl has it without): the table lookup and
// the choice, exactly as the light pass runs them.
namespace hv::eval::budget_glsl {
using namespace glm;
using namespace ::hv::glsl;
#undef HV_ERROR_BUDGET_GLSL
#undef HV_ERROR_BUDGET
#define HV_ERROR_BUDGET 1
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
namespace {
#include "halfvec/shaders/common/error_budget.glsl"
}  // namespace
#pragma GCC diagnostic pop
#undef HV_ERROR_BUDGET
}  // namespace hv::eval::budget_glsl

namespace hv::eval {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr float kMaxLogRatio = 4.0f;  // e^4 = 55x: beyond it the budget's choice is the same
constexpr int kNx = HV_ERR_TEXELS_X;
constexpr int kNy = HV_ERR_SIN_CELLS, kNz = HV_ERR_NOV_CELLS;
constexpr int kDims[5] = {HV_ERR_ROUGHNESS_CELLS, HV_ERR_SIN_CELLS, HV_ERR_NOV_CELLS,
                          HV_ERR_OFFSET_CELLS, HV_ERR_AZIMUTH_CELLS};

// Cell (i roughness, j sin sigma, k N.V, l offset, m azimuth) in texel order.
size_t texelIndex(const int c[5]) {
  return (size_t(c[2]) * kNy + size_t(c[1])) * kNx +
         (size_t(c[4]) * HV_ERR_OFFSET_CELLS + size_t(c[3])) * HV_ERR_ROUGHNESS_CELLS +
         size_t(c[0]);
}

// A sphere of the sweeps (sweepLight) at `center`, of `radius`.
Light sphereLight(const glm::vec3& center, float radius) {
  Light l = sweepLight(LightType::Sphere);
  l.position = center;
  l.radius = radius;
  return l;
}

// The view of N.V in the xz plane (N = +z), and the direction at angle theta from R in azimuth
// phi around it, phi = 0 toward N.
glm::vec3 viewOf(float NoV) {
  return {std::sqrt(std::max(1.0f - NoV * NoV, 0.0f)), 0.0f, NoV};
}
glm::vec3 aroundR(const glm::vec3& R, float theta, float phi) {
  const glm::vec3 t1(R.z, 0.0f, -R.x), t2(0.0f, 1.0f, 0.0f);  // both perpendicular to R
  return glm::normalize(std::cos(theta) * R +
                        std::sin(theta) * (std::cos(phi) * t1 + std::sin(phi) * t2));
}

const LightMethod& rpMethod() {
  return sphereSpecularMethods()[kSphereRp];
}
const LightMethod& ltcMethod() {
  return sphereSpecularMethods()[kSphereLtcSchlick];
}

// Cells without a measurement take the mean of their measured neighbours along each axis,
// repeatedly, until every cell has a value.
int fillEmptyCells(std::vector<float>& table, std::vector<char>& have) {
  int filled = 0;
  for (bool again = true; again;) {
    again = false;
    std::vector<float> next = table;
    std::vector<char> next_have = have;
    int c[5];
    for (c[4] = 0; c[4] < kDims[4]; ++c[4])
      for (c[3] = 0; c[3] < kDims[3]; ++c[3])
        for (c[2] = 0; c[2] < kDims[2]; ++c[2])
          for (c[1] = 0; c[1] < kDims[1]; ++c[1])
            for (c[0] = 0; c[0] < kDims[0]; ++c[0]) {
              const size_t at = texelIndex(c);
              if (have[at]) continue;
              double sum = 0.0;
              int n = 0;
              for (int axis = 0; axis < 5; ++axis) {
                for (int step : {-1, 1}) {
                  int nb[5] = {c[0], c[1], c[2], c[3], c[4]};
                  nb[axis] += step;
                  if (nb[axis] < 0 || nb[axis] >= kDims[axis]) continue;
                  if (have[texelIndex(nb)]) sum += table[texelIndex(nb)], ++n;
                }
              }
              if (n > 0) {
                next[at] = float(sum / n);
                next_have[at] = 1;
                ++filled;
              } else {
                again = true;
              }
            }
    table.swap(next);
    have.swap(next_have);
  }
  return filled;
}

}  // namespace

size_t fitErrorTableCells() {
  return HV_ERR_CELLS;
}

ErrorCell measureErrorCell(int i, int j, int k, int l, int m, int samples, uint64_t seed) {
  const glm::vec3 P(0.0f), N(0.0f, 0.0f, 1.0f);
  const glm::vec4 p = glsl::errorCellParameters(i, j, k, l);
  const float roughness = p.x, sin_sigma = std::min(p.y, 0.98f), NoV = p.z;
  const glm::vec3 V = viewOf(NoV);
  const glm::vec3 R(-V.x, 0.0f, V.z);
  const float alpha = roughness * roughness;
  const float theta = p.w * glsl::errorFootprint(alpha, sin_sigma);
  const float phi = std::acos(glsl::errorCellCosAzimuth(m));
  const int cell[5] = {i, j, k, l, m};
  ErrorCell c;
  double sum = 0.0;
  // Off the plane of N and R, both sides (the same by symmetry: two samples of one value).
  const int sides = phi > 0.1f && phi < float(kPi) - 0.1f ? 2 : 1;
  for (int side = 0; side < sides; ++side) {
    const glm::vec3 L = aroundR(R, theta, side ? -phi : phi);
    // Entirely below the horizon: no light, no error. A straddling sphere is measured too,
    // though the budget always takes the LTC there: it is the neighbour that the cells of
    // spheres just above the horizon interpolate toward, where the point's error grows.
    if (L.z <= -sin_sigma) continue;
    const Light light = sphereLight(L, sin_sigma);
    const double e =
        engineLightTerm(rpMethod().variant, light, P, N, V, glm::vec3(1.0f), 1.0f, roughness).x;
    const double r = integrateLight(light, P, N, V, glm::vec3(0.0f), glm::vec3(1.0f), roughness,
                                    samples, seed + texelIndex(cell) * 2 + uint64_t(side))
                         .specular.x;
    if (!(r > 0.0) || !(e > 0.0)) continue;
    sum += std::clamp(std::log(e / r), double(-kMaxLogRatio), double(kMaxLogRatio));
    ++c.measured;
  }
  if (c.measured > 0) c.log_ratio = float(sum / c.measured);
  return c;
}

ErrorFit fitErrorTable(const ErrorFitOptions& o) {
  const auto t0 = std::chrono::steady_clock::now();
  ErrorFit fit;
  fit.table.assign(size_t(kNx) * kNy * kNz, 0.0f);
  std::vector<char> have(fit.table.size(), 0);
  std::vector<int> measured(size_t(kNy) * kNz, 0);
  std::atomic<int> done{0};
  // One task per (N.V, sin sigma) slice: its roughness x offset cells.
  detail::parallelFor(kNy * kNz, o.threads, [&](int task) {
    const int j = task % kNy, k = task / kNy;
    for (int m = 0; m < HV_ERR_AZIMUTH_CELLS; ++m)
      for (int l = 0; l < HV_ERR_OFFSET_CELLS; ++l)
        for (int i = 0; i < HV_ERR_ROUGHNESS_CELLS; ++i) {
          const ErrorCell c = measureErrorCell(i, j, k, l, m, o.samples, o.seed);
          const int cell[5] = {i, j, k, l, m};
          if (c.measured > 0) {
            fit.table[texelIndex(cell)] = c.log_ratio;
            have[texelIndex(cell)] = 1;
          }
          measured[size_t(task)] += c.measured;
        }
    const int d = ++done;
    if (o.progress) o.progress(d, kNy * kNz);
  });
  for (int m : measured) fit.measured += m;
  fit.filled = fillEmptyCells(fit.table, have);
  fit.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return fit;
}

std::string errorTableSource(const ErrorFit& fit, const ErrorFitOptions& o,
                             const std::string& command) {
  std::ostringstream s;
  s << "// Generated by `" << command << "`\n"
    << "// (samples/app/cmd_error_fit.cpp, engine/eval/src/error_fit.cpp); do not edit: run the\n"
    << "// command again. The error budget's table of\n"
    << "// shaders/common/error_budget.glsl: ln(E_rp / R) of the representative-point sphere "
       "specular\n"
    << "// against the reference, " << o.samples << " sample pairs per cell and side; "
    << fit.measured << " measurements, " << fit.filled
    << " cells\n// filled from their neighbours (the sphere is below the horizon there).\n"
    << "// clang-format off\n"
    << "#include \"halfvec/shading/error_table.hpp\"\n"
    << "#include \"halfvec/shading/shading.hpp\"\n\n"
    << "namespace hv {\nnamespace {\n"
    << "// ln(E_rp / R) per cell, in texel order (error_budget.glsl).\n"
    << "constexpr float kTable[] = {\n";
  // Four significant digits: the measurement's own noise is larger (about 1e-2 in ln), and the
  // 163,840 cells stay a source file of about 1.6 MB.
  for (size_t c = 0; c < fit.table.size(); c += 8) {
    s << "   ";
    for (size_t q = c; q < std::min(c + 8, fit.table.size()); ++q) {
      std::ostringstream v;
      v << std::setprecision(4) << fit.table[q];
      std::string t = v.str();
      if (t.find_first_of(".e") == std::string::npos) t += ".0";
      s << " " << t << "f,";
    }
    s << "\n";
  }
  s << "};\nstatic_assert(sizeof(kTable) / sizeof(float) ==\n"
    << "              HV_ERR_CELLS);\n"
    << "}  // namespace\n\n"
    << "std::span<const float> errorTableData() { return kTable; }\n"
    << "std::string_view errorTableProvenance() {\n  return \"" << command << " (samples "
    << o.samples << ", seed " << o.seed << ")\";\n}\n\n"
    << "}  // namespace hv\n";
  return s.str();
}

float predictedSphereLogRatio(float roughness, float sin_sigma, float NoV, float offset,
                              float cos_phi) {
  return budget_glsl::sphereRpLogRatio(roughness, sin_sigma, NoV, offset, cos_phi);
}

float predictedSphereLogRatio(const glm::vec3& N, const glm::vec3& V, const glm::vec3& L_center,
                              float sin_sigma, float roughness) {
  const glsl::Surface s = glsl::makeSurface(N, glm::vec3(1.0f), 1.0f, roughness, 1.0f);
  const float NoV = std::max(glm::dot(N, V), glsl::HV_MIN_NOV);
  return budget_glsl::sphereRpLogRatioAt(s, glm::reflect(-V, N), NoV, L_center, sin_sigma);
}

bool budgetTakesLtc(const glm::vec3& N, const glm::vec3& V, const glm::vec3& L_center,
                    float sin_sigma, float roughness, float diffuse, float rp_specular,
                    float max_error) {
  const glsl::Surface s = glsl::makeSurface(N, glm::vec3(1.0f), 1.0f, roughness, 1.0f);
  const float NoV = std::max(glm::dot(N, V), glsl::HV_MIN_NOV);
  return budget_glsl::sphereNeedsLtc(s, glm::reflect(-V, N), NoV, L_center, sin_sigma,
                                     glm::vec3(diffuse), glm::vec3(rp_specular), max_error);
}

BudgetSweep sweepBudget(const SphereSweepGrid& g, const std::vector<double>& budgets) {
  BudgetSweep out;
  out.budgets = budgets;
  for (float r : g.roughness)
    for (float rad : g.radius)
      for (float el : g.elevation_deg) {
        BudgetSweepRow row;
        row.roughness = r;
        row.radius = rad;
        row.elevation_deg = el;
        row.above = sphereAboveHorizon(rad, el);
        out.rows.push_back(row);
      }
  const glm::vec3 P(0.0f), N(0.0f, 0.0f, 1.0f);
  detail::parallelFor(int(out.rows.size()), g.threads, [&](int idx) {
    BudgetSweepRow& row = out.rows[size_t(idx)];
    const float el = float(row.elevation_deg * kPi / 180.0);
    const glm::vec3 dir(std::cos(el), 0.0f, std::sin(el));
    const Light light = sphereLight(dir, row.radius);
    const auto views = sphereSweepViews(dir, row.roughness, row.radius);
    std::vector<double> rp, ltc, ref, ref_se;
    std::vector<std::vector<double>> chosen(budgets.size());
    std::vector<int> took(budgets.size(), 0);
    double pred_err = 0.0, pred_sum = 0.0;
    for (size_t v = 0; v < views.size(); ++v) {
      const glm::vec3& V = views[v];
      const LightIntegral x =
          integrateLight(light, P, N, V, glm::vec3(0.0f), glm::vec3(1.0f), row.roughness, g.samples,
                         g.seed + uint64_t(idx) * 1000003ull + v);
      ref.push_back(x.specular.x);
      ref_se.push_back(x.specular_se.x);
      const float e_rp =
          engineLightTerm(rpMethod().variant, light, P, N, V, glm::vec3(1.0f), 1.0f, row.roughness)
              .x;
      const float e_ltc =
          engineLightTerm(ltcMethod().variant, light, P, N, V, glm::vec3(1.0f), 1.0f, row.roughness)
              .x;
      rp.push_back(e_rp);
      ltc.push_back(e_ltc);
      const double t = predictedSphereLogRatio(N, V, dir, row.radius, row.roughness);
      pred_err += std::abs(e_rp - e_rp * std::exp(-t));
      pred_sum += e_rp * std::exp(-t);
      for (size_t b = 0; b < budgets.size(); ++b) {
        const bool l =
            budgetTakesLtc(N, V, dir, row.radius, row.roughness, 0.0f, e_rp, float(budgets[b]));
        chosen[b].push_back(l ? e_ltc : e_rp);
        took[b] += l;
      }
    }
    row.rp = termError(rp, ref, ref_se);
    row.ltc = termError(ltc, ref, ref_se);
    row.predicted = pred_sum > 0.0 ? pred_err / pred_sum : 0.0;
    for (size_t b = 0; b < budgets.size(); ++b) {
      row.budget.push_back(termError(chosen[b], ref, ref_se));
      row.ltc_share.push_back(double(took[b]) / double(views.size()));
    }
  });
  return out;
}

}  // namespace hv::eval
