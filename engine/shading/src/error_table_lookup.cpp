#include <algorithm>
#include <cmath>

#include "halfvec/shading/error_table.hpp"
#include "halfvec/shading/shading.hpp"

namespace hv {

float errorTableSample(glm::vec3 uvw) {
  constexpr int nx = HV_ERR_TEXELS_X, ny = HV_ERR_SIN_CELLS, nz = HV_ERR_NOV_CELLS;
  const std::span<const float> data = errorTableData();
  // GL_LINEAR: the eight texels around uvw * size - 0.5, each index clamped to the edge.
  const glm::vec3 s = uvw * glm::vec3(nx, ny, nz) - 0.5f;
  const glm::vec3 f0 = glm::floor(s);
  const glm::vec3 f = s - f0;
  auto texel = [&](int i, int j, int k) {
    i = std::clamp(i, 0, nx - 1);
    j = std::clamp(j, 0, ny - 1);
    k = std::clamp(k, 0, nz - 1);
    return data[(size_t(k) * ny + size_t(j)) * nx + size_t(i)];
  };
  const int i0 = int(f0.x), j0 = int(f0.y), k0 = int(f0.z);
  auto plane = [&](int k) {
    return glm::mix(glm::mix(texel(i0, j0, k), texel(i0 + 1, j0, k), f.x),
                    glm::mix(texel(i0, j0 + 1, k), texel(i0 + 1, j0 + 1, k), f.x), f.y);
  };
  return glm::mix(plane(k0), plane(k0 + 1), f.z);
}

}  // namespace hv
