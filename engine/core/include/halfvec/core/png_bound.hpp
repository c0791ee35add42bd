// What a PNG file's compressed image data can decode to, checked from its chunks before any
// decoder allocates the pixels its header declares. Used by the PNG reader (halfvec/image) and the
// glTF loader's image decoding (halfvec/scene).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace hv {

// Deflate (RFC 1951) expands at most about 1032:1: its longest match, 258 bytes, takes at least 2
// bits. The PNG's filtered scanlines (one filter byte, then ceil(width x bits per pixel / 8) bytes
// per row) all come from the IDAT chunks' zlib stream, so a file whose IDAT bytes x 1032 fall
// short of them is truncated or hostile: an 81-byte file declaring 4096 x 4096 pixels of 16-bit
// RGBA would otherwise have stb_image allocate 128 MiB before it finds the data missing.
constexpr uint64_t kDeflateMaxRatio = 1032;

// "" when `bytes` is not a PNG (no signature or IHDR: the decoder reports that), or when its IDAT
// chunks can inflate to the scanlines of its IHDR; otherwise why not, e.g. "4096x4096 pixels of
// 64 bits need 134,221,824 bytes of scanlines, more than the 1032 x 12 bytes its IDAT chunks can
// inflate to (truncated or not a valid PNG)". Chunks are read up to the end of `bytes`; one that
// runs past it counts its bytes present.
std::string pngDataShortfall(const uint8_t* bytes, size_t size);

}  // namespace hv
