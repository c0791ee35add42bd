// PNG and PFM readers against files from independent writers (below, written from the formats'
// specifications: PNG with stored deflate blocks, PFM big- and little-endian), and against
// hostile headers: dimensions past kMaxImageSide, sizes the data cannot hold.
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <cstring>
#include <string>
#include <vector>

#include "halfvec/core/png_bound.hpp"
#include "halfvec/image/image.hpp"

namespace {

uint32_t crc32(const uint8_t* p, size_t n, uint32_t crc = 0) {
  crc = ~crc;
  for (size_t i = 0; i < n; ++i) {
    crc ^= p[i];
    for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
  }
  return ~crc;
}

void putBe32(std::vector<uint8_t>& out, uint32_t v) {
  for (int i = 3; i >= 0; --i) out.push_back(uint8_t(v >> (8 * i)));
}

void chunk(std::vector<uint8_t>& png, const char* type, const std::vector<uint8_t>& data) {
  putBe32(png, uint32_t(data.size()));
  const size_t start = png.size();
  png.insert(png.end(), type, type + 4);
  png.insert(png.end(), data.begin(), data.end());
  putBe32(png, crc32(&png[start], png.size() - start));
}

// An 8-bit RGBA PNG (ISO/IEC 15948): rows with filter byte 0, zlib stream of stored blocks.
std::vector<uint8_t> encodePng(int w, int h, const std::vector<uint8_t>& rgba) {
  std::vector<uint8_t> raw;
  for (int y = 0; y < h; ++y) {
    raw.push_back(0);
    raw.insert(raw.end(), rgba.begin() + long(y) * w * 4, rgba.begin() + long(y + 1) * w * 4);
  }
  std::vector<uint8_t> z = {0x78, 0x01};
  for (size_t at = 0; at < raw.size() || at == 0;) {
    const size_t n = std::min<size_t>(65535, raw.size() - at);
    z.push_back(at + n == raw.size() ? 1 : 0);
    z.insert(z.end(), {uint8_t(n), uint8_t(n >> 8), uint8_t(~n), uint8_t(~n >> 8)});
    z.insert(z.end(), raw.begin() + long(at), raw.begin() + long(at + n));
    at += n;
    if (n == 0) break;
  }
  uint32_t a = 1, b = 0;  // Adler-32
  for (uint8_t c : raw) a = (a + c) % 65521, b = (b + a) % 65521;
  putBe32(z, b << 16 | a);
  std::vector<uint8_t> png = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  std::vector<uint8_t> ihdr;
  putBe32(ihdr, uint32_t(w));
  putBe32(ihdr, uint32_t(h));
  ihdr.insert(ihdr.end(), {8, 6, 0, 0, 0});
  chunk(png, "IHDR", ihdr);
  chunk(png, "IDAT", z);
  chunk(png, "IEND", {});
  return png;
}

template <class F>
std::string errorOf(F&& f) {
  try {
    f();
  } catch (const hv::ImageError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(ImageReaders, PngFromAnIndependentWriter) {
  const int w = 37, h = 11;
  std::vector<uint8_t> rgba(size_t(w) * h * 4);
  for (size_t i = 0; i < rgba.size(); ++i) rgba[i] = uint8_t((i * 131 + 7) & 255);
  const std::vector<uint8_t> png = encodePng(w, h, rgba);
  const hv::ImageRGBA8 img = hv::decodePng(png.data(), png.size(), "indep.png");
  ASSERT_EQ(img.width, w);
  ASSERT_EQ(img.height, h);
  EXPECT_EQ(img.px, rgba);
}

TEST(ImageReaders, PngDimensionsBoundedBeforeDecoding) {
  // A header declaring kMaxImageSide + 1 columns: rejected from the header alone.
  std::vector<uint8_t> png = encodePng(1, 1, {1, 2, 3, 4});
  const uint32_t wide = hv::kMaxImageSide + 1;
  png[16] = uint8_t(wide >> 24), png[17] = uint8_t(wide >> 16), png[18] = uint8_t(wide >> 8),
  png[19] = uint8_t(wide);
  std::string e = errorOf([&] { hv::decodePng(png.data(), png.size(), "wide.png"); });
  EXPECT_NE(e.find("kMaxImageSide"), std::string::npos) << e;
  EXPECT_NE(e.find("wide.png"), std::string::npos) << e;
  // Truncated image data.
  png = encodePng(64, 64, std::vector<uint8_t>(64 * 64 * 4, 9));
  e = errorOf([&] { hv::decodePng(png.data(), png.size() / 2, "cut.png"); });
  EXPECT_NE(e.find("cut.png"), std::string::npos) << e;
}

TEST(ImageReaders, PngDataMustInflateToTheDeclaredPixels) {
  // A 1x1 file whose header declares 4096 x 4096: 12 bytes of zlib data cannot inflate to the
  // 67 MB of scanlines (deflate expands at most 1032:1), so it is rejected before stb_image
  // allocates them.
  std::vector<uint8_t> png = encodePng(1, 1, {1, 2, 3, 4});
  for (int at : {16, 20}) png[size_t(at) + 2] = 0x10, png[size_t(at) + 3] = 0;  // 4096
  std::string e = errorOf([&] { hv::decodePng(png.data(), png.size(), "bomb.png"); });
  EXPECT_NE(e.find("bomb.png"), std::string::npos) << e;
  EXPECT_NE(e.find("4096x4096"), std::string::npos) << e;
  EXPECT_NE(e.find("IDAT"), std::string::npos) << e;
  // The bound exactly: one 1032-pixel row of 8-bit gray is 1033 bytes of scanline, which 1 byte
  // of compressed data cannot give and 2 bytes can.
  auto grayRow = [](size_t idat_bytes) {
    std::vector<uint8_t> p = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    std::vector<uint8_t> ihdr;
    putBe32(ihdr, 1032);
    putBe32(ihdr, 1);
    ihdr.insert(ihdr.end(), {8, 0, 0, 0, 0});
    chunk(p, "IHDR", ihdr);
    chunk(p, "IDAT", std::vector<uint8_t>(idat_bytes, 0));
    chunk(p, "IEND", {});
    return p;
  };
  std::vector<uint8_t> one = grayRow(1), two = grayRow(2);
  EXPECT_NE(hv::pngDataShortfall(one.data(), one.size()), "");
  EXPECT_EQ(hv::pngDataShortfall(two.data(), two.size()), "");
  // Legitimate files pass, however well they compress: 512 x 512 of one color by stb's writer.
  const std::string path = ::testing::TempDir() + "flat.png";
  hv::ImageRGBA8 flat = hv::makeImageRGBA8(512, 512);
  for (uint8_t& c : flat.px) c = 200;
  hv::writePng(path, flat);
  EXPECT_EQ(hv::readPng(path).px, flat.px);
  std::remove(path.c_str());
  // Not a PNG, or no header: left to the decoder.
  EXPECT_EQ(hv::pngDataShortfall(png.data(), 7), "");
}

TEST(ImageReaders, PfmFromAnIndependentWriter) {
  // 3x2 colour PFM, big-endian (positive scale), rows bottom to top, written byte by byte.
  const float v[2][3][3] = {{{1, 2, 3}, {4, 5, 6}, {7, 8, 9}},  // bottom row
                            {{-1, 0.5f, 1e30f}, {0, 0, 0}, {3.25f, -2, 1}}};
  std::string s = "PF\n3 2\n1.0\n";
  for (const auto& row : v)
    for (const auto& px : row)
      for (float f : px) {
        uint32_t u;
        std::memcpy(&u, &f, 4);
        for (int i = 3; i >= 0; --i) s.push_back(char(u >> (8 * i)));
      }
  const hv::ImageRGBf img =
      hv::decodePfm(reinterpret_cast<const uint8_t*>(s.data()), s.size(), "be.pfm");
  ASSERT_EQ(img.width, 3);
  ASSERT_EQ(img.height, 2);
  EXPECT_EQ(img.at(0, 1), glm::vec3(1, 2, 3));  // bottom row of the file = last row in memory
  EXPECT_EQ(img.at(2, 0), glm::vec3(3.25f, -2, 1));
  EXPECT_EQ(img.at(0, 0).z, 1e30f);
}

TEST(ImageReaders, PfmDeclaredSizeMustFitTheData) {
  std::string s = "PF\n16384 16384\n-1.0\n" + std::string(64, '\0');
  std::string e = errorOf(
      [&] { hv::decodePfm(reinterpret_cast<const uint8_t*>(s.data()), s.size(), "big.pfm"); });
  EXPECT_NE(e.find("truncated"), std::string::npos) << e;
  s = "PF\n16385 1\n-1.0\n" + std::string(16385 * 12, '\0');
  e = errorOf(
      [&] { hv::decodePfm(reinterpret_cast<const uint8_t*>(s.data()), s.size(), "wide.pfm"); });
  EXPECT_NE(e.find("bad header"), std::string::npos) << e;
  s = "PF\n99999999999999999999 1\n-1.0\n";
  e = errorOf(
      [&] { hv::decodePfm(reinterpret_cast<const uint8_t*>(s.data()), s.size(), "huge.pfm"); });
  EXPECT_NE(e.find("bad header"), std::string::npos) << e;
}

// Regression: a directory or /dev/zero as an input reported "file not found" (and /dev/zero, read
// through, would not end). Each image reader names what the path is, at once; a FIFO is not
// waited on.
TEST(ImageReaders, SpecialFilesAreNamedForWhatTheyAre) {
  namespace fs = std::filesystem;
  const fs::path d = fs::temp_directory_path() / ("hv_image_special_" + std::to_string(::getpid()));
  fs::remove_all(d);
  fs::create_directories(d / "dir.png");
  fs::create_symlink("/dev/zero", d / "zero.pfm");
  ASSERT_EQ(::mkfifo((d / "fifo.png").c_str(), 0600), 0);
  auto error = [](auto&& read) {
    try {
      read();
    } catch (const hv::ImageError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  std::string e = error([&] { hv::readPng((d / "dir.png").string()); });
  EXPECT_NE(e.find("is a directory"), std::string::npos) << e;
  e = error([&] { hv::readPfm((d / "zero.pfm").string()); });
  EXPECT_NE(e.find("is a character device"), std::string::npos) << e;
  e = error([&] { hv::readPng((d / "fifo.png").string()); });
  EXPECT_NE(e.find("is a FIFO"), std::string::npos) << e;
  e = error([&] { hv::readPng((d / "missing.png").string()); });
  EXPECT_NE(e.find("no such file"), std::string::npos) << e;
  fs::remove_all(d);
}
