// Hostile command lines (issue 18): --size parsed strictly, and outputs that appear whole or not
// at all (render, reference): an output that cannot be written fails the command, before the
// render, and leaves none of that run's outputs, nor a temporary file.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "app/cli.hpp"

namespace fs = std::filesystem;

namespace {

fs::path freshDir(const std::string& name) {
  const fs::path d =
      fs::temp_directory_path() / ("hv_cli_hostile_" + std::to_string(::getpid())) / name;
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

std::string scene() {
  return std::string(HV_SAMPLES_DIR) + "/default.json";
}

int run(const std::vector<std::string>& args, std::string* err = nullptr) {
  testing::internal::CaptureStderr();
  testing::internal::CaptureStdout();
  const int rc = hv::app::runCli(args);
  testing::internal::GetCapturedStdout();
  const std::string e = testing::internal::GetCapturedStderr();
  if (err) *err = e;
  return rc;
}

size_t filesIn(const fs::path& dir) {
  size_t n = 0;
  for (const auto& e : fs::recursive_directory_iterator(dir)) n += e.is_regular_file();
  return n;
}

}  // namespace

TEST(CliHostile, SizeIsParsedStrictly) {
  for (const char* bad : {"64x36junk", "64x", "x36", "64 x36", "+64x36", "64x-36", "0x36",
                          "16385x1", "99999999999x1", "64X36", "64x36x2", ""}) {
    std::string err;
    EXPECT_EQ(run({"render", scene(), "--size", bad}, &err), 2) << bad;
    EXPECT_NE(err.find("--size"), std::string::npos) << err;
  }
}

// Every integer option of every command: the whole value, decimal, in range; trailing text,
// an empty value or an overflow is a usage error (status 2) naming the option, before any work.
TEST(CliHostile, IntegerOptionsAreParsedStrictly) {
  const std::vector<std::vector<std::string>> commands = {{"render", scene(), "--frames"},
                                                          {"view", scene(), "--frames"},
                                                          {"bench", "--frames"},
                                                          {"bench", "--max-lights"},
                                                          {"bench", "--lights"},
                                                          {"reference", scene(), "--samples"},
                                                          {"reference", scene(), "--threads"},
                                                          {"stability", "--size"},
                                                          {"accuracy", "--threads"},
                                                          {"ltc-fit", "--size"},
                                                          {"ltc-fit", "--cap-samples"},
                                                          {"trade", scene(), "--frames"}};
  for (const auto& c : commands) {
    for (const char* bad : {"5abc", "", "-1", "99999999999999999999", "1.5", " 5", "\xd9\xa5"}) {
      std::vector<std::string> args = c;
      args.push_back(bad);
      // Options are parsed in order: were the value taken, the command would still stop here
      // (and the assertions below fail) instead of rendering, fitting or writing docs.
      args.push_back("--zzzz-not-an-option");
      std::string err;
      EXPECT_EQ(run(args, &err), 2) << args[0] << " " << c.back() << " '" << bad << "'";
      EXPECT_NE(err.find(c.back() + " expects an integer in"), std::string::npos) << err;
    }
  }
}

// The real-valued options of ltc-fit: the whole value a number in range (not NaN, not a prefix of
// the string), else a usage error naming the option before anything is fitted.
TEST(CliHostile, NumberOptionsAreParsedStrictly) {
  for (const char* option : {"--power", "--cap-weight"}) {
    for (const char* bad : {"abc", "", "2x", "nan", "inf", "-1", "1e9", " 3"}) {
      std::string err;
      EXPECT_EQ(run({"ltc-fit", option, bad, "--zzzz-not-an-option"}, &err), 2)
          << option << " '" << bad << "'";
      EXPECT_NE(err.find(std::string(option) + " expects a number in"), std::string::npos) << err;
    }
  }
  // compare's tolerances (>= 0) and trade's bounds (> 0) parse the same way.
  const std::vector<std::vector<std::string>> others = {
      {"compare", "a.pfm", "b.pfm", "--max-abs"},
      {"compare", "a.pfm", "b.pfm", "--heatmap-max"},
      {"trade", "--max-error"},
      {"trade", "--max-ms"},
      {"reference", scene(), "--ao-distance"}};
  for (const auto& c : others) {
    for (const char* bad : {"abc", "", "2x", "nan", " 3", "-1"}) {
      std::vector<std::string> args = c;
      args.push_back(bad);
      args.push_back("--zzzz-not-an-option");
      std::string err;
      EXPECT_EQ(run(args, &err), 2) << c.back() << " '" << bad << "'";
      EXPECT_NE(err.find(c.back() + " expects a number in"), std::string::npos) << err;
    }
  }
  std::string err;
  EXPECT_EQ(run({"trade", "--max-ms", "0", "--zzzz-not-an-option"}, &err), 2);
  EXPECT_NE(err.find("--max-ms expects a number in"), std::string::npos) << err;
  // reference's --visibility takes on or off, nothing else.
  for (const char* bad : {"yes", "", "ON", "1"}) {
    err.clear();
    EXPECT_EQ(run({"reference", scene(), "--visibility", bad, "--zzzz-not-an-option"}, &err), 2);
    EXPECT_NE(err.find("--visibility expects on or off, got '" + std::string(bad) + "'"),
              std::string::npos)
        << err;
  }
}

TEST(CliHostile, UnwritableOutputFailsBeforeRenderingAndLeavesNothing) {
  const fs::path dir = freshDir("unwritable");
  const fs::path png = dir / "ok.png";
  std::string err;
  // --stats into a folder that does not exist: exit 1 naming it, no PNG written.
  EXPECT_EQ(run({"render", scene(), "--size", "32x18", "--out", png.string(), "--stats",
                 (dir / "missing" / "stats.json").string()},
                &err),
            1);
  EXPECT_NE(err.find("stats.json"), std::string::npos) << err;
  EXPECT_FALSE(fs::exists(png));
  // --hdr where a file stands in for the folder: the PNG asked for beside it is not left behind.
  std::ofstream(dir / "afile") << "x";
  EXPECT_EQ(run({"render", scene(), "--size", "32x18", "--out", png.string(), "--hdr",
                 (dir / "afile" / "x.pfm").string()},
                &err),
            1);
  EXPECT_NE(err.find("x.pfm"), std::string::npos) << err;
  EXPECT_FALSE(fs::exists(png));
  // --aov into a path that cannot be a folder.
  EXPECT_EQ(run({"render", scene(), "--size", "32x18", "--out", png.string(), "--aov",
                 (dir / "afile").string()}),
            1);
  EXPECT_FALSE(fs::exists(png));
  // reference, the same (it would otherwise render for minutes first).
  EXPECT_EQ(run({"reference", scene(), "--size", "8x8", "--hdr", png.string() + ".pfm", "--out",
                 (dir / "missing" / "ref.png").string()}),
            1);
  EXPECT_FALSE(fs::exists(png.string() + ".pfm"));
  EXPECT_EQ(filesIn(dir), 1u) << "only 'afile': no temporary files";
}

TEST(CliHostile, AllOutputsOfASuccessfulRunAndNoTemporaries) {
  const fs::path dir = freshDir("ok");
  std::ofstream(dir / "old.png") << "previous contents";
  ASSERT_EQ(run({"render", scene(), "--size", "32x18", "--out", (dir / "old.png").string(), "--hdr",
                 (dir / "a.pfm").string(), "--stats", (dir / "s.json").string()}),
            0);
  EXPECT_GT(fs::file_size(dir / "old.png"), 100u);  // replaced whole
  EXPECT_TRUE(fs::exists(dir / "a.pfm"));
  EXPECT_TRUE(fs::exists(dir / "s.json"));
  EXPECT_EQ(filesIn(dir), 3u);
}
