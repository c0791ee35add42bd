// The error budget's table (shaders/common/error_budget.glsl describes its axes and layout): the
// committed data that `halfvec error-fit` generates (engine/shading/src/error_table.cpp), read on
// the CPU exactly as the GPU samples it. Included by halfvec/shading/shading.hpp before the shared
// GLSL headers, whose C++ compilation of error_budget.glsl calls errorTableSample where GLSL calls
// texture().
#pragma once

#include <span>
#include <string_view>

#include <glm/glm.hpp>

namespace hv {

// The committed table, in texel order of its 3D texture: x = (azimuth cell * offset cells + offset
// cell) * roughness cells + roughness cell, then sin(sigma), then N.V (error_budget.glsl): one
// float per cell, ln(E_rp / R).
std::span<const float> errorTableData();
// The command that generated the table and its options, as written in its header.
std::string_view errorTableProvenance();

// The table sampled at texture coordinates uvw as a GPU does with linear filtering and
// clamp-to-edge (texel centers at (i + 0.5) / size; trilinear in float).
float errorTableSample(glm::vec3 uvw);

}  // namespace hv
