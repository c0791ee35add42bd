#include <gtest/gtest.h>

#include "halfvec/shading/shading.hpp"

TEST(ShadingMath, HelpersCompileAsCpp) {
  EXPECT_FLOAT_EQ(hv::glsl::saturate(2.0f), 1.0f);
  EXPECT_FLOAT_EQ(hv::glsl::saturate(-1.0f), 0.0f);
  EXPECT_FLOAT_EQ(hv::glsl::pow5(0.5f), 0.03125f);
}
