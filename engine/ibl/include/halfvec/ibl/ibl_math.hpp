// shaders/common/ibl.glsl and sampling.glsl compiled as C++ (hv::glsl::EnvBRDFApprox,
// evalSH9Irradiance, ...), the same way halfvec/shading/shading.hpp compiles the other shared
// headers.
#pragma once

#include "halfvec/shading/shading.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
namespace hv::glsl {
namespace {
#include "halfvec/shaders/common/sampling.glsl"  // hammersley, importanceSampleGGX, pdfGGX
#include "halfvec/shaders/common/ibl.glsl"
}  // namespace
}  // namespace hv::glsl
#pragma GCC diagnostic pop
