// The report formats of `halfvec bench` (bench_frame.cpp writes them) from the data that
// engine/eval's measurements return (halfvec/eval/bench.hpp).
#pragma once

#include <string>
#include <vector>

#include "halfvec/eval/bench.hpp"

namespace hv::app {

// Markdown table: one row per scene, per pass "ms (x floor)" ("-" where the scene has no such
// pass), then the whole frame.
std::string frameCostMarkdown(const std::vector<eval::FrameCost>& costs);

}  // namespace hv::app
