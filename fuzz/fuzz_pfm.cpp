// libFuzzer harness: PFM files (the raster must be in the file, so no size limit is lowered).
#include <cstdint>

#include "halfvec/image/image.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    hv::decodePfm(data, size, "fuzz.pfm");
  } catch (const hv::ImageError&) {
  }
  return 0;
}
