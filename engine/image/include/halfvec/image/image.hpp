// CPU images: 8-bit RGBA and float RGB, PNG and PFM I/O. Row 0 is the top row in memory for both
// types (PFM files store rows bottom-to-top; readPfm/writePfm flip). Knows nothing of OpenGL.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace hv {

// Every failure of the image module: the message names the file and what is wrong.
class ImageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct ImageRGBA8 {
  int width = 0;
  int height = 0;
  std::vector<uint8_t> px;  // width * height * 4, row-major, row 0 = top
  uint8_t* at(int x, int y) { return &px[(size_t(y) * size_t(width) + size_t(x)) * 4]; }
  const uint8_t* at(int x, int y) const { return &px[(size_t(y) * size_t(width) + size_t(x)) * 4]; }
};

struct ImageRGBf {
  int width = 0;
  int height = 0;
  std::vector<glm::vec3> px;  // width * height, row-major, row 0 = top
  glm::vec3& at(int x, int y) { return px[size_t(y) * size_t(width) + size_t(x)]; }
  const glm::vec3& at(int x, int y) const { return px[size_t(y) * size_t(width) + size_t(x)]; }
};

ImageRGBA8 makeImageRGBA8(int width, int height);  // zero-filled
ImageRGBf makeImageRGBf(int width, int height, glm::vec3 fill = glm::vec3(0.0f));

// Largest width and height the readers accept (the renderer's largest --size). Declared
// dimensions are checked against it and against the file's data before pixels are allocated: a
// PFM's floats must be present in the file (so it allocates about three times its size, at most
// 3 GiB), a PNG's compressed data must be able to inflate to its scanlines (deflate expands at
// most 1032:1, halfvec/core/png_bound.hpp; at most 2 GiB for 16-bit RGBA).
constexpr int kMaxImageSide = 16384;

// PNG through libstb (stb_image_write / stb_image). readPng always returns 4 channels.
void writePng(const std::string& path, const ImageRGBA8& img);
ImageRGBA8 readPng(const std::string& path);
// The same from the file's bytes (`path` names it in messages), at most `max_side` pixels wide
// and high (fuzzers lower it to keep each run small).
ImageRGBA8 decodePng(const uint8_t* bytes, size_t size, const std::string& path,
                     int max_side = kMaxImageSide);

// Portable float map, color ("PF") only on write; reads "PF" and grayscale "Pf" (expanded to
// RGB), either byte order (negative scale = little-endian). Bit-exact round trip.
void writePfm(const std::string& path, const ImageRGBf& img);
ImageRGBf readPfm(const std::string& path);
ImageRGBf decodePfm(const uint8_t* bytes, size_t size, const std::string& path,
                    int max_side = kMaxImageSide);

// Linear float -> 8-bit sRGB-encoded (IEC 61966-2-1 curve), after multiplying by exposure and
// clamping to [0, 1]; alpha = 255. NaN maps to magenta so it is visible.
ImageRGBA8 toSrgb8(const ImageRGBf& img, float exposure = 1.0f);

}  // namespace hv
