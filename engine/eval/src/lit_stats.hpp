// Private to engine/eval (src/): engine against reference over a set of pixels, shared by the
// accuracy measurements (accuracy_report.cpp, clear_coat_accuracy.cpp).
#pragma once

#include <cstddef>
#include <functional>

#include "halfvec/eval/accuracy_report.hpp"
#include "halfvec/image/image.hpp"
#include "halfvec/image/metrics.hpp"

namespace hv::eval {

// The pixels (indices) a statistic is taken over.
using PixelMask = std::function<bool(size_t)>;

// Images restricted to the pixels where `use` holds, packed into one row (for compareImages).
ErrorMetrics compareMasked(const ImageRGBf& e, const ImageRGBf& r, const PixelMask& use);
// LitStats of engine image e against reference r (its per-pixel standard error se).
LitStats litStats(const ImageRGBf& e, const ImageRGBf& r, const ImageRGBf& se,
                  const PixelMask& use);

}  // namespace hv::eval
