// The trade report's formats (samples/app/trade_report.hpp) on a report made here: CSV with a
// line per row, markdown naming every row and its picks, the plot, and the three files written
// together.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "app/trade_report.hpp"
#include "halfvec/image/image.hpp"

namespace fs = std::filesystem;
using hv::eval::TradeReport;
using hv::eval::TradeRow;

namespace {

TradeReport sampleReport() {
  TradeReport r;
  r.scene_path = "/somewhere/default.json";
  r.width = 32, r.height = 18, r.frames = 2, r.rounds = 1, r.samples = 16;
  const char* names[] = {"scene", "brdf.v=smith_ggx_correlated", "preset=accurate", "exact"};
  const double ms[] = {10.0, 11.0, 20.0, 22.0};
  const double err[] = {0.30, 0.25, 0.05, 0.04};
  for (int i = 0; i < 4; ++i) {
    TradeRow row;
    row.config.name = names[i];
    row.config.group = i == 1 ? "brdf" : "scene";
    if (i == 2) row.config.aliases = {"preset=balanced, with \"quotes\""};
    row.pass_ms = {{"gbuffer", 2.0}, {"light", ms[i] - 2.0}};
    row.total_ms = ms[i];
    row.cost_ratio = ms[i] / ms[0];
    row.error.mean_rel = err[i];
    row.error.rel_rmse = 3.0 * err[i];
    r.rows.push_back(row);
  }
  r.skipped = {"tube_specular: no tube lights"};
  r.max_error = 0.05;
  r.max_ms = 12.0;
  r.exact_row = 3;
  hv::eval::markPareto(r.rows);
  hv::eval::pickConfigurations(r);
  return r;
}

TEST(TradeReport, CsvHasALinePerRowAndQuotesFields) {
  const TradeReport r = sampleReport();
  const std::string csv = hv::app::tradeCsv(r);
  size_t lines = 0;
  for (char c : csv) lines += c == '\n';
  EXPECT_EQ(lines, r.rows.size() + 1);
  EXPECT_EQ(csv.rfind("scene,configuration,aliases,group", 0), 0u) << csv;
  EXPECT_NE(csv.find("gbuffer_ms"), std::string::npos);
  EXPECT_NE(csv.find(",total_ms,mean_rel,p99_rel,top_share,rel_rmse,"), std::string::npos) << csv;
  EXPECT_NE(csv.find("\"preset=balanced, with \"\"quotes\"\"\""), std::string::npos) << csv;
}

TEST(TradeReport, MarkdownNamesEveryRowAndThePicks) {
  const TradeReport r = sampleReport();
  ASSERT_EQ(r.cheapest_within_error, 2);
  const std::string md = hv::app::tradeMarkdown(r, "img/", 2);
  EXPECT_EQ(md.rfind("## ", 0), 0u) << md.substr(0, 80);
  for (const auto& row : r.rows) EXPECT_NE(md.find("`" + row.config.name), std::string::npos);
  EXPECT_NE(md.find("img/plot.png"), std::string::npos);
  // The headline column comes first; the pick is by it (row 2's rel. RMSE, 0.15, is above 0.05).
  EXPECT_NE(md.find("| mean rel. | p99 rel. | worst 0.1% | rel. RMSE |"), std::string::npos);
  EXPECT_NE(md.find("Cheapest within mean rel. error <= 0.05: `preset=accurate"), std::string::npos)
      << md;
  EXPECT_NE(md.find("tube_specular: no tube lights"), std::string::npos);
  EXPECT_FALSE(hv::app::presetRationale().empty());
}

TEST(TradeReport, WritesTheThreeFiles) {
  const TradeReport r = sampleReport();
  const fs::path dir =
      fs::temp_directory_path() / ("hv_trade_report_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  hv::app::writeTradeReport(r, dir.string());
  EXPECT_TRUE(fs::exists(dir / "trade.md"));
  EXPECT_TRUE(fs::exists(dir / "trade.csv"));
  const hv::ImageRGBA8 plot = hv::readPng((dir / "plot.png").string());
  EXPECT_EQ(plot.width, 960);
  fs::remove_all(dir);
}

}  // namespace
