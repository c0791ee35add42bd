// The ambient occlusion math of shaders/common/ao.glsl compiled as C++ (hv::glsl::NAME), for the
// tests and the evaluation; kept out of shading.hpp so that what includes only that one does not
// change. Include guards make it safe after shading.hpp.
#pragma once

#include "halfvec/shading/glsl.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
namespace hv::glsl {
namespace {
#include "halfvec/shaders/common/math.glsl"
#include "halfvec/shaders/common/ao.glsl"
}  // namespace
}  // namespace hv::glsl
#pragma GCC diagnostic pop
