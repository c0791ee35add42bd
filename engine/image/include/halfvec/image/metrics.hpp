// Error metrics between a test image and a reference, and a relative-error heat map.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "halfvec/image/image.hpp"

namespace hv {

// Definitions (all over the pixels where both images are finite in all three channels; a pixel
// with any NaN/Inf channel is counted in nonfinite_* and left out of everything else):
//   d_c = test_c - ref_c for each channel c of each compared pixel.
//   rmse      = sqrt(mean over pixels and channels of d_c^2)
//   rel_rmse  = rmse / mean over pixels and channels of |ref_c|  (normalized RMSE; 0/0 -> 0,
//               x/0 -> +inf)
//   mean_abs  = mean over pixels and channels of |d_c|;  max_abs = max of |d_c|
//   per-pixel relative error e = (sum_c |d_c|) / (sum_c |ref_c| + 3 * kRelEpsilon), i.e. the
//               mean channel error over the mean reference channel value plus kRelEpsilon, so
//               black reference pixels do not blow up (relativeError() below);
//   mean_rel  = mean over pixels of e: the error as the image shows it, each pixel counting
//               once whatever its brightness (the trade report's headline);
//   p99_rel   = 99th percentile of e by nearest rank (the ceil(0.99 n)-th smallest);
//   top_share = the share of sum d_c^2 (what rmse and rel_rmse are made of) carried by the
//               ceil(kTopFraction n) pixels of largest sum_c d_c^2: near 1 when a few pixels
//               (a glint, a firefly) make the RMSE, about kTopFraction when the error is spread
//               evenly (0 when there is no error);
//   psnr      = 10 log10(psnr_peak^2 / mse) in dB, psnr_peak = 1.0 (display-referred range;
//               +inf when mse = 0).
inline constexpr double kRelEpsilon = 1e-2;
inline constexpr double kPsnrPeak = 1.0;
inline constexpr double kTopFraction = 1e-3;  // the worst 0.1% of pixels (top_share)

struct ErrorMetrics {
  double rmse = 0.0;
  double rel_rmse = 0.0;
  double mean_abs = 0.0;
  double max_abs = 0.0;
  double mean_rel = 0.0;
  double p99_rel = 0.0;
  double top_share = 0.0;
  double psnr = 0.0;
  double psnr_peak = kPsnrPeak;
  int64_t compared_pixels = 0;
  int64_t nonfinite_test = 0;  // pixels of `test` with a NaN or Inf channel
  int64_t nonfinite_ref = 0;   // pixels of `ref` with a NaN or Inf channel
};

// Throws ImageError when the sizes differ.
ErrorMetrics compareImages(const ImageRGBf& test, const ImageRGBf& ref);

// Regression-test tolerances (`halfvec compare --max-rel-rmse/--max-p99/--max-abs`, Filament
// renderdiff's habit): each given one must hold. A test image with more NaN/Inf pixels than the
// reference is outside any tolerance.
struct Tolerances {
  std::optional<double> max_rel_rmse, max_p99_rel, max_abs;
  bool any() const { return max_rel_rmse || max_p99_rel || max_abs; }
};

// One line per tolerance that `m` exceeds ("rel_rmse 0.031 > 0.02"); empty when within all.
std::vector<std::string> toleranceViolations(const ErrorMetrics& m, const Tolerances& t);

// The per-pixel relative error e defined above (NaN if either pixel is not finite).
double relativeError(glm::vec3 test, glm::vec3 ref);

// Viridis colormap (polynomial fit of the matplotlib table by Matt Zucker, degree 6; max error
// about 0.01 per channel). t is clamped to [0, 1].
glm::vec3 viridis(float t);

// Heat map of relativeError(test, ref) over [0, max_rel] (max_rel <= 0: the p99 of e, at least
// 1e-6), viridis-coded, NaN/Inf pixels in magenta, with a legend strip under the image: a color
// bar and tick labels at 0, 1/4, ..., 1 of the range. Output width = max(image width, 240).
ImageRGBA8 relativeErrorHeatMap(const ImageRGBf& test, const ImageRGBf& ref, float max_rel = 0.0f);

}  // namespace hv
