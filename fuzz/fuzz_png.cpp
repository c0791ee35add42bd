// libFuzzer harness: PNG files, at most 4096 pixels per side (the limit is a parameter of the
// same check; stb_image allocates the declared size before it finds the data short).
#include <cstdint>

#include "halfvec/image/image.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    hv::decodePng(data, size, "fuzz.png", 4096);
  } catch (const hv::ImageError&) {
  }
  return 0;
}
