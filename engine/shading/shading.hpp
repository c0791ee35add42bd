// The shared shading math, compiled as C++: every function in shaders/common/*.glsl is callable
// here as hv::glsl::NAME. Term choices default to the GLSL defaults (see docs/brdf.md); a test
// that needs another choice includes the headers itself with its own defines inside its own
// namespace (the headers have no linkage of their own: they sit in an anonymous namespace).
#pragma once

#include "shading/glsl.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
// Dispatchers (visibility(), ...) ignore the arguments of the terms not picked.
#pragma GCC diagnostic ignored "-Wunused-parameter"
namespace hv::glsl {
namespace {
#include "../../shaders/common/math.glsl"
#include "../../shaders/common/brdf.glsl"
#include "../../shaders/common/sampling.glsl"
#include "../../shaders/common/lights.glsl"
#include "../../shaders/common/gbuffer.glsl"
#include "../../shaders/common/tonemap.glsl"
}  // namespace
}  // namespace hv::glsl
#pragma GCC diagnostic pop
