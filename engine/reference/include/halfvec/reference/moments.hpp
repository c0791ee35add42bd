// Running sums of one Monte Carlo estimator, per channel, for its mean and standard error.
#pragma once

#include <glm/glm.hpp>

namespace hv::reference_detail {

struct Moments {
  glm::dvec3 sum{0.0}, sum2{0.0};
  void add(const glm::dvec3& x) {
    sum += x;
    sum2 += x * x;
  }
  glm::dvec3 mean(int n) const { return n > 0 ? sum / double(n) : glm::dvec3(0.0); }
  // Standard error of the mean: sqrt(s^2 / n), s^2 the unbiased sample variance.
  glm::dvec3 stdError(int n) const {
    if (n < 2) return glm::dvec3(0.0);
    const glm::dvec3 m = sum / double(n);
    const glm::dvec3 var = glm::max((sum2 - double(n) * m * m) / double(n - 1), glm::dvec3(0.0));
    return glm::sqrt(var / double(n));
  }
};

}  // namespace hv::reference_detail
