// The Radiance .hdr reader against files written by an independent encoder (below, written from
// the format description, not from the reader): run-length encoded, flat and old-style repeat
// scanlines mixed in one file; declared sizes the data cannot hold; the project's limit; and,
// where the shared assets exist, agreement with stb_image on every real HDR (all RLE).
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <stb/stb_image.h>

#include "halfvec/ibl/ibl.hpp"
#include "hdr_file.hpp"
#include "shared_assets.hpp"

namespace fs = std::filesystem;

namespace {

using Rgbe = std::array<uint8_t, 4>;

using hv::test::toRgbe;  // hdr_file.hpp

// RGBE -> float, the convention the reader documents (mantissa * 2^(e - 136)).
glm::vec3 fromRgbe(const Rgbe& p) {
  if (p[3] == 0) return glm::vec3(0.0f);
  const double f = std::ldexp(1.0, int(p[3]) - 136);
  return glm::vec3(float(p[0] * f), float(p[1] * f), float(p[2] * f));
}

enum class Line { Rle, Flat, OldRuns };

// One scanline in the chosen encoding. Rle: per component, runs of >= 3 equal bytes become runs,
// the rest literals (at most 128 / 127 per code). OldRuns: flat, with each repeat of the previous
// pixel written as (1, 1, 1, count) pixels (count split into 8-bit digits, low digit first).
std::string encodeLine(const std::vector<Rgbe>& px, Line mode) {
  std::string out;
  const int w = int(px.size());
  if (mode == Line::Rle) {
    out += {2, 2, char(w >> 8), char(w & 255)};
    for (int c = 0; c < 4; ++c) {
      int x = 0;
      while (x < w) {
        int run = 1;
        while (x + run < w && run < 127 &&
               px[size_t(x + run)][size_t(c)] == px[size_t(x)][size_t(c)])
          ++run;
        if (run >= 3) {
          out += char(128 + run);
          out += char(px[size_t(x)][size_t(c)]);
          x += run;
          continue;
        }
        int lit = 0;  // literals up to the next run of 3 or 128 bytes
        while (x + lit < w && lit < 128) {
          if (x + lit + 2 < w &&
              px[size_t(x + lit)][size_t(c)] == px[size_t(x + lit + 1)][size_t(c)] &&
              px[size_t(x + lit)][size_t(c)] == px[size_t(x + lit + 2)][size_t(c)]) {
            break;
          }
          ++lit;
        }
        out += char(lit);
        for (int k = 0; k < lit; ++k) out += char(px[size_t(x + k)][size_t(c)]);
        x += lit;
      }
    }
    return out;
  }
  for (int x = 0; x < w;) {
    out.append(reinterpret_cast<const char*>(px[size_t(x)].data()), 4);
    int repeat = 0;
    while (mode == Line::OldRuns && x + 1 + repeat < w &&
           px[size_t(x + 1 + repeat)] == px[size_t(x)]) {
      ++repeat;
    }
    for (int shift = 0, left = repeat; left > 0; shift += 8, left >>= 8) {
      out += {1, 1, 1, char(left & 255)};
    }
    x += 1 + repeat;
  }
  return out;
}

std::string hdrFile(int w, int h, const std::string& raster) {
  return "#?RADIANCE\n# written by the test's "
         "encoder\nFORMAT=32-bit_rle_rgbe\nEXPOSURE=1.0\n\n-Y " +
         std::to_string(h) + " +X " + std::to_string(w) + "\n" + raster;
}

std::string errorOf(const std::string& bytes) {
  try {
    hv::decodeHdr(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size(), "test.hdr");
  } catch (const hv::IblError& e) {
    return e.what();
  }
  return "";
}

// A w x h test pattern with long constant stretches (runs) and noise (literals).
std::vector<std::vector<Rgbe>> pattern(int w, int h) {
  std::vector<std::vector<Rgbe>> img(static_cast<size_t>(h),
                                     std::vector<Rgbe>(static_cast<size_t>(w)));
  uint32_t s = 12345;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      s = s * 1664525u + 1013904223u;
      const glm::vec3 c =
          x < w / 3 ? glm::vec3(0.5f, 0.25f, 2.0f)
                    : glm::vec3(float(s >> 24) / 16.0f, float(y) + 0.1f, 1e-3f * float(x));
      img[size_t(y)][size_t(x)] = toRgbe(c);
    }
  return img;
}

}  // namespace

TEST(HdrReader, MixedScanlineEncodingsDecodeExactly) {
  const int w = 300, h = 150;
  const auto img = pattern(w, h);
  std::string raster;
  for (int y = 0; y < h; ++y) raster += encodeLine(img[size_t(y)], Line(y % 3));
  const std::string file = hdrFile(w, h, raster);
  const hv::ImageRGBf out =
      hv::decodeHdr(reinterpret_cast<const uint8_t*>(file.data()), file.size(), "mixed.hdr");
  ASSERT_EQ(out.width, w);
  ASSERT_EQ(out.height, h);
  int wrong = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) wrong += out.at(x, y) != fromRgbe(img[size_t(y)][size_t(x)]);
  EXPECT_EQ(wrong, 0);
  // The same file with every scanline flat, or every one RLE, decodes to the same image.
  for (Line mode : {Line::Flat, Line::Rle}) {
    std::string r;
    for (int y = 0; y < h; ++y) r += encodeLine(img[size_t(y)], mode);
    const std::string f = hdrFile(w, h, r);
    const hv::ImageRGBf o =
        hv::decodeHdr(reinterpret_cast<const uint8_t*>(f.data()), f.size(), "x");
    EXPECT_EQ(std::memcmp(o.px.data(), out.px.data(), out.px.size() * sizeof(glm::vec3)), 0);
  }
}

TEST(HdrReader, DeclaredSizeMustFitTheData) {
  // A reported file: an RLE raster declaring 18918 x 9459 (4.9 GB decoded): over the limit.
  std::string e = errorOf(hdrFile(18918, 9459, std::string(1 << 16, '\x7f')));
  EXPECT_NE(e.find("kMaxHdrWidth"), std::string::npos) << e;
  // Within the limit, but a few bytes cannot hold 16384 x 8192 pixels: rejected before
  // allocating 1.5 GiB.
  e = errorOf(hdrFile(16384, 8192, std::string(4096, '\x02')));
  EXPECT_NE(e.find("cannot hold"), std::string::npos) << e;
  // Old-style runs: the largest run count is bounded by the scanline.
  std::string line = encodeLine({toRgbe(glm::vec3(1.0f))}, Line::Flat);
  line += {1, 1, 1, char(255)};  // 255 repeats in a 16-pixel scanline
  e = errorOf(hdrFile(16, 8, std::string(line) + std::string(200, '\0')));
  EXPECT_NE(e.find("corrupt scanline 0"), std::string::npos) << e;
  // A run at the start of a scanline has no pixel to repeat.
  e = errorOf(hdrFile(16, 8, std::string({1, 1, 1, 4}) + std::string(400, '\0')));
  EXPECT_NE(e.find("without a previous pixel"), std::string::npos) << e;
  // An RLE run past the end of the scanline.
  std::string rle = {2, 2, 0, 16, char(128 + 20), 7};
  e = errorOf(hdrFile(16, 8, rle + std::string(400, '\0')));
  EXPECT_NE(e.find("past the end"), std::string::npos) << e;
  // Truncated in the middle of the raster.
  const auto img = pattern(64, 32);
  std::string raster;
  for (int y = 0; y < 32; ++y) raster += encodeLine(img[size_t(y)], Line::Rle);
  e = errorOf(hdrFile(64, 32, raster.substr(0, raster.size() * 2 / 3)));
  EXPECT_NE(e.find("truncated"), std::string::npos) << e;
}

TEST(HdrReader, AgreesWithStbImageOnSharedAssets) {
  const fs::path dir = hv::test::assetsDir() / "env";
  if (hv::test::assetsDir().empty() || !fs::is_directory(dir)) {
    GTEST_SKIP() << "no shared assets at " << dir;
  }
  int files = 0;
  for (const auto& entry : fs::directory_iterator(dir)) {
    if (entry.path().extension() != ".hdr") continue;
    const hv::ImageRGBf ours = hv::loadHdr(entry.path().string());
    int w = 0, h = 0, n = 0;
    float* ref = stbi_loadf(entry.path().c_str(), &w, &h, &n, 3);
    ASSERT_NE(ref, nullptr) << entry.path();
    ASSERT_EQ(w, ours.width);
    ASSERT_EQ(h, ours.height);
    EXPECT_EQ(std::memcmp(ref, ours.px.data(), size_t(w) * size_t(h) * 12), 0) << entry.path();
    stbi_image_free(ref);
    ++files;
  }
  EXPECT_GT(files, 0);
}
