// The error budget's table and choice (shaders/common/error_budget.glsl, engine/eval
// error_fit.hpp): the committed table is what the reference measures, the lookup reads each cell
// where it was measured, and the budget's choice over the sphere sweep meets what `ltc` meets.
#include <gtest/gtest.h>

#include <cmath>

#include "halfvec/eval/error_fit.hpp"
#include "halfvec/shading/error_table.hpp"
#include "halfvec/shading/shading.hpp"

using namespace hv;

namespace {

size_t texel(int i, int j, int k, int l, int m) {
  return (size_t(k) * HV_ERR_SIN_CELLS + size_t(j)) * HV_ERR_TEXELS_X +
         (size_t(m) * HV_ERR_OFFSET_CELLS + size_t(l)) * HV_ERR_ROUGHNESS_CELLS + size_t(i);
}

}  // namespace

// The lookup at a cell's own configuration returns that cell (the coordinates and their inverse
// agree, and the offset's two fetches land on the right blocks).
TEST(ErrorTable, LookupAtACellReturnsTheCell) {
  const auto data = errorTableData();
  ASSERT_EQ(data.size(), eval::fitErrorTableCells());
  for (int m = 0; m < HV_ERR_AZIMUTH_CELLS; ++m)
    for (int k = 0; k < HV_ERR_NOV_CELLS; k += 3)
      for (int j = 0; j < HV_ERR_SIN_CELLS; j += 2)
        for (int l = 0; l < HV_ERR_OFFSET_CELLS; ++l)
          for (int i = 0; i < HV_ERR_ROUGHNESS_CELLS; i += 3) {
            const glm::vec4 p = glsl::errorCellParameters(i, j, k, l);
            EXPECT_NEAR(
                eval::predictedSphereLogRatio(p.x, p.y, p.z, p.w, glsl::errorCellCosAzimuth(m)),
                data[texel(i, j, k, l, m)], 1e-4f)
                << i << " " << j << " " << k << " " << l << " " << m;
          }
}

// The committed table against a new measurement with other random numbers (the command's own
// code): every 61st cell (a prime: the sample walks every axis) measured again agrees to within
// the reference's noise, 0.1 in ln (10%), on at least 95% of them.
TEST(ErrorTable, CommittedTableIsWhatTheReferenceMeasures) {
  const auto data = errorTableData();
  int close = 0, n = 0;
  for (size_t c = 0; c < data.size(); c += 61) {
    const int i = int(c % HV_ERR_ROUGHNESS_CELLS);
    const int l = int(c / HV_ERR_ROUGHNESS_CELLS % HV_ERR_OFFSET_CELLS);
    const int m = int(c / (HV_ERR_ROUGHNESS_CELLS * HV_ERR_OFFSET_CELLS) % HV_ERR_AZIMUTH_CELLS);
    const int j = int(c / HV_ERR_TEXELS_X % HV_ERR_SIN_CELLS);
    const int k = int(c / (HV_ERR_TEXELS_X * HV_ERR_SIN_CELLS));
    ASSERT_EQ(texel(i, j, k, l, m), c);
    const eval::ErrorCell cell = eval::measureErrorCell(i, j, k, l, m, 2048, 777);
    if (cell.measured == 0) continue;  // filled from its neighbours
    ++n;
    close += std::abs(cell.log_ratio - data[c]) <= 0.1f;
  }
  std::printf("%d of %d cells within 0.1 of the committed table\n", close, n);
  EXPECT_GT(n, 300);
  EXPECT_GE(close, n * 95 / 100);
}

// The choice: a budget of 0 takes the LTC wherever the table predicts any error, a budget of 1
// almost never does above the horizon; a sphere straddling the horizon or holding the shading
// point always takes it.
TEST(ErrorBudget, ChoiceFollowsTheBudgetAndTheHorizon) {
  const glm::vec3 N(0.0f, 0.0f, 1.0f), V = glm::normalize(glm::vec3(0.6f, 0.0f, 0.8f));
  const glm::vec3 R = glm::reflect(-V, N);
  // Glossy, small light on the mirror direction: the point is far off.
  EXPECT_TRUE(eval::budgetTakesLtc(N, V, R, 0.05f, 0.1f, 0.0f, 1.0f, 0.05f));
  EXPECT_FALSE(eval::budgetTakesLtc(N, V, R, 0.05f, 0.1f, 0.0f, 1.0f, 1e6f));
  // A bright diffuse hides the same error.
  EXPECT_FALSE(eval::budgetTakesLtc(N, V, R, 0.05f, 0.1f, 1e6f, 1.0f, 0.05f));
  // Straddling (elevation 2 degrees, sin sigma 0.2), and inside the sphere (sin sigma > 1).
  const glm::vec3 low(std::cos(0.035f), 0.0f, std::sin(0.035f));
  EXPECT_TRUE(eval::budgetTakesLtc(N, V, low, 0.2f, 0.6f, 0.0f, 1.0f, 1e6f));
  EXPECT_TRUE(eval::budgetTakesLtc(N, V, R, 1.5f, 0.6f, 0.0f, 1.0f, 1e6f));
}

// Over a reduced sphere sweep (roughness 0.05-1 x r/d 0.01-0.5 x elevations above and straddling
// the horizon, 4096 samples), max_error 0.05: of the configurations where `ltc` alone is within
// 5%, at least 85% are within 5% (plus twice the reference's noise) with the budget and every one
// within twice the budget, which takes the LTC for fewer views than all. (The prediction misses
// some of them: docs/accuracy.md, "Error budget".)
TEST(ErrorBudget, BudgetMeetsMostOfWhatLtcMeetsOnTheSweep) {
  eval::SphereSweepGrid g;
  g.roughness = {0.05f, 0.2f, 0.5f, 1.0f};
  g.radius = {0.01f, 0.1f, 0.5f};
  g.elevation_deg = {90.0f, 30.0f, 5.0f};
  g.samples = 4096;
  const eval::BudgetSweep sw = eval::sweepBudget(g, {0.05});
  int met = 0, ltc_met = 0;
  double share = 0.0;
  for (const auto& row : sw.rows) {
    if (!row.ltc.valid) continue;
    share += row.ltc_share[0];
    if (row.ltc.rel_error > 0.05) continue;
    ++ltc_met;
    const double slack = 2.0 * row.budget[0].noise;
    met += row.budget[0].rel_error <= 0.05 + slack;
    EXPECT_LE(row.budget[0].rel_error, 0.10 + slack)
        << "roughness " << row.roughness << ", r/d " << row.radius << ", elevation "
        << row.elevation_deg << ": ltc " << row.ltc.rel_error << ", rp " << row.rp.rel_error;
  }
  std::printf("%d of %d configurations that ltc meets, LTC share %.2f\n", met, ltc_met,
              share / double(sw.rows.size()));
  EXPECT_GT(ltc_met, 20);
  EXPECT_GE(met * 100, ltc_met * 85);
  EXPECT_LT(share, double(sw.rows.size()));
}
