// libFuzzer harness: Radiance .hdr files, at most 2048 pixels wide (the limit is a parameter of
// the same check; 16384 would make single inputs decode 1.5 GiB), and what the engine does with
// a decoded image before baking it: find its sun and take it out (halfvec/ibl/hdr_sun.hpp).
#include <cstdint>

#include "halfvec/ibl/hdr_sun.hpp"
#include "halfvec/ibl/ibl.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    hv::ImageRGBf img = hv::decodeHdr(data, size, "fuzz.hdr", 2048);
    hv::removeHdrSun(img, hv::findHdrSun(img));
  } catch (const hv::IblError&) {
  }
  return 0;
}
