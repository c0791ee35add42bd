// The fitted LTC table (shaders/common/ltc.glsl describes its layout): the committed data that
// `halfvec ltc-fit` generates (engine/shading/src/ltc_table.cpp), read on the CPU exactly as the
// GPU samples it. Included by halfvec/shading/shading.hpp before the shared GLSL headers, whose C++
// compilation of ltc.glsl calls ltcTableSample where GLSL calls texture().
#pragma once

#include <span>
#include <string_view>

#include <glm/glm.hpp>

namespace hv {

// Floats per cell: texture 0 (a_x/alpha, a_y/alpha, s, the axis's tilt), then texture 1 (n_f,
// n_fresnel, the cell's fit error, 0).
inline constexpr int kLtcFloatsPerCell = 8;

// The committed table: size x size cells, row j (N.V index) after row j - 1, cell (i, j) at
// (j * size + i) * kLtcFloatsPerCell. size = HV_LTC_TABLE_SIZE (ltc.glsl).
std::span<const float> ltcTableData();
// The command that generated the table and its fit options, as written in its header.
std::string_view ltcTableProvenance();

// Texture `which` (0 or 1) of the table sampled at texture coordinates uv as a GPU does with
// linear filtering and clamp-to-edge (texel centers at (i + 0.5) / size; bilinear in float).
glm::vec4 ltcTableSample(int which, glm::vec2 uv);

}  // namespace hv
