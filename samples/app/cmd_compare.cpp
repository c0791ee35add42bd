// `halfvec compare A.pfm B.pfm`: error metrics of A against reference B.
#include <cstdio>
#include <fstream>

#include <nlohmann/json.hpp>

#include "app/commands.hpp"
#include "halfvec/image/image.hpp"
#include "halfvec/image/metrics.hpp"

namespace hv::app {

namespace {
constexpr const char* kCompareHelp = R"(Usage: halfvec compare TEST.pfm REFERENCE.pfm [options]

Error of TEST against REFERENCE: RMSE, relative RMSE, mean and max absolute error,
99th-percentile relative error, PSNR, and NaN/Inf pixel counts of each image.

Options:
  --heatmap FILE.png    color-mapped relative error with a legend
  --json FILE.json      the metrics as JSON
)";
}  // namespace

int cmdCompare(const Args& args) {
  std::string a, b, heat, json;
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& s = args[i];
    auto value = [&] { return optionValue(args, i); };
    if (s == "--help" || s == "-h") {
      std::fputs(kCompareHelp, stdout);
      return 0;
    } else if (s == "--heatmap") {
      heat = value();
    } else if (s == "--json") {
      json = value();
    } else if (!s.empty() && s[0] == '-') {
      throw UsageError{"unknown option '" + s + "'"};
    } else if (a.empty()) {
      a = s;
    } else if (b.empty()) {
      b = s;
    } else {
      throw UsageError{"expected exactly two images"};
    }
  }
  if (b.empty()) throw UsageError{"expected two images"};
  const ImageRGBf test = readPfm(a);
  const ImageRGBf ref = readPfm(b);
  const ErrorMetrics m = compareImages(test, ref);
  nlohmann::ordered_json j = {{"test", a},
                              {"reference", b},
                              {"rmse", m.rmse},
                              {"rel_rmse", m.rel_rmse},
                              {"mean_abs", m.mean_abs},
                              {"max_abs", m.max_abs},
                              {"p99_rel", m.p99_rel},
                              {"psnr_db", m.psnr},
                              {"psnr_peak", m.psnr_peak},
                              {"pixels", m.compared_pixels},
                              {"nan_inf_pixels_test", m.nonfinite_test},
                              {"nan_inf_pixels_reference", m.nonfinite_ref}};
  std::printf("%s\n", j.dump(2).c_str());
  if (!json.empty()) std::ofstream(json) << j.dump(2) << "\n";
  if (!heat.empty()) writePng(heat, relativeErrorHeatMap(test, ref));
  return 0;
}

}  // namespace hv::app
