// Inputs read as hostile (halfvec/core/input_file.hpp): a FIFO, a device, a directory or a file
// over the limit is reported by what it is, before anything is read, and reading never goes past
// the limit (a scene path symlinked to /dev/zero grew past 3.9 GB; a FIFO hung).
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>

#include "halfvec/core/input_file.hpp"

namespace fs = std::filesystem;
using namespace hv;

namespace {

fs::path freshDir(const std::string& name) {
  const fs::path d =
      fs::temp_directory_path() / ("hv_input_file_test_" + std::to_string(::getpid())) / name;
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

// The message of readInputFile(path), "" when it succeeds.
std::string readError(const fs::path& path, uint64_t limit = 1 << 20) {
  try {
    readInputFile(path, limit, "kTestLimit");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

bool has(const std::string& s, const std::string& what) {
  return s.find(what) != std::string::npos;
}

}  // namespace

TEST(InputFile, ReadsARegularFileWhole) {
  const fs::path d = freshDir("regular");
  std::ofstream(d / "a.json", std::ios::binary) << "{\"x\": 1}";
  EXPECT_EQ(readInputFile(d / "a.json", 100, "kTestLimit"), "{\"x\": 1}");
  EXPECT_EQ(checkInputFile(d / "a.json", 100, "kTestLimit"), 8u);
  fs::create_symlink(d / "a.json", d / "link.json");  // a symlink to a file is followed
  EXPECT_EQ(readInputFile(d / "link.json", 100, "kTestLimit"), "{\"x\": 1}");
}

TEST(InputFile, MissingAndDirectoryAreNamed) {
  const fs::path d = freshDir("missing");
  std::string e = readError(d / "nope.json");
  EXPECT_TRUE(has(e, (d / "nope.json").string()) && has(e, "no such file")) << e;
  e = readError(d);
  EXPECT_TRUE(has(e, d.string()) && has(e, "is a directory")) << e;
}

TEST(InputFile, SizeLimitCheckedBeforeReading) {
  const fs::path d = freshDir("limit");
  std::ofstream(d / "big.json", std::ios::binary) << std::string(101, ' ');
  const std::string e = readError(d / "big.json", 100);
  EXPECT_TRUE(has(e, "101 bytes exceed the limit of 100") && has(e, "kTestLimit")) << e;
  EXPECT_EQ(readError(d / "big.json", 101), "");
}

// A FIFO with no writer: opening it for reading would block forever; it is reported at once.
TEST(InputFile, FifoIsRefusedWithoutBlocking) {
  const fs::path d = freshDir("fifo");
  ASSERT_EQ(::mkfifo((d / "scene.json").c_str(), 0600), 0);
  const auto t0 = std::chrono::steady_clock::now();
  const std::string e = readError(d / "scene.json");
  EXPECT_LT(std::chrono::steady_clock::now() - t0, std::chrono::seconds(2));
  EXPECT_TRUE(has(e, "is a FIFO (named pipe), not a regular file")) << e;
}

// /dev/zero is endless: through a symlink it must be refused, not read until memory runs out.
TEST(InputFile, SymlinkToDevZeroIsRefused) {
  if (!fs::exists("/dev/zero")) GTEST_SKIP() << "no /dev/zero";
  const fs::path d = freshDir("zero");
  fs::create_symlink("/dev/zero", d / "scene.json");
  const std::string e = readError(d / "scene.json", uint64_t(64) << 20);
  EXPECT_TRUE(has(e, (d / "scene.json").string()) && has(e, "is a character device")) << e;
}

// A private character device (the numbers of /dev/null, made with mknod): refused as an input.
TEST(InputFile, CharacterDeviceIsRefused) {
  if (::geteuid() != 0) GTEST_SKIP() << "mknod of a character device needs root";
  const fs::path d = freshDir("chardev");
  struct stat null_st {};
  ASSERT_EQ(::stat("/dev/null", &null_st), 0);
  if (::mknod((d / "dev.png").c_str(), S_IFCHR | 0600, null_st.st_rdev) != 0) {
    GTEST_SKIP() << "mknod refused here (a container without CAP_MKNOD?)";
  }
  const std::string e = readError(d / "dev.png");
  EXPECT_TRUE(has(e, "is a character device")) << e;
}

TEST(InputFile, TextPositionCountsLinesAndColumnsFromOne) {
  const std::string_view t = "ab\ncde\n\nf";
  EXPECT_EQ(textPosition(t, 0).line, 1u);
  EXPECT_EQ(textPosition(t, 0).column, 1u);
  EXPECT_EQ(textPosition(t, 4).line, 2u);  // 'd'
  EXPECT_EQ(textPosition(t, 4).column, 2u);
  EXPECT_EQ(textPosition(t, 8).line, 4u);  // 'f'
  EXPECT_EQ(textPosition(t, 8).column, 1u);
}

TEST(InputFile, JsonNestingBeyondSkipsStrings) {
  EXPECT_EQ(jsonNestingBeyond("[[[]]]", 3), std::string_view::npos);
  EXPECT_EQ(jsonNestingBeyond("[[[[]]]]", 3), 3u);
  EXPECT_EQ(jsonNestingBeyond(R"({"a": "[[[[\"[[[["})", 1), std::string_view::npos);
  EXPECT_EQ(jsonNestingBeyond(std::string(100000, '['), 64), 64u);
}
