// The scatter-plot writer of halfvec/image/plot.hpp: tick rules, text and the marked front.
#include <gtest/gtest.h>

#include <cmath>

#include "halfvec/image/plot.hpp"

namespace {
size_t countColor(const hv::ImageRGBA8& img, hv::Rgb8 c) {
  size_t n = 0;
  for (size_t i = 0; i < img.px.size(); i += 4)
    n += img.px[i] == c.r && img.px[i + 1] == c.g && img.px[i + 2] == c.b;
  return n;
}
}  // namespace

TEST(Plot, LinearTicksAreOneTwoFiveSteps) {
  const std::vector<double> t = hv::linearTicks(0.0, 10.0, 5);
  ASSERT_EQ(t.size(), 6u);
  for (size_t i = 0; i < t.size(); ++i) EXPECT_NEAR(t[i], 2.0 * double(i), 1e-12);
  const std::vector<double> u = hv::linearTicks(0.13, 0.61, 6);  // step 0.1 from 0.2
  ASSERT_FALSE(u.empty());
  EXPECT_NEAR(u.front(), 0.2, 1e-12);
  EXPECT_NEAR(u.back(), 0.6, 1e-12);
  EXPECT_TRUE(hv::linearTicks(1.0, 1.0).empty());
}

TEST(Plot, LogTicks) {
  const std::vector<double> fine = hv::logTicks(0.05, 2.0);  // < 3 decades: 1-2-5
  const std::vector<double> want = {0.05, 0.1, 0.2, 0.5, 1.0, 2.0};
  ASSERT_EQ(fine.size(), want.size());
  for (size_t i = 0; i < want.size(); ++i) EXPECT_NEAR(fine[i], want[i], 1e-12);
  const std::vector<double> coarse = hv::logTicks(1e-4, 10.0);  // powers of ten only
  ASSERT_EQ(coarse.size(), 6u);
  EXPECT_NEAR(coarse.front(), 1e-4, 1e-16);
  EXPECT_TRUE(hv::logTicks(0.0, 1.0).empty());
}

TEST(Plot, TextAndFrontAreDrawn) {
  hv::ImageRGBA8 img = hv::makeImageRGBA8(200, 40);
  hv::drawText(img, 5, 5, "E=0.5", 2, hv::Rgb8{255, 0, 0});
  const size_t red = countColor(img, hv::Rgb8{255, 0, 0});
  EXPECT_GT(red, 20u);
  EXPECT_EQ(hv::textWidth("E=0.5", 2), 2 * hv::textWidth("E=0.5", 1));

  hv::ScatterPlot p;
  p.title = "t";
  p.log_y = true;
  p.points = {{1.0, 0.5, "a", true, true}, {2.0, 0.1, "b", true, true}, {3.0, 0.4, "c"}};
  p.front = {0, 1};
  const hv::ImageRGBA8 plot = hv::drawScatterPlot(p, 400, 300);
  EXPECT_EQ(plot.width, 400);
  EXPECT_EQ(plot.height, 300);
  const size_t front = countColor(plot, hv::Rgb8{214, 96, 0});
  const size_t grey = countColor(plot, hv::Rgb8{110, 110, 110});
  EXPECT_GT(front, 2u * 60u);  // two large discs, the staircase, labels, legend
  EXPECT_GT(grey, 20u);        // the unmarked point
  p.front.clear();
  for (auto& pt : p.points) pt.marked = false;
  EXPECT_EQ(countColor(hv::drawScatterPlot(p, 400, 300), hv::Rgb8{214, 96, 0}), 0u);
}
