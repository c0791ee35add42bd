// Replays the committed hostile and fuzzer-found inputs of tests/fuzz/hdr: each must decode or
// be rejected with an IblError naming the file. Two decode: mixed_rle_flat.hdr (the reader's
// scanline forms) and sky_with_sun.hdr (the seed of findHdrSun's paths: a one-texel sun).
#include <gtest/gtest.h>

#include <filesystem>

#include "halfvec/ibl/hdr_sun.hpp"
#include "halfvec/ibl/ibl.hpp"

namespace fs = std::filesystem;

TEST(FuzzInputs, HdrFiles) {
  int files = 0, decoded = 0;
  for (const auto& e : fs::directory_iterator(fs::path(HV_SOURCE_DIR) / "tests" / "fuzz" / "hdr")) {
    ++files;
    try {
      const hv::ImageRGBf img = hv::loadHdr(e.path().string());
      const std::string name = e.path().filename().string();
      if (name == "mixed_rle_flat.hdr") {
        // Row 1 is flat: pixel x = (x + 2, x + 3, x + 4) * 2^(130 - 136).
        EXPECT_EQ(img.at(5, 1), glm::vec3(7, 8, 9) / 64.0f);
      } else if (name == "sky_with_sun.hdr") {
        const hv::HdrSun sun = hv::findHdrSun(img);
        EXPECT_TRUE(sun.found);
        EXPECT_EQ(sun.texels.size(), 1u);
      } else {
        ADD_FAILURE() << name << " decodes: say here what it must hold";
      }
      ++decoded;
    } catch (const hv::IblError& err) {
      EXPECT_NE(std::string(err.what()).find(e.path().string()), std::string::npos) << err.what();
    }
  }
  EXPECT_GT(files, 0);
  EXPECT_EQ(decoded, 2);
}
