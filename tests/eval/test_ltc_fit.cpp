// The committed LTC table (engine/shading/src/ltc_table.cpp) against its fit (eval/ltc_fit.hpp):
// cells re-fitted reproduce it, and its magnitudes are the lobe's albedo.
#include <gtest/gtest.h>

#include <cmath>

#include "halfvec/eval/ltc_fit.hpp"
#include "halfvec/shading/ltc_table.hpp"
#include "halfvec/shading/shading.hpp"

using namespace hv;
using namespace hv::eval;

namespace {
constexpr double kPi = 3.14159265358979323846;
}  // namespace

// Re-fitting cells from the start the table's own fit used (the cell of the next roughness of the
// same row) reproduces the committed cells: the fit is deterministic, and the committed floats
// round-trip exactly. Tolerance 1e-5 relative (float printing).
TEST(LtcFit, RefitReproducesTheTable) {
  const std::span<const float> t = ltcTableData();
  constexpr int n = HV_LTC_TABLE_SIZE;
  const LtcFitOptions o;  // the options the committed table was generated with
  ASSERT_EQ(o.size, n);
  auto cell = [&](int i, int j) {
    return t.data() + (size_t(j) * n + size_t(i)) * kLtcFloatsPerCell;
  };
  for (auto [i, j] : {std::pair{40, 10}, std::pair{12, 30}, std::pair{3, 50}, std::pair{55, 62}}) {
    const float* next = cell(i + 1, j);
    const LtcParams start{next[0], next[1], next[2], next[3]};
    const glm::vec2 rn = glsl::ltcCellParameters(i, j);
    const LtcCell c = fitLtcCell(rn.x, rn.y, start, o);
    const float* want = cell(i, j);
    const float got[6] = {c.params.ax, c.params.ay,   c.params.sk,
                          c.params.dx, float(c.norm), float(c.fresnel)};
    for (int k = 0; k < 6; ++k) {
      EXPECT_NEAR(got[k], want[k], 1e-5f * std::abs(want[k]) + 1e-7f)
          << "cell " << i << ", " << j << " value " << k;
    }
  }
}

// The table's magnitude n_f is the directional albedo of the fitted lobe: against an independent
// quadrature (uniform directions on the hemisphere, 512^2 Hammersley points, the lobe evaluated
// directly) within 1% for cells of roughness >= 0.3 (the quadrature cannot resolve glossier lobes).
TEST(LtcFit, MagnitudeIsTheLobesAlbedo) {
  for (auto [i, j] : {std::pair{20, 5}, std::pair{40, 30}, std::pair{63, 50}, std::pair{30, 60}}) {
    const glm::vec2 rn = glsl::ltcCellParameters(i, j);
    const int m = 512 * 512;
    double sum = 0.0;
    for (int k = 0; k < m; ++k) {
      const glm::vec2 u = glsl::hammersley(uint32_t(k), uint32_t(m));
      const float z = u.x, s = std::sqrt(std::max(0.0f, 1.0f - z * z));
      const glm::vec3 l(s * std::cos(float(2.0 * kPi) * u.y), s * std::sin(float(2.0 * kPi) * u.y),
                        z);
      sum += ltcLobeValue(rn.x, rn.y, 1.0, l) * 2.0 * kPi / m;
    }
    const float* c =
        ltcTableData().data() + (size_t(j) * HV_LTC_TABLE_SIZE + size_t(i)) * kLtcFloatsPerCell;
    EXPECT_NEAR(c[4], sum, 0.01 * sum) << "cell " << i << ", " << j;
  }
}

// The fit's optional cap term (LtcFitOptions::cap_weight, `ltc-fit --cap-weight`; not the
// committed table's fit, docs/lights.md): it lowers the LTC's error over the caps it measures
// (sphere lights of 3-29 degrees on the lobe), at the cost of the pointwise norm. Cell: roughness
// 0.5, N.V 0.36, where the committed LTC is 40% too bright on the lobe's flank (docs/lights.md).
TEST(LtcFit, CapTermLowersTheCapError) {
  LtcFitOptions plain;
  LtcFitOptions caps;
  caps.cap_weight = 100.0;
  caps.cap_samples = 64;
  const float roughness = 0.5f, NoV = 0.36f;
  const LtcCell a = fitLtcCell(roughness, NoV, {}, plain);
  const LtcCell b = fitLtcCell(roughness, NoV, {}, caps);
  const double ea = ltcCapError(a.params, roughness, NoV, a.norm, 64);
  const double eb = ltcCapError(b.params, roughness, NoV, b.norm, 64);
  std::printf(
      "relative squared cap error: norm alone %.5f, with the cap term %.5f; L1 %.4f / %.4f\n", ea,
      eb, a.error, b.error);
  EXPECT_LT(eb, 0.5 * ea);
  EXPECT_GT(ea, 0.0);
  EXPECT_EQ(a.norm, b.norm);  // the magnitude is integrated either way
  EXPECT_LT(b.error, 0.5);    // still a lobe: L1 distance well below 2
}
