// The markdown of `halfvec bench --frame --report`: engine/eval measures (halfvec/eval/bench.hpp),
// the command formats.
#include "app/bench_report.hpp"

#include <algorithm>
#include <cstdio>
#include <sstream>

namespace hv::app {

std::string frameCostMarkdown(const std::vector<eval::FrameCost>& costs) {
  std::vector<std::string> passes;
  for (const eval::FrameCost& c : costs) {
    for (const eval::PassCost& p : c.passes) {
      if (std::find(passes.begin(), passes.end(), p.pass) == passes.end()) passes.push_back(p.pass);
    }
  }
  std::ostringstream o;
  o << "| scene | floor ms |";
  for (const std::string& p : passes) o << " " << p << " |";
  o << " frame |\n|---|---:|";
  for (size_t i = 0; i < passes.size(); ++i) o << "---:|";
  o << "---:|\n";
  // Milliseconds to 0.1 ms, or to 3 decimals under 1 ms (a hardware GPU's passes: its floor pass
  // at 1280x720 takes a few hundredths of a millisecond).
  auto ms = [](double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, v < 1.0 ? "%.3f" : "%.1f", v);
    return std::string(buf);
  };
  auto cell = [&](const eval::PassCost& p) {
    char buf[64];
    std::snprintf(buf, sizeof buf, " ms (%.2fx)", p.floor_ratio.median);
    return ms(p.ms) + buf;
  };
  for (const eval::FrameCost& c : costs) {
    o << "| " << c.scene << " | " << ms(c.floor_ms) << " |";
    for (const std::string& name : passes) {
      const auto it = std::find_if(c.passes.begin(), c.passes.end(),
                                   [&](const eval::PassCost& p) { return p.pass == name; });
      o << " " << (it == c.passes.end() ? std::string("-") : cell(*it)) << " |";
    }
    o << " " << cell(c.frame) << " |\n";
  }
  return o.str();
}

}  // namespace hv::app
