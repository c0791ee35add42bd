#include "halfvec/core/png_bound.hpp"

#include <algorithm>
#include <cstring>

namespace hv {
namespace {

uint32_t be32(const uint8_t* p) {
  return uint32_t(p[0]) << 24 | uint32_t(p[1]) << 16 | uint32_t(p[2]) << 8 | uint32_t(p[3]);
}

constexpr uint32_t chunkType(const char (&s)[5]) {
  return uint32_t(uint8_t(s[0])) << 24 | uint32_t(uint8_t(s[1])) << 16 |
         uint32_t(uint8_t(s[2])) << 8 | uint32_t(uint8_t(s[3]));
}

}  // namespace

std::string pngDataShortfall(const uint8_t* bytes, size_t size) {
  static const uint8_t kSig[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (size < 8 || std::memcmp(bytes, kSig, 8) != 0) return "";
  uint64_t width = 0, height = 0, bits = 0, idat = 0;
  bool header = false;
  // Each chunk: length (4 bytes, big-endian), type (4), data (length), CRC (4).
  for (size_t at = 8; size - at >= 8;) {
    const uint64_t len = be32(bytes + at);
    const uint32_t type = be32(bytes + at + 4);
    const size_t data = at + 8;
    const uint64_t present = std::min<uint64_t>(len, size - data);
    if (type == chunkType("IHDR") && present >= 13 && !header) {
      width = be32(bytes + data);
      height = be32(bytes + data + 4);
      const uint64_t depth = bytes[data + 8];
      const int color = bytes[data + 9];  // 0 gray, 2 RGB, 3 palette, 4 gray + alpha, 6 RGBA
      const uint64_t channels = color == 0 || color == 3 ? 1
                                : color == 2             ? 3
                                : color == 4             ? 2
                                : color == 6             ? 4
                                                         : 0;
      bits = depth * channels;
      header = true;
    } else if (type == chunkType("IDAT")) {
      idat += present;
    } else if (type == chunkType("IEND")) {
      break;
    }
    if (len + 4 > size - data) break;  // the chunk (and its CRC) runs past the end
    at = data + size_t(len) + 4;
  }
  // Dimensions beyond 2^24 are left to the decoder's size check (and keep the product in range).
  if (!header || bits == 0 || width == 0 || height == 0 || width > (1u << 24) ||
      height > (1u << 24)) {
    return "";
  }
  const uint64_t scanlines = height * (1 + (width * bits + 7) / 8);
  if (scanlines <= kDeflateMaxRatio * idat) return "";
  return std::to_string(width) + "x" + std::to_string(height) + " pixels of " +
         std::to_string(bits) + " bits need " + std::to_string(scanlines) +
         " bytes of scanlines, more than the " + std::to_string(kDeflateMaxRatio) + " x " +
         std::to_string(idat) +
         " bytes its IDAT chunks can inflate to (truncated or not a valid PNG)";
}

}  // namespace hv
