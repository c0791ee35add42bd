// A small PNG-ready scatter plot (axes, tick labels, a marked and labeled front) drawn into an
// ImageRGBA8 with stb_easy_font's bitmap glyphs: enough for `halfvec trade`'s error-vs-time plot
// without a plotting dependency.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "halfvec/image/image.hpp"

namespace hv {

struct Rgb8 {
  uint8_t r = 0, g = 0, b = 0;
};

struct PlotPoint {
  double x = 0.0, y = 0.0;
  std::string label;     // drawn next to the point when `labeled`
  bool marked = false;   // drawn large, in the front color
  bool labeled = false;  // label drawn
};

struct ScatterPlot {
  std::string title, x_label, y_label;
  bool log_y = false;  // decade ticks; points with y <= 0 are drawn at the bottom edge
  std::vector<PlotPoint> points;
  // Indices into `points` joined by a staircase line in this order (a Pareto front sorted by x).
  std::vector<size_t> front;
};

// Draws the plot at width x height (at least 320 x 240). Axis ranges cover all finite points
// with a margin; ticks at 1-2-5 steps (linear) or powers of ten (log). Points with a non-finite
// coordinate are skipped.
ImageRGBA8 drawScatterPlot(const ScatterPlot& plot, int width = 960, int height = 640);

// Text in stb_easy_font's glyphs (about 6 x 7 pixels per character at scale 1, baseline at the
// bottom of the box), clipped to the image.
void drawText(ImageRGBA8& img, int x, int y, const std::string& text, int scale, Rgb8 color);
int textWidth(const std::string& text, int scale);
constexpr int kTextHeight = 7;  // glyph box height at scale 1

// Plot primitives, clipped to the image.
void fillRect(ImageRGBA8& img, int x0, int y0, int x1, int y1, Rgb8 color);  // [x0,x1) x [y0,y1)
void drawLine(ImageRGBA8& img, int x0, int y0, int x1, int y1, Rgb8 color);  // Bresenham
void fillDisc(ImageRGBA8& img, int cx, int cy, int radius, Rgb8 color);

// Tick positions: multiples of a 1-2-5 step covering [lo, hi] (about `target` ticks), or the
// powers of ten within [lo, hi] for a log axis (lo > 0).
std::vector<double> linearTicks(double lo, double hi, int target = 6);
std::vector<double> logTicks(double lo, double hi);

}  // namespace hv
