// The markdown of `halfvec bench --frame --report` (samples/app/bench_report.hpp) on costs made
// here: the union of the scenes' passes in order of first appearance, "-" where a scene lacks one,
// each cell as "ms (x floor)".
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "app/bench_report.hpp"

namespace {

hv::eval::PassCost pass(const std::string& name, double ms, double ratio) {
  hv::eval::PassCost p;
  p.pass = name;
  p.ms = ms;
  p.floor_ratio.median = ratio;
  return p;
}

std::vector<std::string> lines(const std::string& s) {
  std::vector<std::string> out;
  std::istringstream in(s);
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

}  // namespace

TEST(BenchReport, FrameCostTableHasEveryPassOfEveryScene) {
  hv::eval::FrameCost a;
  a.scene = "tiny";
  a.floor_ms = 7.3;
  a.passes = {pass("gbuffer", 14.5, 2.0), pass("light", 21.7, 3.0)};
  a.frame = pass("frame", 36.2, 5.0);
  hv::eval::FrameCost b;
  b.scene = "brute";
  b.floor_ms = 8.0;
  b.passes = {pass("gbuffer", 8.0, 1.0), pass("light_cull", 4.0, 0.5), pass("light", 16.0, 2.0)};
  b.frame = pass("frame", 28.0, 3.5);
  const std::vector<std::string> l = lines(hv::app::frameCostMarkdown({a, b}));
  ASSERT_EQ(l.size(), 4u);
  EXPECT_EQ(l[0], "| scene | floor ms | gbuffer | light | light_cull | frame |");
  EXPECT_EQ(l[1], "|---|---:|---:|---:|---:|---:|");
  EXPECT_EQ(l[2], "| tiny | 7.3 | 14.5 ms (2.00x) | 21.7 ms (3.00x) | - | 36.2 ms (5.00x) |");
  EXPECT_EQ(
      l[3],
      "| brute | 8.0 | 8.0 ms (1.00x) | 16.0 ms (2.00x) | 4.0 ms (0.50x) | 28.0 ms (3.50x) |");
}

TEST(BenchReport, FrameCostTableOfNoScenesIsItsHeader) {
  EXPECT_EQ(hv::app::frameCostMarkdown({}), "| scene | floor ms | frame |\n|---|---:|---:|\n");
}
