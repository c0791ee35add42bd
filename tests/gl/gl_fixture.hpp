#pragma once

#include <gtest/gtest.h>

#include <memory>

#include "halfvec/platform/context.hpp"

// One headless context per test binary (creating EGL contexts repeatedly is slow on llvmpipe).
inline hv::Context& testContext() {
  static std::unique_ptr<hv::Context> ctx = hv::createHeadlessContext();
  return *ctx;
}
