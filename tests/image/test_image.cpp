#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>

#include <unistd.h>

#include "halfvec/image/image.hpp"
#include "halfvec/image/metrics.hpp"

namespace fs = std::filesystem;

namespace {

// A per-process scratch directory, removed at exit.
struct TmpDir {
  fs::path dir = fs::temp_directory_path() / ("hv_test_image_" + std::to_string(::getpid()));
  TmpDir() { fs::create_directories(dir); }
  ~TmpDir() {
    std::error_code ec;
    fs::remove_all(dir, ec);
  }
};

std::string tmpPath(const std::string& name) {
  static TmpDir tmp;
  return (tmp.dir / name).string();
}

void writeBytes(const std::string& path, const std::string& bytes) {
  std::ofstream f(path, std::ios::binary);
  f.write(bytes.data(), std::streamsize(bytes.size()));
}

std::string readBytes(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>());
}

template <class F>
std::string errorOf(F&& f) {
  try {
    f();
  } catch (const hv::ImageError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(Png, RoundTripExact) {
  hv::ImageRGBA8 img = hv::makeImageRGBA8(7, 5);
  for (size_t i = 0; i < img.px.size(); ++i) img.px[i] = uint8_t((i * 37 + 11) & 255);
  const std::string path = tmpPath("rt.png");
  hv::writePng(path, img);
  hv::ImageRGBA8 back = hv::readPng(path);
  ASSERT_EQ(back.width, 7);
  ASSERT_EQ(back.height, 5);
  EXPECT_EQ(back.px, img.px);
}

TEST(Png, Errors) {
  EXPECT_NE(errorOf([] { hv::readPng("/nonexistent/x.png"); }).find("/nonexistent/x.png"),
            std::string::npos);
  const std::string garbage = tmpPath("garbage.png");
  writeBytes(garbage, "this is not a png file at all");
  EXPECT_NE(errorOf([&] { hv::readPng(garbage); }).find("bad header"), std::string::npos);

  hv::ImageRGBA8 img = hv::makeImageRGBA8(64, 64);
  for (size_t i = 0; i < img.px.size(); ++i) img.px[i] = uint8_t((i * 7919) >> 3);
  const std::string good = tmpPath("good.png"), cut = tmpPath("cut.png");
  hv::writePng(good, img);
  std::string bytes = readBytes(good);
  writeBytes(cut, bytes.substr(0, bytes.size() / 2));
  const std::string msg = errorOf([&] { hv::readPng(cut); });
  EXPECT_NE(msg.find("cut.png"), std::string::npos) << msg;
  EXPECT_NE(msg.find("truncated"), std::string::npos) << msg;
}

TEST(Pfm, RoundTripBitExact) {
  hv::ImageRGBf img = hv::makeImageRGBf(5, 3);
  const float specials[] = {0.0f, -0.0f,  1e-38f,      3.4e38f,
                            0.1f, -7.25f, 1.0f / 3.0f, std::numeric_limits<float>::denorm_min()};
  for (size_t i = 0; i < img.px.size(); ++i)
    img.px[i] = glm::vec3(specials[i % 8], float(i) * 0.37f, -float(i) / 7.0f);
  img.px[4].y = std::numeric_limits<float>::infinity();
  const std::string path = tmpPath("rt.pfm");
  hv::writePfm(path, img);
  hv::ImageRGBf back = hv::readPfm(path);
  ASSERT_EQ(back.width, 5);
  ASSERT_EQ(back.height, 3);
  EXPECT_EQ(std::memcmp(back.px.data(), img.px.data(), img.px.size() * sizeof(glm::vec3)), 0);
  // File layout: bottom row first, little-endian, negative scale.
  const std::string bytes = readBytes(path);
  ASSERT_EQ(bytes.rfind("PF\n5 3\n-1.0\n", 0), 0u);
  float first;
  std::memcpy(&first, bytes.data() + std::strlen("PF\n5 3\n-1.0\n"), 4);
  EXPECT_EQ(first, img.at(0, 2).x);
}

TEST(Pfm, BigEndianAndGray) {
  // 2x1 grayscale, big-endian (positive scale): values 1.0 and -2.0.
  std::string s = "Pf\n2 1\n1.0\n";
  const char be[] = {0x3f, char(0x80), 0, 0, char(0xc0), 0, 0, 0};
  s.append(be, 8);
  const std::string path = tmpPath("be.pfm");
  writeBytes(path, s);
  hv::ImageRGBf img = hv::readPfm(path);
  ASSERT_EQ(img.width, 2);
  EXPECT_EQ(img.at(0, 0), glm::vec3(1.0f));
  EXPECT_EQ(img.at(1, 0), glm::vec3(-2.0f));
}

TEST(Pfm, Errors) {
  EXPECT_NE(errorOf([] { hv::readPfm("/nonexistent/y.pfm"); }).find("cannot open"),
            std::string::npos);
  const std::string p1 = tmpPath("bad1.pfm");
  writeBytes(p1, "P6\n2 2\n255\n");
  EXPECT_NE(errorOf([&] { hv::readPfm(p1); }).find("bad header"), std::string::npos);
  writeBytes(p1, "PF\nabc 2\n-1.0\n");
  EXPECT_NE(errorOf([&] { hv::readPfm(p1); }).find("bad header"), std::string::npos);
  writeBytes(p1, "PF\n2 2\n0\n");
  EXPECT_NE(errorOf([&] { hv::readPfm(p1); }).find("bad header"), std::string::npos);
  writeBytes(p1, "PF\n2 2\n-1.0\n" + std::string(47, 'x'));  // 48 bytes needed
  const std::string msg = errorOf([&] { hv::readPfm(p1); });
  EXPECT_NE(msg.find("truncated"), std::string::npos) << msg;
  EXPECT_NE(msg.find("bad1.pfm"), std::string::npos) << msg;
}

TEST(Metrics, HandComputed) {
  // ref: two pixels (1,1,1) and (0,0,0); test: (1,1,3) and (0,0,0.5).
  hv::ImageRGBf ref = hv::makeImageRGBf(2, 1), test = hv::makeImageRGBf(2, 1);
  ref.px = {glm::vec3(1.0f), glm::vec3(0.0f)};
  test.px = {glm::vec3(1.0f, 1.0f, 3.0f), glm::vec3(0.0f, 0.0f, 0.5f)};
  const hv::ErrorMetrics m = hv::compareImages(test, ref);
  // d = {0,0,2, 0,0,0.5}: sum d^2 = 4.25 over 6 -> mse 0.708333.
  const double mse = 4.25 / 6.0;
  EXPECT_NEAR(m.rmse, std::sqrt(mse), 1e-12);
  EXPECT_NEAR(m.rel_rmse, std::sqrt(mse) / 0.5, 1e-12);  // mean |ref| = 3/6
  EXPECT_NEAR(m.mean_abs, 2.5 / 6.0, 1e-12);
  EXPECT_NEAR(m.max_abs, 2.0, 1e-12);
  EXPECT_NEAR(m.psnr, 10.0 * std::log10(1.0 / mse), 1e-9);
  // e0 = 2 / (3 + 0.03), e1 = 0.5 / 0.03; p99 of two values (nearest rank 2) = the larger.
  EXPECT_NEAR(m.p99_rel, 0.5 / 0.03, 1e-9);
  EXPECT_NEAR(hv::relativeError(test.px[0], ref.px[0]), 2.0 / 3.03, 1e-9);
  EXPECT_EQ(m.compared_pixels, 2);
  EXPECT_EQ(m.nonfinite_test, 0);
}

TEST(Metrics, IdenticalAndPercentile) {
  hv::ImageRGBf ref = hv::makeImageRGBf(10, 10, glm::vec3(1.0f));
  hv::ImageRGBf test = ref;
  hv::ErrorMetrics m = hv::compareImages(test, ref);
  EXPECT_EQ(m.rmse, 0.0);
  EXPECT_TRUE(std::isinf(m.psnr));
  // 100 pixels with relative errors 0.01 * i / 1.01 ... use exact offsets: pixel i off by i/100
  // in every channel -> e_i = 3 (i/100) / 3.03; p99 = 99th smallest = pixel 98.
  for (int i = 0; i < 100; ++i) test.px[size_t(i)] += glm::vec3(float(i) / 100.0f);
  m = hv::compareImages(test, ref);
  EXPECT_NEAR(m.p99_rel, 3.0 * double(0.98f) / 3.03, 1e-6);
}

// The robust metrics: one pixel far off among 1999 slightly off carries almost all of the
// squared error (top_share) but little of the mean relative error; spread evenly, the worst 0.1%
// (2 of 2000 pixels) carry 0.1% of it.
TEST(Metrics, MeanRelativeErrorAndTopShare) {
  hv::ImageRGBf ref = hv::makeImageRGBf(2000, 1, glm::vec3(1.0f));
  hv::ImageRGBf test = hv::makeImageRGBf(2000, 1, glm::vec3(1.0625f));  // d = 1/16, exact
  test.px[7] = glm::vec3(17.0f);                                        // d = 16
  hv::ErrorMetrics m = hv::compareImages(test, ref);
  const double e_small = 3.0 * 0.0625 / 3.03, e_big = 48.0 / 3.03;
  EXPECT_NEAR(m.mean_rel, (e_big + 1999.0 * e_small) / 2000.0, 1e-12);
  const double sq_small = 3.0 * 0.0625 * 0.0625, sq_big = 3.0 * 256.0;
  EXPECT_NEAR(m.top_share, (sq_big + sq_small) / (sq_big + 1999.0 * sq_small), 1e-12);
  EXPECT_GT(m.top_share, 0.9);
  EXPECT_LT(m.mean_rel, 0.1);  // while rel_rmse is large:
  EXPECT_GT(m.rel_rmse, 0.3);

  test.px[7] = glm::vec3(1.0625f);
  m = hv::compareImages(test, ref);
  EXPECT_NEAR(m.top_share, 2.0 / 2000.0, 1e-12);
  EXPECT_NEAR(m.mean_rel, e_small, 1e-12);
  EXPECT_EQ(hv::compareImages(ref, ref).top_share, 0.0);
  EXPECT_EQ(hv::compareImages(ref, ref).mean_rel, 0.0);
}

TEST(Metrics, NanCountingAndSizeMismatch) {
  hv::ImageRGBf ref = hv::makeImageRGBf(3, 2, glm::vec3(0.5f)), test = ref;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  test.px[0].y = nan;
  test.px[3].z = std::numeric_limits<float>::infinity();
  ref.px[5].x = nan;
  ref.px[0].x = nan;  // both bad: counted in both
  const hv::ErrorMetrics m = hv::compareImages(test, ref);
  EXPECT_EQ(m.nonfinite_test, 2);
  EXPECT_EQ(m.nonfinite_ref, 2);
  EXPECT_EQ(m.compared_pixels, 3);
  EXPECT_EQ(m.rmse, 0.0);
  const hv::ImageRGBf other = hv::makeImageRGBf(2, 3);
  EXPECT_NE(errorOf([&] { hv::compareImages(other, ref); }).find("sizes differ"),
            std::string::npos);
}

TEST(HeatMap, ColorsAndLegend) {
  EXPECT_NEAR(hv::viridis(0.0f).x, 0.267f, 0.015f);
  EXPECT_NEAR(hv::viridis(0.0f).z, 0.329f, 0.015f);
  EXPECT_NEAR(hv::viridis(1.0f).x, 0.993f, 0.015f);
  EXPECT_NEAR(hv::viridis(1.0f).y, 0.906f, 0.015f);
  EXPECT_NEAR(hv::viridis(1.0f).z, 0.144f, 0.015f);

  hv::ImageRGBf ref = hv::makeImageRGBf(64, 32, glm::vec3(1.0f)), test = ref;
  for (int x = 0; x < 64; ++x)
    for (int y = 0; y < 32; ++y) test.at(x, y) += glm::vec3(float(x) / 63.0f * 0.1f);
  test.at(0, 0).x = std::numeric_limits<float>::quiet_NaN();
  const hv::ImageRGBA8 hm = hv::relativeErrorHeatMap(test, ref, 0.1f);
  EXPECT_EQ(hm.width, 240);
  EXPECT_GT(hm.height, 32 + 20);
  const uint8_t* nanpx = hm.at(0, 0);
  EXPECT_EQ(nanpx[0], 255);
  EXPECT_EQ(nanpx[1], 0);
  EXPECT_EQ(nanpx[2], 255);
  const uint8_t* lo = hm.at(1, 5);  // error ~0.0016 of 0.1 -> dark purple
  EXPECT_GT(lo[2], lo[1]);
  const uint8_t* hi = hm.at(63, 5);  // error 0.1/1.01 -> yellow
  EXPECT_GT(hi[0], 200);
  EXPECT_GT(hi[1], 200);
  // The legend has some white text pixels below the color bar.
  int white = 0;
  for (int y = 32; y < hm.height; ++y)
    for (int x = 0; x < hm.width; ++x) white += hm.at(x, y)[0] == 255 && hm.at(x, y)[2] == 255;
  EXPECT_GT(white, 50);
  hv::writePng(tmpPath("heatmap.png"), hm);
}
