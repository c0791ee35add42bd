#include "halfvec/image/plot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wsign-compare"
#include <stb/stb_easy_font.h>  // header-only, static functions: no implementation macro
#pragma GCC diagnostic pop

namespace hv {

namespace {
constexpr Rgb8 kBlack{0, 0, 0};
constexpr Rgb8 kGrid{225, 225, 225};
constexpr Rgb8 kPoint{110, 110, 110};
constexpr Rgb8 kFront{214, 96, 0};

struct Box {
  int x0, y0, x1, y1;
  bool overlaps(const Box& o) const { return x0 < o.x1 && o.x0 < x1 && y0 < o.y1 && o.y0 < y1; }
};

std::string tickLabel(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}
}  // namespace

void fillRect(ImageRGBA8& img, int x0, int y0, int x1, int y1, Rgb8 c) {
  x0 = std::max(x0, 0), y0 = std::max(y0, 0);
  x1 = std::min(x1, img.width), y1 = std::min(y1, img.height);
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) {
      uint8_t* p = img.at(x, y);
      p[0] = c.r, p[1] = c.g, p[2] = c.b, p[3] = 255;
    }
}

void drawLine(ImageRGBA8& img, int x0, int y0, int x1, int y1, Rgb8 c) {
  const int dx = std::abs(x1 - x0), dy = -std::abs(y1 - y0);
  const int sx = x0 < x1 ? 1 : -1, sy = y0 < y1 ? 1 : -1;
  int err = dx + dy;
  for (;;) {
    fillRect(img, x0, y0, x0 + 1, y0 + 1, c);
    if (x0 == x1 && y0 == y1) break;
    const int e2 = 2 * err;
    if (e2 >= dy) err += dy, x0 += sx;
    if (e2 <= dx) err += dx, y0 += sy;
  }
}

void fillDisc(ImageRGBA8& img, int cx, int cy, int r, Rgb8 c) {
  for (int y = -r; y <= r; ++y)
    for (int x = -r; x <= r; ++x)
      if (x * x + y * y <= r * r + r) fillRect(img, cx + x, cy + y, cx + x + 1, cy + y + 1, c);
}

// stb_easy_font emits axis-aligned quads (4 vertices of x, y, z floats + 4 color bytes); each
// quad's bounding box is filled, scaled by an integer factor.
void drawText(ImageRGBA8& img, int x, int y, const std::string& text, int scale, Rgb8 c) {
  static thread_local char buf[64 * 1024];
  std::string t = text;
  unsigned char color[4] = {255, 255, 255, 255};
  const int quads = stb_easy_font_print(0.0f, 0.0f, t.data(), color, buf, sizeof(buf));
  for (int q = 0; q < quads; ++q) {
    float lo[2] = {1e9f, 1e9f}, hi[2] = {-1e9f, -1e9f};
    for (int v = 0; v < 4; ++v) {
      const float* f = reinterpret_cast<const float*>(buf + (q * 4 + v) * 16);
      for (int k = 0; k < 2; ++k) lo[k] = std::min(lo[k], f[k]), hi[k] = std::max(hi[k], f[k]);
    }
    fillRect(img, x + int(lo[0] * float(scale)), y + int(lo[1] * float(scale)),
             x + int(hi[0] * float(scale)), y + int(hi[1] * float(scale)), c);
  }
}

int textWidth(const std::string& text, int scale) {
  std::string t = text;
  return stb_easy_font_width(t.data()) * scale;
}

std::vector<double> linearTicks(double lo, double hi, int target) {
  std::vector<double> ticks;
  if (!(hi > lo) || !std::isfinite(lo) || !std::isfinite(hi)) return ticks;
  const double raw = (hi - lo) / std::max(target, 1);
  const double mag = std::pow(10.0, std::floor(std::log10(raw)));
  double step = mag;
  for (double m : {1.0, 2.0, 5.0, 10.0}) {
    step = m * mag;
    if (step >= raw) break;
  }
  for (double t = std::ceil(lo / step) * step; t <= hi + step * 1e-9; t += step) {
    ticks.push_back(std::abs(t) < step * 1e-9 ? 0.0 : t);
  }
  return ticks;
}

std::vector<double> logTicks(double lo, double hi) {
  std::vector<double> ticks;
  if (!(lo > 0.0) || !(hi > lo)) return ticks;
  const int k0 = int(std::floor(std::log10(lo))), k1 = int(std::ceil(std::log10(hi)));
  // At most three decades: 1-2-5 within each decade, else the powers of ten only.
  const bool fine = k1 - k0 <= 3;
  for (int k = k0; k <= k1; ++k) {
    for (double m : {1.0, 2.0, 5.0}) {
      if (!fine && m != 1.0) continue;
      const double t = m * std::pow(10.0, k);
      if (t >= lo * (1 - 1e-9) && t <= hi * (1 + 1e-9)) ticks.push_back(t);
    }
  }
  return ticks;
}

namespace {

bool plottable(const ScatterPlot& plot, const PlotPoint& p) {
  return std::isfinite(p.x) && std::isfinite(p.y) && (!plot.log_y || p.y > 0.0);
}

// The plot area in pixels and the data range it shows, with the mapping between them.
struct PlotFrame {
  int left = 0, right = 0, top = 0, bottom = 0;
  double x_lo = 0.0, x_hi = 1.0, y_lo = 0.0, y_hi = 1.0;
  bool log_y = false;
  int px(double x) const {
    return left + int(std::lround((x - x_lo) / (x_hi - x_lo) * (right - left)));
  }
  int py(double y) const {
    const double t = log_y ? (std::log10(std::max(y, y_lo)) - std::log10(y_lo)) /
                                 (std::log10(y_hi) - std::log10(y_lo))
                           : (y - y_lo) / (y_hi - y_lo);
    return bottom - int(std::lround(t * (bottom - top)));
  }
};

PlotFrame plotFrame(const ScatterPlot& plot, int width, int height) {
  PlotFrame f{.left = 90, .right = width - 24, .top = 56, .bottom = height - 64};
  f.log_y = plot.log_y;
  double x_lo = std::numeric_limits<double>::infinity(), x_hi = -x_lo, y_lo = x_lo, y_hi = -x_lo;
  for (const PlotPoint& p : plot.points) {
    if (!plottable(plot, p)) continue;
    x_lo = std::min(x_lo, p.x), x_hi = std::max(x_hi, p.x);
    y_lo = std::min(y_lo, p.y), y_hi = std::max(y_hi, p.y);
  }
  if (!std::isfinite(x_lo)) x_lo = 0.0, x_hi = 1.0, y_lo = plot.log_y ? 0.1 : 0.0, y_hi = 1.0;
  // Margins: 8% of the x range on both sides; y: a fraction of a decade or 8% of the range.
  const double dx = std::max(x_hi - x_lo, std::max(std::abs(x_hi), 1e-6) * 0.1);
  x_lo -= 0.08 * dx, x_hi += 0.08 * dx;
  if (plot.log_y) {
    y_lo /= 1.6, y_hi *= 1.6;
  } else {
    const double dy = std::max(y_hi - y_lo, std::max(std::abs(y_hi), 1e-6) * 0.1);
    y_lo -= 0.08 * dy, y_hi += 0.08 * dy;
  }
  f.x_lo = x_lo, f.x_hi = x_hi, f.y_lo = y_lo, f.y_hi = y_hi;
  return f;
}

// Grid, ticks, tick labels, axes, title, axis labels and the legend.
void drawAxes(ImageRGBA8& img, const PlotFrame& f, const ScatterPlot& plot) {
  for (double t : linearTicks(f.x_lo, f.x_hi)) {
    const int x = f.px(t);
    drawLine(img, x, f.top, x, f.bottom, kGrid);
    drawLine(img, x, f.bottom, x, f.bottom + 5, kBlack);
    const std::string s = tickLabel(t);
    drawText(img, x - textWidth(s, 2) / 2, f.bottom + 9, s, 2, kBlack);
  }
  for (double t : plot.log_y ? logTicks(f.y_lo, f.y_hi) : linearTicks(f.y_lo, f.y_hi)) {
    const int y = f.py(t);
    drawLine(img, f.left, y, f.right, y, kGrid);
    drawLine(img, f.left - 5, y, f.left, y, kBlack);
    const std::string s = tickLabel(t);
    drawText(img, f.left - 9 - textWidth(s, 2), y - kTextHeight, s, 2, kBlack);
  }
  drawLine(img, f.left, f.top, f.left, f.bottom, kBlack);
  drawLine(img, f.left, f.bottom, f.right, f.bottom, kBlack);
  drawText(img, f.left, 12, plot.title, 2, kBlack);
  if (!plot.front.empty()) {
    const std::string legend = "front (no row faster and more accurate)";
    const int lx = f.right - textWidth(legend, 2);
    fillDisc(img, lx - 12, f.top - 15, 5, kFront);
    drawText(img, lx, f.top - 22, legend, 2, kFront);
  }
  drawText(img, f.left, f.top - 22, plot.y_label, 2, kBlack);
  drawText(img, (f.left + f.right - textWidth(plot.x_label, 2)) / 2, img.height - 26, plot.x_label,
           2, kBlack);
}

// Labels: the first of a few positions around the point that overlaps no label or point.
void drawPointLabels(ImageRGBA8& img, const PlotFrame& f, const ScatterPlot& plot,
                     std::vector<Box>& taken) {
  for (const PlotPoint& p : plot.points) {
    if (!plottable(plot, p) || !p.labeled || p.label.empty()) continue;
    const int w = textWidth(p.label, 2), h = 2 * kTextHeight, x = f.px(p.x), y = f.py(p.y);
    const int cand[][2] = {{8, -h - 2},      {8, 4},         {-8 - w, -h - 2},     {-8 - w, 4},
                           {8, -2 * h - 6},  {8, h + 8},     {-8 - w, -2 * h - 6}, {-8 - w, h + 8},
                           {8, -3 * h - 10}, {8, 2 * h + 12}};
    Box best{x + cand[0][0], y + cand[0][1], x + cand[0][0] + w, y + cand[0][1] + h};
    for (const auto& c : cand) {
      Box b{x + c[0], y + c[1], x + c[0] + w, y + c[1] + h};
      if (b.x0 < 0 || b.x1 > img.width || b.y0 < f.top - 4 || b.y1 > f.bottom) continue;
      if (std::none_of(taken.begin(), taken.end(), [&](const Box& o) { return b.overlaps(o); })) {
        best = b;
        break;
      }
    }
    best.x0 = std::clamp(best.x0, 0, std::max(img.width - w, 0));
    drawText(img, best.x0, best.y0, p.label, 2, p.marked ? kFront : kBlack);
    taken.push_back(best);
  }
}

}  // namespace

ImageRGBA8 drawScatterPlot(const ScatterPlot& plot, int width, int height) {
  width = std::max(width, 320), height = std::max(height, 240);
  ImageRGBA8 img = makeImageRGBA8(width, height);
  fillRect(img, 0, 0, width, height, Rgb8{255, 255, 255});
  const PlotFrame f = plotFrame(plot, width, height);
  drawAxes(img, f, plot);
  // The front as a staircase (each point dominates the region to its upper right).
  for (size_t i = 1; i < plot.front.size(); ++i) {
    const PlotPoint& a = plot.points[plot.front[i - 1]];
    const PlotPoint& b = plot.points[plot.front[i]];
    if (!plottable(plot, a) || !plottable(plot, b)) continue;
    drawLine(img, f.px(a.x), f.py(a.y), f.px(b.x), f.py(a.y), kFront);
    drawLine(img, f.px(b.x), f.py(a.y), f.px(b.x), f.py(b.y), kFront);
  }
  std::vector<Box> taken;
  for (const PlotPoint& p : plot.points) {
    if (!plottable(plot, p)) continue;
    const int r = p.marked ? 5 : 3;
    fillDisc(img, f.px(p.x), f.py(p.y), r, p.marked ? kFront : kPoint);
    taken.push_back({f.px(p.x) - r, f.py(p.y) - r, f.px(p.x) + r + 1, f.py(p.y) + r + 1});
  }
  drawPointLabels(img, f, plot, taken);
  return img;
}

}  // namespace hv
