// The trade report's first stage (trade.cpp runs the others): the reference of the exact
// configuration, read from the cache when its inputs match, else rendered and cached.
#pragma once

#include <functional>
#include <string>
#include <utility>

#include "halfvec/eval/trade.hpp"
#include "halfvec/image/image.hpp"
#include "halfvec/reference/reference.hpp"

namespace hv::eval::trade_detail {

using Say = std::function<void(const std::string&)>;  // a progress line

// The reference of `scene` under rep.truth over the G-buffer `gb`, at rep.samples per pixel:
// (image, standard error). Fills rep.reference, rep.reference_cached and rep.reference_file.
std::pair<ImageRGBf, ImageRGBf> tradeReference(const Scene& scene, const GBufferReadback& gb,
                                               const TradeOptions& opt, TradeReport& rep,
                                               const Say& say);

}  // namespace hv::eval::trade_detail
