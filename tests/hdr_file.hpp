// Test helpers: a Radiance .hdr file written from linear RGB (flat RGBE scanlines, which the
// reader accepts as Radiance does), and an equirect sky with a small bright sun in it.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "halfvec/ibl/ibl.hpp"
#include "halfvec/image/image.hpp"

namespace hv::test {

// Float -> RGBE as Ward's writer does: mantissas scaled by the largest component's exponent.
inline std::array<uint8_t, 4> toRgbe(glm::vec3 c) {
  const float v = std::max({c.x, c.y, c.z});
  if (v < 1e-32f) return {0, 0, 0, 0};
  int e = 0;
  const float m = std::frexp(v, &e) * 256.0f / v;
  return {uint8_t(c.x * m), uint8_t(c.y * m), uint8_t(c.z * m), uint8_t(e + 128)};
}

// Flat scanlines: no pixel of these images starts (2, 2, ...) or is (1, 1, 1, e), the markers
// of a run-length scanline and an old-style repeat, since every channel is 0 or has a mantissa
// byte of at least 128 for the largest channel and the test images use grey or near-grey values.
inline void writeHdrFile(const std::filesystem::path& path, const ImageRGBf& img) {
  std::ofstream f(path, std::ios::binary);
  f << "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y " << img.height << " +X " << img.width << "\n";
  for (const glm::vec3& c : img.px) {
    const std::array<uint8_t, 4> rgbe = toRgbe(c);
    f.write(reinterpret_cast<const char*>(rgbe.data()), 4);
  }
}

// A w x (w / 2) sky: radiance `sky` above the horizon, `ground` below, and a sun of `size` x
// `size` texels of radiance `sun` (warm white) centred on direction `to_sun` (unit, the image's
// own frame).
inline ImageRGBf skyWithSun(int w, glm::vec3 to_sun, float sun, int size = 2,
                            glm::vec3 sky = glm::vec3(0.4f, 0.5f, 0.7f),
                            glm::vec3 ground = glm::vec3(0.2f)) {
  const int h = w / 2;
  ImageRGBf img = makeImageRGBf(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) img.at(x, y) = y < h / 2 ? sky : ground;
  const glm::vec2 uv = equirectUV(to_sun);
  const int cx = int(uv.x * float(w)), cy = int(uv.y * float(h));
  for (int y = cy - size / 2; y < cy - size / 2 + size; ++y)
    for (int x = cx - size / 2; x < cx - size / 2 + size; ++x)
      img.at((x + w) % w, y) = sun * glm::vec3(1.0f, 0.96f, 0.9f);
  return img;
}

}  // namespace hv::test
