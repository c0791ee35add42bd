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
  auto cell = [](const eval::PassCost& p) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.1f ms (%.2fx)", p.ms, p.floor_ratio.median);
    return std::string(buf);
  };
  for (const eval::FrameCost& c : costs) {
    char floor[32];
    std::snprintf(floor, sizeof floor, "%.1f", c.floor_ms);
    o << "| " << c.scene << " | " << floor << " |";
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
