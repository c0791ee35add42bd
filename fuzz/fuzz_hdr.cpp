// libFuzzer harness: Radiance .hdr files, at most 2048 pixels wide (the limit is a parameter of
// the same check; 16384 would make single inputs decode 1.5 GiB).
#include <cstdint>

#include "halfvec/ibl/ibl.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    hv::decodeHdr(data, size, "fuzz.hdr", 2048);
  } catch (const hv::IblError&) {
  }
  return 0;
}
