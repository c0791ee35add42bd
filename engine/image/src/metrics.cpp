#include "halfvec/image/metrics.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <string>

#include "halfvec/image/plot.hpp"  // text and rectangle primitives for the legend

namespace hv {
namespace {

bool finite3(glm::vec3 v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

void checkSameSize(const ImageRGBf& test, const ImageRGBf& ref, const char* what) {
  if (test.width != ref.width || test.height != ref.height ||
      test.px.size() != size_t(test.width) * size_t(test.height) ||
      ref.px.size() != size_t(ref.width) * size_t(ref.height))
    throw ImageError(std::string(what) + ": image sizes differ (test " +
                     std::to_string(test.width) + "x" + std::to_string(test.height) + ", ref " +
                     std::to_string(ref.width) + "x" + std::to_string(ref.height) + ")");
}
}  // namespace

double relativeError(glm::vec3 test, glm::vec3 ref) {
  if (!finite3(test) || !finite3(ref)) return std::numeric_limits<double>::quiet_NaN();
  double num = 0.0, den = 3.0 * kRelEpsilon;
  for (int c = 0; c < 3; ++c) {
    num += std::abs(double(test[c]) - double(ref[c]));
    den += std::abs(double(ref[c]));
  }
  return num / den;
}

ErrorMetrics compareImages(const ImageRGBf& test, const ImageRGBf& ref) {
  checkSameSize(test, ref, "compareImages");
  ErrorMetrics m;
  double sum_sq = 0.0, sum_abs = 0.0, sum_ref = 0.0;
  std::vector<double> rel, pixel_sq;
  rel.reserve(ref.px.size());
  pixel_sq.reserve(ref.px.size());
  for (size_t i = 0; i < ref.px.size(); ++i) {
    const bool ft = finite3(test.px[i]), fr = finite3(ref.px[i]);
    m.nonfinite_test += !ft;
    m.nonfinite_ref += !fr;
    if (!ft || !fr) continue;
    ++m.compared_pixels;
    double px_sq = 0.0;
    for (int c = 0; c < 3; ++c) {
      const double d = double(test.px[i][c]) - double(ref.px[i][c]);
      px_sq += d * d;
      sum_abs += std::abs(d);
      sum_ref += std::abs(double(ref.px[i][c]));
      m.max_abs = std::max(m.max_abs, std::abs(d));
    }
    sum_sq += px_sq;
    pixel_sq.push_back(px_sq);
    rel.push_back(relativeError(test.px[i], ref.px[i]));
  }
  const double n = double(m.compared_pixels) * 3.0;
  if (m.compared_pixels == 0) {
    m.psnr = std::numeric_limits<double>::infinity();
    return m;
  }
  const double mse = sum_sq / n;
  m.rmse = std::sqrt(mse);
  const double mean_ref = sum_ref / n;
  m.rel_rmse = m.rmse == 0.0  ? 0.0
               : mean_ref > 0 ? m.rmse / mean_ref
                              : std::numeric_limits<double>::infinity();
  m.mean_abs = sum_abs / n;
  m.psnr = mse == 0.0 ? std::numeric_limits<double>::infinity()
                      : 10.0 * std::log10(m.psnr_peak * m.psnr_peak / mse);
  double sum_rel = 0.0;
  for (double e : rel) sum_rel += e;
  m.mean_rel = sum_rel / double(rel.size());
  // The worst ceil(kTopFraction n) pixels by squared error: their sum over the whole sum.
  const size_t top =
      std::min(pixel_sq.size(), size_t(std::ceil(kTopFraction * double(pixel_sq.size()))));
  std::nth_element(pixel_sq.begin(), pixel_sq.begin() + long(top - 1), pixel_sq.end(),
                   std::greater<double>());
  double top_sq = 0.0;
  for (size_t i = 0; i < top; ++i) top_sq += pixel_sq[i];
  m.top_share = sum_sq > 0.0 ? top_sq / sum_sq : 0.0;
  const size_t k = size_t(std::ceil(0.99 * double(rel.size()))) - 1;  // nearest rank
  std::nth_element(rel.begin(), rel.begin() + long(k), rel.end());
  m.p99_rel = rel[k];
  return m;
}

std::vector<std::string> toleranceViolations(const ErrorMetrics& m, const Tolerances& t) {
  std::vector<std::string> out;
  auto check = [&](const char* name, double value, const std::optional<double>& limit) {
    // !(value <= limit): a NaN metric is a violation too.
    if (limit && !(value <= *limit)) {
      char line[128];
      std::snprintf(line, sizeof line, "%s %.6g > %.6g", name, value, *limit);
      out.push_back(line);
    }
  };
  check("rel_rmse", m.rel_rmse, t.max_rel_rmse);
  check("p99_rel", m.p99_rel, t.max_p99_rel);
  check("max_abs", m.max_abs, t.max_abs);
  if (t.any() && m.nonfinite_test > m.nonfinite_ref) {
    out.push_back(std::to_string(m.nonfinite_test) + " NaN/Inf pixels in the test image (" +
                  std::to_string(m.nonfinite_ref) + " in the reference)");
  }
  return out;
}

glm::vec3 viridis(float t) {
  // Matt Zucker's least-squares degree-6 fit to matplotlib's viridis (shadertoy WlfXRN, CC0).
  const glm::vec3 c0(0.2777273272234177f, 0.005407344544966578f, 0.3340998053353061f);
  const glm::vec3 c1(0.1050930431085774f, 1.404613529898575f, 1.384590162594685f);
  const glm::vec3 c2(-0.3308618287255563f, 0.214847559468213f, 0.09509516302823659f);
  const glm::vec3 c3(-4.634230498983486f, -5.799100973351585f, -19.33244095627987f);
  const glm::vec3 c4(6.228269936347081f, 14.17993336680509f, 56.69055260068105f);
  const glm::vec3 c5(4.776384997670288f, -13.74514537774601f, -65.35303263337234f);
  const glm::vec3 c6(-5.435455855934631f, 4.645852612178535f, 26.3124352495832f);
  t = std::clamp(t, 0.0f, 1.0f);
  return glm::clamp(c0 + t * (c1 + t * (c2 + t * (c3 + t * (c4 + t * (c5 + t * c6))))), 0.0f, 1.0f);
}

ImageRGBA8 relativeErrorHeatMap(const ImageRGBf& test, const ImageRGBf& ref, float max_rel) {
  checkSameSize(test, ref, "relativeErrorHeatMap");
  if (!(max_rel > 0.0f)) max_rel = std::max(float(compareImages(test, ref).p99_rel), 1e-6f);

  constexpr int kMargin = 8;      // legend padding
  constexpr int kBarHeight = 14;  // color bar
  constexpr int kTickHeight = 4;
  const int W = std::max(test.width, 240);
  const int x0 = kMargin + 12, x1 = W - kMargin - 24;  // color bar spans [x0, x1)
  char labels[5][32];
  int widest = 0;
  for (int i = 0; i <= 4; ++i) {
    std::snprintf(labels[i], sizeof(labels[i]), "%.3g", double(max_rel) * i / 4.0);
    widest = std::max(widest, textWidth(labels[i], 1));
  }
  // Text scale 2 where the labels fit between ticks (stb_easy_font glyphs are ~6x7 at 1).
  const int scale = (x1 - x0) / 4 >= 2 * widest + 10 ? 2 : 1;
  const int text_h = 7 * scale;
  const int legend_h = kMargin + kBarHeight + kTickHeight + 2 + text_h + kMargin;
  ImageRGBA8 out = makeImageRGBA8(W, test.height + legend_h);
  for (size_t i = 3; i < out.px.size(); i += 4) out.px[i] = 255;  // opaque black background

  auto toByte = [](float v) { return uint8_t(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)); };
  for (int y = 0; y < test.height; ++y)
    for (int x = 0; x < test.width; ++x) {
      const double e = relativeError(test.at(x, y), ref.at(x, y));
      uint8_t* p = out.at(x, y);
      if (std::isnan(e)) {
        p[0] = 255, p[1] = 0, p[2] = 255;  // magenta: a NaN/Inf pixel
        continue;
      }
      const glm::vec3 c = viridis(float(e / max_rel));
      p[0] = toByte(c.x), p[1] = toByte(c.y), p[2] = toByte(c.z);
    }

  // Legend: color bar, tick marks and labels at 0, 1/4, ..., 1 of max_rel.
  const int bar_y = test.height + kMargin;
  for (int x = x0; x < x1; ++x) {
    const glm::vec3 c = viridis(float(x - x0) / float(x1 - 1 - x0));
    fillRect(out, x, bar_y, x + 1, bar_y + kBarHeight, Rgb8{toByte(c.x), toByte(c.y), toByte(c.z)});
  }
  const Rgb8 white{255, 255, 255};
  for (int i = 0; i <= 4; ++i) {
    const int tx = x0 + (x1 - 1 - x0) * i / 4;
    fillRect(out, tx, bar_y + kBarHeight, tx + 1, bar_y + kBarHeight + kTickHeight, white);
    const int w = textWidth(labels[i], scale);
    const int lx = std::clamp(tx - w / 2, 0, W - w);
    drawText(out, lx, bar_y + kBarHeight + kTickHeight + 2, labels[i], scale, white);
  }
  return out;
}

}  // namespace hv
