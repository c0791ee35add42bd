// Measures the octahedral normal encodings over a dense set of directions (docs/gbuffer.md holds
// the numbers this test asserts).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "halfvec/shading/shading.hpp"

using namespace hv::glsl;

namespace {
struct Err {
  double max_deg = 0, mean_deg = 0;
};

// Fibonacci sphere: `n` nearly uniform directions, plus the axes and diagonals.
template <class Quant>
Err measure(int n, Quant q) {
  Err e;
  auto one = [&](vec3 d) {
    vec2 enc = octEncode(d);
    enc = vec2(q(enc.x), q(enc.y));
    vec3 r = octDecode(enc);
    // Angle in double via atan2(|a x b|, a.b): acos of a float dot loses ~0.02 deg near 1.
    const double ax = r.x, ay = r.y, az = r.z, bx = d.x, by = d.y, bz = d.z;
    const double cx = ay * bz - az * by, cy = az * bx - ax * bz, cz = ax * by - ay * bx;
    double a = std::atan2(std::sqrt(cx * cx + cy * cy + cz * cz), ax * bx + ay * by + az * bz) *
               180.0 / M_PI;
    e.max_deg = std::max(e.max_deg, a);
    e.mean_deg += a;
  };
  const double golden = M_PI * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < n; ++i) {
    double y = 1.0 - 2.0 * (i + 0.5) / n;
    double r = std::sqrt(1.0 - y * y);
    one(normalize(
        vec3(float(std::cos(golden * i) * r), float(y), float(std::sin(golden * i) * r))));
  }
  for (vec3 d : {vec3(1, 0, 0), vec3(-1, 0, 0), vec3(0, 1, 0), vec3(0, -1, 0), vec3(0, 0, 1),
                 vec3(0, 0, -1), normalize(vec3(1, 1, 1)), normalize(vec3(-1, -1, -1))}) {
    one(d);
  }
  e.mean_deg /= (n + 8);
  return e;
}
}  // namespace

TEST(GBufferEncoding, OctahedralRoundTripIsExactWithoutQuantization) {
  Err e = measure(100000, [](float x) { return x; });
  EXPECT_LT(e.max_deg, 0.01);
}

// Budget (docs/gbuffer.md): RG16 snorm, max error < 0.005 deg, mean < 0.002 deg (measured 0.0037
// and 0.0013).
TEST(GBufferEncoding, Rg16SnormMeetsBudget) {
  Err e = measure(1000000, [](float x) { return quantizeSnorm16(x); });
  std::printf("oct RG16_SNORM: max %.5f deg, mean %.5f deg\n", e.max_deg, e.mean_deg);
  EXPECT_LT(e.max_deg, 0.005);
  EXPECT_LT(e.mean_deg, 0.002);
}

// The rejected alternative, measured for the record: 10:10 in RGB10A2 (unorm, remapped).
TEST(GBufferEncoding, TenTenIsCoarser) {
  Err e = measure(1000000, [](float x) { return quantizeUnorm10(x * 0.5f + 0.5f) * 2.0f - 1.0f; });
  std::printf("oct 10:10 (RGB10A2): max %.5f deg, mean %.5f deg\n", e.max_deg, e.mean_deg);
  EXPECT_GT(e.max_deg, 0.05);  // why we pay 4 bytes for the normal
  EXPECT_LT(e.max_deg, 0.5);
}
