#include "halfvec/image/image.hpp"

#include "halfvec/core/input_file.hpp"
#include "halfvec/core/png_bound.hpp"

#include <algorithm>
#include <bit>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <span>
#include <sstream>
#include <filesystem>

// libstb.so carries the implementations; never define STB_IMAGE*_IMPLEMENTATION here.
#include <stb/stb_image.h>
#include <stb/stb_image_write.h>

namespace hv {
namespace {

// The whole file, if it is a regular file of at most `max_bytes`.
std::vector<uint8_t> readFileBytes(const std::string& path, const char* what, uint64_t max_bytes) {
  try {
    const std::string bytes =
        readInputFile(path, max_bytes, "the largest file an accepted image needs");
    return std::vector<uint8_t>(bytes.begin(), bytes.end());
  } catch (const InputError& e) {
    throw ImageError(std::string(what) + " '" + path + "': " + e.reason);
  }
}

void checkSize(const std::string& path, int w, int h, size_t have, size_t want, const char* what) {
  if (w <= 0 || h <= 0)
    throw ImageError(std::string(what) + " '" + path + "': empty image (" + std::to_string(w) +
                     "x" + std::to_string(h) + ")");
  if (have != want)
    throw ImageError(std::string(what) + " '" + path + "': pixel buffer has " +
                     std::to_string(have) + " entries, expected " + std::to_string(want));
}

}  // namespace

ImageRGBA8 makeImageRGBA8(int width, int height) {
  ImageRGBA8 img;
  img.width = width;
  img.height = height;
  img.px.assign(size_t(width) * size_t(height) * 4, 0);
  return img;
}

ImageRGBf makeImageRGBf(int width, int height, glm::vec3 fill) {
  ImageRGBf img;
  img.width = width;
  img.height = height;
  img.px.assign(size_t(width) * size_t(height), fill);
  return img;
}

void writePng(const std::string& path, const ImageRGBA8& img) {
  checkSize(path, img.width, img.height, img.px.size(), size_t(img.width) * img.height * 4,
            "writePng");
  if (!stbi_write_png(path.c_str(), img.width, img.height, 4, img.px.data(), img.width * 4))
    throw ImageError("writePng '" + path + "': write failed (directory missing or not writable?)");
}

ImageRGBA8 decodePng(const uint8_t* bytes, size_t size, const std::string& path, int max_side) {
  static const uint8_t kSig[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (size < 8 || std::memcmp(bytes, kSig, 8) != 0)
    throw ImageError("readPng '" + path + "': bad header (not a PNG file)");
  if (size > size_t(std::numeric_limits<int>::max()))
    throw ImageError("readPng '" + path + "': file too large");
  // The header's dimensions, checked before stb_image allocates and inflates anything.
  int w = 0, h = 0, n = 0;
  if (!stbi_info_from_memory(bytes, int(size), &w, &h, &n)) {
    const char* why = stbi_failure_reason();
    throw ImageError("readPng '" + path + "': corrupt or truncated PNG (" +
                     (why ? why : "unknown") + ")");
  }
  if (w <= 0 || h <= 0 || w > max_side || h > max_side) {
    throw ImageError("readPng '" + path + "': " + std::to_string(w) + "x" + std::to_string(h) +
                     " outside 1.." + std::to_string(max_side) + " per side (kMaxImageSide)");
  }
  // The compressed data must be able to inflate to the declared pixels (halfvec/core/png_bound.hpp)
  // before stb_image allocates them.
  if (const std::string why = pngDataShortfall(bytes, size); !why.empty()) {
    throw ImageError("readPng '" + path + "': " + why);
  }
  int dw = 0, dh = 0;
  stbi_uc* data = stbi_load_from_memory(bytes, int(size), &dw, &dh, &n, 4);
  if (!data || dw != w || dh != h) {
    if (data) stbi_image_free(data);
    const char* why = stbi_failure_reason();
    throw ImageError("readPng '" + path + "': corrupt or truncated PNG (" +
                     (why ? why : "unknown") + ")");
  }
  ImageRGBA8 img = makeImageRGBA8(w, h);
  std::memcpy(img.px.data(), data, img.px.size());
  stbi_image_free(data);
  return img;
}

ImageRGBA8 readPng(const std::string& path) {
  // A PNG's compressed data is smaller than its raw pixels (plus a little per row): a bound.
  const uint64_t max_bytes = uint64_t(kMaxImageSide) * kMaxImageSide * 4 * 2 + (1 << 20);
  const std::vector<uint8_t> bytes = readFileBytes(path, "readPng", max_bytes);
  return decodePng(bytes.data(), bytes.size(), path);
}

void writePfm(const std::string& path, const ImageRGBf& img) {
  checkSize(path, img.width, img.height, img.px.size(), size_t(img.width) * img.height, "writePfm");
  std::ofstream f(path, std::ios::binary);
  if (!f) throw ImageError("writePfm '" + path + "': cannot open for writing");
  // Negative scale = little-endian samples; we always write little-endian.
  f << "PF\n" << img.width << " " << img.height << "\n-1.0\n";
  std::vector<float> row(size_t(img.width) * 3);
  for (int y = img.height - 1; y >= 0; --y) {  // PFM rows run bottom to top
    for (int x = 0; x < img.width; ++x) {
      const glm::vec3& p = img.at(x, y);
      for (int c = 0; c < 3; ++c) {
        uint32_t u = std::bit_cast<uint32_t>(p[c]);
        if constexpr (std::endian::native == std::endian::big) u = __builtin_bswap32(u);
        row[size_t(x) * 3 + c] = std::bit_cast<float>(u);
      }
    }
    f.write(reinterpret_cast<const char*>(row.data()), std::streamsize(row.size() * 4));
  }
  if (!f) throw ImageError("writePfm '" + path + "': write failed");
}

ImageRGBf readPfm(const std::string& path) {
  const uint64_t max_bytes = uint64_t(kMaxImageSide) * kMaxImageSide * 12 + 1024;
  const std::vector<uint8_t> bytes = readFileBytes(path, "readPfm", max_bytes);
  return decodePfm(bytes.data(), bytes.size(), path);
}

ImageRGBf decodePfm(const uint8_t* data, size_t size, const std::string& path, int max_side) {
  const std::span<const uint8_t> bytes(data, size);
  // Header: three whitespace-separated tokens ("PF"/"Pf", "W H", scale), then exactly one
  // whitespace byte before the raster.
  size_t pos = 0;
  auto token = [&]() -> std::string {
    while (pos < bytes.size() && std::isspace(bytes[pos])) ++pos;
    size_t start = pos;
    while (pos < bytes.size() && !std::isspace(bytes[pos]) && pos - start < 64) ++pos;
    return std::string(bytes.begin() + long(start), bytes.begin() + long(pos));
  };
  std::string magic = token();
  if (magic != "PF" && magic != "Pf")
    throw ImageError("readPfm '" + path + "': bad header (magic '" + magic.substr(0, 8) +
                     "', expected PF or Pf)");
  const int channels = magic == "PF" ? 3 : 1;
  std::string ws = token(), hs = token(), ss = token();
  long w = 0, h = 0;
  double scale = 0.0;
  try {
    size_t used = 0;
    w = std::stol(ws, &used);
    if (used != ws.size()) throw std::invalid_argument("w");
    h = std::stol(hs, &used);
    if (used != hs.size()) throw std::invalid_argument("h");
    scale = std::stod(ss, &used);
    if (used != ss.size()) throw std::invalid_argument("scale");
  } catch (const std::exception&) {
    throw ImageError("readPfm '" + path + "': bad header (dimensions/scale '" + ws + " " + hs +
                     " " + ss + "')");
  }
  if (w <= 0 || h <= 0 || w > max_side || h > max_side || scale == 0.0 || !std::isfinite(scale))
    throw ImageError("readPfm '" + path + "': bad header (size " + std::to_string(w) + "x" +
                     std::to_string(h) + ", scale " + ss + ")");
  if (pos >= bytes.size() || !std::isspace(bytes[pos]))
    throw ImageError("readPfm '" + path + "': truncated header");
  ++pos;
  const size_t count = size_t(w) * size_t(h) * size_t(channels);
  if (bytes.size() - pos < count * 4)
    throw ImageError("readPfm '" + path + "': truncated (" + std::to_string(bytes.size() - pos) +
                     " raster bytes, expected " + std::to_string(count * 4) + ")");
  const bool file_little = scale < 0.0;
  const bool swap = file_little != (std::endian::native == std::endian::little);
  ImageRGBf img = makeImageRGBf(int(w), int(h));
  const uint8_t* src = bytes.data() + pos;
  for (long row = 0; row < h; ++row) {
    const int y = int(h - 1 - row);
    for (long x = 0; x < w; ++x) {
      glm::vec3 p;
      for (int c = 0; c < channels; ++c) {
        uint32_t u;
        std::memcpy(&u, src, 4);
        src += 4;
        if (swap) u = __builtin_bswap32(u);
        p[c] = std::bit_cast<float>(u);
      }
      if (channels == 1) p = glm::vec3(p.x);
      img.at(int(x), y) = p;
    }
  }
  return img;
}

ImageRGBA8 toSrgb8(const ImageRGBf& img, float exposure) {
  ImageRGBA8 out = makeImageRGBA8(img.width, img.height);
  for (size_t i = 0; i < img.px.size(); ++i) {
    glm::vec3 v = img.px[i] * exposure;
    uint8_t* o = &out.px[i * 4];
    if (std::isnan(v.x) || std::isnan(v.y) || std::isnan(v.z)) {
      o[0] = 255, o[1] = 0, o[2] = 255, o[3] = 255;
      continue;
    }
    for (int c = 0; c < 3; ++c) {
      float x = std::clamp(v[c], 0.0f, 1.0f);
      float s = x <= 0.0031308f ? 12.92f * x : 1.055f * std::pow(x, 1.0f / 2.4f) - 0.055f;
      o[c] = uint8_t(std::lround(s * 255.0f));
    }
    o[3] = 255;
  }
  return out;
}

}  // namespace hv
