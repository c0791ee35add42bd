// Replays the committed hostile and fuzzer-found inputs of tests/fuzz/png and tests/fuzz/pfm:
// each must decode or be rejected with an ImageError naming the file.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "halfvec/image/image.hpp"

namespace fs = std::filesystem;

TEST(FuzzInputs, PngAndPfmFiles) {
  int files = 0, decoded = 0;
  for (const char* target : {"png", "pfm"}) {
    for (const auto& e :
         fs::directory_iterator(fs::path(HV_SOURCE_DIR) / "tests" / "fuzz" / target)) {
      ++files;
      try {
        if (e.path().extension() == ".png") {
          hv::readPng(e.path().string());
        } else {
          hv::readPfm(e.path().string());
        }
        ++decoded;
      } catch (const hv::ImageError& err) {
        EXPECT_NE(std::string(err.what()).find(e.path().string()), std::string::npos) << err.what();
      }
    }
  }
  EXPECT_GT(files, 0);
  EXPECT_EQ(decoded, 1) << "only rgb_4x3.png is a valid file";
}
