// `halfvec compare TEST REF`: error metrics of an image against a reference, and a pass/fail exit
// status for regression tests (docs/testing.md).
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>

#include <nlohmann/json.hpp>

#include "app/commands.hpp"
#include "halfvec/core/output_files.hpp"
#include "halfvec/image/image.hpp"
#include "halfvec/image/metrics.hpp"

namespace hv::app {

namespace {
constexpr const char* kCompareHelp = R"(Usage: halfvec compare TEST REFERENCE [options]

Error of TEST against REFERENCE, two PFM images (linear HDR) or two PNG images (8-bit values as
stored, divided by 255): RMSE, relative RMSE, mean and max absolute error, 99th-percentile
per-pixel relative error, PSNR, and NaN/Inf pixel counts of each image (docs/testing.md gives
the definitions). Printed as JSON.

Tolerances (any subset; each given one must hold, and TEST must not have more NaN/Inf pixels
than REFERENCE):
  --max-rel-rmse X      relative RMSE (RMSE / mean reference value) at most X
  --max-p99 X           99th percentile of the per-pixel relative error at most X
  --max-abs X           largest absolute channel difference at most X

Outputs (written whole or not at all):
  --heatmap FILE.png    color-mapped per-pixel relative error with a legend
  --heatmap-max X       the relative error at the top of its scale (default: the 99th
                        percentile; set it to compare several heat maps)
  --json FILE.json      the metrics and the verdict as JSON

Exit status: 0 within the tolerances (or none given), 1 outside them, 2 bad input (missing or
unreadable file, images of different sizes or formats, bad option) or an output that cannot be
written.
)";

struct CompareArgs {
  std::string test, ref, heatmap, json;
  Tolerances tol;
  float heatmap_max = 0.0f;  // 0: the p99
};

double parseTolerance(const std::string& option, const std::string& v) {
  return numberInRange(option, v, 0.0, HUGE_VAL);
}

CompareArgs parse(const Args& args) {
  CompareArgs r;
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& s = args[i];
    auto value = [&] { return optionValue(args, i); };
    if (s == "--heatmap") {
      r.heatmap = value();
    } else if (s == "--heatmap-max") {
      r.heatmap_max = floatInRange(s, value(), 0.0f, FLT_MAX);  // 1e300 would become inf
    } else if (s == "--json") {
      r.json = value();
    } else if (s == "--max-rel-rmse") {
      r.tol.max_rel_rmse = parseTolerance(s, value());
    } else if (s == "--max-p99") {
      r.tol.max_p99_rel = parseTolerance(s, value());
    } else if (s == "--max-abs") {
      r.tol.max_abs = parseTolerance(s, value());
    } else if (!s.empty() && s[0] == '-') {
      throw UsageError{"unknown option '" + s + "'"};
    } else if (r.test.empty()) {
      r.test = s;
    } else if (r.ref.empty()) {
      r.ref = s;
    } else {
      throw UsageError{"expected exactly two images"};
    }
  }
  if (r.ref.empty()) throw UsageError{"expected two images, TEST and REFERENCE"};
  return r;
}

bool isPng(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  return ext == ".png";
}

// A PNG as its stored 8-bit values / 255 (display-referred, alpha ignored), or a PFM as is.
ImageRGBf readImage(const std::string& path) {
  if (!isPng(path)) return readPfm(path);
  const ImageRGBA8 png = readPng(path);
  ImageRGBf img = makeImageRGBf(png.width, png.height);
  for (size_t i = 0; i < img.px.size(); ++i) {
    img.px[i] = glm::vec3(png.px[4 * i], png.px[4 * i + 1], png.px[4 * i + 2]) / 255.0f;
  }
  return img;
}

nlohmann::ordered_json report(const CompareArgs& a, const ErrorMetrics& m,
                              const std::vector<std::string>& violations) {
  nlohmann::ordered_json j = {{"test", a.test},
                              {"reference", a.ref},
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
  nlohmann::ordered_json tol = nlohmann::ordered_json::object();
  if (a.tol.max_rel_rmse) tol["max_rel_rmse"] = *a.tol.max_rel_rmse;
  if (a.tol.max_p99_rel) tol["max_p99"] = *a.tol.max_p99_rel;
  if (a.tol.max_abs) tol["max_abs"] = *a.tol.max_abs;
  j["tolerances"] = tol;
  j["pass"] = violations.empty();
  j["violations"] = violations;
  return j;
}

}  // namespace

int cmdCompare(const Args& args) {
  for (const auto& a : args) {
    if (a == "--help" || a == "-h") {
      std::fputs(kCompareHelp, stdout);
      return 0;
    }
  }
  const CompareArgs a = parse(args);
  try {
    if (isPng(a.test) != isPng(a.ref)) {
      throw ImageError("cannot compare a PNG (display values) with a PFM (linear radiance): '" +
                       a.test + "' and '" + a.ref + "'");
    }
    OutputFiles outputs;           // reserved first: an unwritable output fails before the work
    outputs.protectInput(a.test);  // --heatmap a.png over an input: refused
    outputs.protectInput(a.ref);
    const auto heat_tmp = a.heatmap.empty() ? std::filesystem::path() : outputs.add(a.heatmap);
    const auto json_tmp = a.json.empty() ? std::filesystem::path() : outputs.add(a.json);
    const ImageRGBf test = readImage(a.test);
    const ImageRGBf ref = readImage(a.ref);
    const ErrorMetrics m = compareImages(test, ref);
    const std::vector<std::string> violations = toleranceViolations(m, a.tol);
    const nlohmann::ordered_json j = report(a, m, violations);
    if (!heat_tmp.empty())
      writePng(heat_tmp.string(), relativeErrorHeatMap(test, ref, a.heatmap_max));
    if (!json_tmp.empty()) {
      std::ofstream out(json_tmp);
      out << j.dump(2) << "\n";
      if (!out) throw OutputError("cannot write " + a.json);
    }
    outputs.commit();
    std::printf("%s\n", j.dump(2).c_str());
    if (!violations.empty()) {
      for (const std::string& v : violations) std::fprintf(stderr, "compare: FAIL %s\n", v.c_str());
      return 1;
    }
    if (a.tol.any()) std::fprintf(stderr, "compare: within the tolerances\n");
    return 0;
  } catch (const std::exception& e) {  // ImageError, OutputError: bad input or output
    std::fprintf(stderr, "halfvec compare: error: %s\n", e.what());
    return 2;
  }
}

}  // namespace hv::app
