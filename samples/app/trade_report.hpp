// The trade report's formats: `halfvec trade` (cmd_trade.cpp) writes them from the data that
// engine/eval's runTrade returns (halfvec/eval/trade.hpp).
#pragma once

#include <string>

#include "halfvec/eval/trade.hpp"
#include "halfvec/image/image.hpp"

namespace hv::app {

std::string tradeCsv(const eval::TradeReport& report);
// The report as markdown; images are linked as image_prefix + "plot.png" etc.;
// heading_level: '#' count of its title.
std::string tradeMarkdown(const eval::TradeReport& report, const std::string& image_prefix,
                          int heading_level = 1);
ImageRGBA8 tradePlot(const eval::TradeReport& report);
// Why the presets (engine/scene/src/presets.cpp) set what they set: markdown, for docs/trade.md.
std::string presetRationale();

// Writes trade.md, trade.csv and plot.png into `dir` (created if needed).
void writeTradeReport(const eval::TradeReport& report, const std::string& dir);

}  // namespace hv::app
