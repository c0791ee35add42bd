// The shared shading math, compiled as C++: every function in shaders/common/*.glsl is callable
// here as hv::glsl::NAME. Term choices are the GLSL defaults (docs/brdf.md, docs/lights.md); for
// run-time choice of BRDF terms use halfvec/shading/brdf.hpp. Code that needs other defines
// compiles the headers again in its own namespace after resetting the include guards and option
// defines (see tests/shading/test_lights_variant.cpp). The headers sit in an anonymous namespace,
// so the functions have internal linkage; C++ functions taking their structs (Surface, GpuLight)
// must be inline in a header.
#pragma once

#include "halfvec/shading/glsl.hpp"
#include "halfvec/shading/gpu_records.hpp"
#include "halfvec/shading/error_table.hpp"
#include "halfvec/shading/ltc_table.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
// Dispatchers (visibility(), ...) ignore the arguments of the terms not picked.
#pragma GCC diagnostic ignored "-Wunused-parameter"
namespace hv::glsl {
namespace {
#include "halfvec/shaders/common/math.glsl"
#include "halfvec/shaders/common/brdf.glsl"
#include "halfvec/shaders/common/sampling.glsl"
#include "halfvec/shaders/common/ltc_integrals.glsl"
#include "halfvec/shaders/common/ltc.glsl"
#include "halfvec/shaders/common/lights.glsl"
#include "halfvec/shaders/common/clear_coat.glsl"
#include "halfvec/shaders/common/cull.glsl"
#include "halfvec/shaders/common/gbuffer.glsl"
#include "halfvec/shaders/common/probes.glsl"
#include "halfvec/shaders/common/tonemap.glsl"
#include "halfvec/shaders/common/fxaa.glsl"
#include "halfvec/shaders/common/emitter.glsl"
#include "halfvec/shaders/common/texture_transform.glsl"
}  // namespace
}  // namespace hv::glsl
#pragma GCC diagnostic pop
