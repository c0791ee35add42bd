#include <algorithm>
#include <cmath>

#include "halfvec/shading/ltc_table.hpp"
#include "halfvec/shading/shading.hpp"

namespace hv {

glm::vec4 ltcTableSample(int which, glm::vec2 uv) {
  constexpr int n = HV_LTC_TABLE_SIZE;
  const std::span<const float> data = ltcTableData();
  // GL_LINEAR: the four texels around uv * size - 0.5, each index clamped to the edge.
  const glm::vec2 s = uv * float(n) - 0.5f;
  const glm::vec2 f0 = glm::floor(s);
  const glm::vec2 f = s - f0;
  auto texel = [&](int i, int j) {
    i = std::clamp(i, 0, n - 1);
    j = std::clamp(j, 0, n - 1);
    const float* c = data.data() + (size_t(j) * n + size_t(i)) * kLtcFloatsPerCell + which * 4;
    return glm::vec4(c[0], c[1], c[2], c[3]);
  };
  const int i0 = int(f0.x), j0 = int(f0.y);
  return glm::mix(glm::mix(texel(i0, j0), texel(i0 + 1, j0), f.x),
                  glm::mix(texel(i0, j0 + 1), texel(i0 + 1, j0 + 1), f.x), f.y);
}

}  // namespace hv
