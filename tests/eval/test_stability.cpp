// The CI-sized stability sweep: zero NaN/Inf/negative HDR pixels, read back from the GPU.
#include <gtest/gtest.h>

#include "halfvec/eval/stability.hpp"
#include "halfvec/platform/context.hpp"

TEST(Stability, SmallSweepHasNoBadPixels) {
  auto ctx = hv::createHeadlessContext();
  hv::eval::StabilityOptions o;
  o.small = true;
  o.size = 32;
  const auto rows = hv::eval::runStabilitySweep(o);
  ASSERT_GT(rows.size(), 100u);
  for (const auto& r : rows) {
    EXPECT_TRUE(r.ok()) << r.light << " / " << r.geometry << " / " << r.option << ": NaN " << r.nan
                        << ", Inf " << r.inf << ", negative " << r.negative;
  }
}
