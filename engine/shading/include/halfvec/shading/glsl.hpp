// Lets the GLSL headers in shaders/common/ compile as C++ against GLM, so the CPU reference and
// the unit tests run the very code the GPU runs.
//
// Rules for a shared header (shaders/common/*.glsl), checked by both compilers:
//  - include guards (#ifndef HV_X_GLSL), #include "other.glsl" by relative path;
//  - float literals with an f suffix (1.0f), valid in GLSL >= 1.30 and in C++;
//  - no swizzles beyond .x/.y/.z/.w, no constructors of structs, no arrays of structs;
//  - out/inout parameters through HV_OUT(T) / HV_INOUT(T);
//  - helper functions that GLSL lacks (saturate, sq, ...) come from shaders/common/math.glsl.
#pragma once

#include <glm/glm.hpp>
#include <glm/gtc/constants.hpp>

namespace hv::glsl {
using namespace glm;
using uint = unsigned int;
}  // namespace hv::glsl

#define HV_CPP 1
#define HV_OUT(T) T&
#define HV_INOUT(T) T&
