#include "halfvec/reference/env_sampling.hpp"

#include <algorithm>
#include <cmath>

#include "halfvec/core/parallel.hpp"

namespace hv::reference_detail {

namespace {
constexpr double kPi = 3.14159265358979323846;

// Index i with cdf[i] <= u < cdf[i + 1] (cdf nondecreasing, cdf[0] = 0, cdf[n] = 1).
int findInterval(const float* cdf, int n, float u) {
  const float* it = std::upper_bound(cdf, cdf + n + 1, u);
  return std::clamp(int(it - cdf) - 1, 0, n - 1);
}
}  // namespace

EnvDistribution::EnvDistribution(const EnvSource& env, int width, int height)
    : width_(width), height_(height) {
  // The largest luminance of 4x4 sub-samples per texel: a source much smaller than the texel
  // (the sky's sun is 0.53 degrees, a texel 0.35) still gets its full weight wherever a
  // sub-sample sees it.
  std::vector<double> lum(size_t(width) * size_t(height), 0.0);
  detail::parallelFor(height, 0, [&](int y) {
    for (int x = 0; x < width; ++x) {
      double m = 0.0;
      for (int sy = 0; sy < 4; ++sy) {
        for (int sx = 0; sx < 4; ++sx) {
          const glm::vec2 uv((float(x) + 0.125f + 0.25f * float(sx)) / float(width),
                             (float(y) + 0.125f + 0.25f * float(sy)) / float(height));
          const glm::vec3 c = env.radiance(equirectDirection(uv));
          m = std::max(m, 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z);
        }
      }
      lum[size_t(y) * size_t(width) + size_t(x)] = m;
    }
  });
  // Dilated by one texel (3x3 maximum, longitude wraps): a sliver of a source that no
  // sub-sample of its texel saw lies next to a texel that saw it, and then keeps a density of
  // the source's order. Without this such slivers were hit by the other strategies with a tiny
  // density and gave rare, huge samples (a heavy-tailed estimate of the sky's irradiance).
  std::vector<double> w(lum.size());
  double total = 0.0;
  for (int y = 0; y < height; ++y) {
    const double sin_t = std::sin(kPi * (double(y) + 0.5) / double(height));
    for (int x = 0; x < width; ++x) {
      double m = 0.0;
      for (int dy = -1; dy <= 1; ++dy) {
        const int yy = std::clamp(y + dy, 0, height - 1);
        for (int dx = -1; dx <= 1; ++dx) {
          const int xx = (x + dx + width) % width;
          m = std::max(m, lum[size_t(yy) * size_t(width) + size_t(xx)]);
        }
      }
      w[size_t(y) * size_t(width) + size_t(x)] = m * sin_t;
      total += m * sin_t;
    }
  }
  // Floor: 1e-3 of the mean weight (times sin theta), so no direction has density 0.
  const double floor_w = 1e-3 * std::max(total, 1e-30) / double(w.size());
  total = 0.0;
  for (int y = 0; y < height; ++y) {
    const double sin_t = std::sin(kPi * (double(y) + 0.5) / double(height));
    for (int x = 0; x < width; ++x) {
      double& v = w[size_t(y) * size_t(width) + size_t(x)];
      v += floor_w * sin_t;
      total += v;
    }
  }
  texel_p_.resize(w.size());
  row_cdf_.assign(size_t(height) + 1, 0.0f);
  col_cdf_.assign(size_t(height) * size_t(width + 1), 0.0f);
  double acc_rows = 0.0;
  for (int y = 0; y < height; ++y) {
    double row = 0.0;
    for (int x = 0; x < width; ++x) row += w[size_t(y) * size_t(width) + size_t(x)];
    double acc = 0.0;
    float* cdf = &col_cdf_[size_t(y) * size_t(width + 1)];
    for (int x = 0; x < width; ++x) {
      const double v = w[size_t(y) * size_t(width) + size_t(x)];
      texel_p_[size_t(y) * size_t(width) + size_t(x)] = float(v / total);
      acc += v;
      cdf[x + 1] = float(acc / row);
    }
    cdf[width] = 1.0f;
    acc_rows += row;
    row_cdf_[size_t(y) + 1] = float(acc_rows / total);
  }
  row_cdf_[size_t(height)] = 1.0f;
}

glm::vec3 EnvDistribution::sample(glm::vec2 u, float& pdf_out) const {
  const int y = findInterval(row_cdf_.data(), height_, u.y);
  const float* cdf = &col_cdf_[size_t(y) * size_t(width_ + 1)];
  const int x = findInterval(cdf, width_, u.x);
  // Position inside the chosen texel from the leftover of each uniform.
  const float dy = row_cdf_[size_t(y) + 1] - row_cdf_[size_t(y)];
  const float dx = cdf[x + 1] - cdf[x];
  const float fy = dy > 0.0f ? std::clamp((u.y - row_cdf_[size_t(y)]) / dy, 0.0f, 0.999999f) : 0.5f;
  const float fx = dx > 0.0f ? std::clamp((u.x - cdf[x]) / dx, 0.0f, 0.999999f) : 0.5f;
  const glm::vec2 uv((float(x) + fx) / float(width_), (float(y) + fy) / float(height_));
  const glm::vec3 dir = equirectDirection(uv);
  pdf_out = pdf(dir);
  return dir;
}

float EnvDistribution::pdf(const glm::vec3& dir) const {
  const glm::vec2 uv = equirectUV(dir);
  const int x = std::clamp(int(uv.x * float(width_)), 0, width_ - 1);
  const int y = std::clamp(int(uv.y * float(height_)), 0, height_ - 1);
  const float sin_t = std::sqrt(std::max(0.0f, 1.0f - dir.y * dir.y));
  if (sin_t <= 0.0f) return 0.0f;
  // Uniform in (u, v) inside the texel: p_texel * width * height per unit uv area, and
  // d(omega) = 2 pi^2 sin(theta) du dv.
  return texel_p_[size_t(y) * size_t(width_) + size_t(x)] * float(width_) * float(height_) /
         (2.0f * float(kPi * kPi) * sin_t);
}

}  // namespace hv::reference_detail
