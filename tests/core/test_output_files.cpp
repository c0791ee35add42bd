// Outputs that appear whole or not at all (halfvec/core/output_files.hpp).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include <signal.h>
#include <unistd.h>

#include "halfvec/core/output_files.hpp"

namespace fs = std::filesystem;
using namespace hv;

namespace {

fs::path freshDir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / "hv_output_files_test" / name;
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

size_t entries(const fs::path& dir) {
  return size_t(std::distance(fs::directory_iterator(dir), fs::directory_iterator()));
}

}  // namespace

TEST(OutputFiles, CommitRenamesEveryOutputInPlace) {
  const fs::path d = freshDir("commit");
  {
    OutputFiles out;
    out.write(d / "a.txt", "alpha");
    const fs::path tmp = out.add(d / "b.bin");
    std::ofstream(tmp, std::ios::binary) << "beta";
    EXPECT_FALSE(fs::exists(d / "a.txt"));  // nothing visible before commit
    EXPECT_FALSE(fs::exists(d / "b.bin"));
    out.commit();
  }
  EXPECT_EQ(slurp(d / "a.txt"), "alpha");
  EXPECT_EQ(slurp(d / "b.bin"), "beta");
  EXPECT_EQ(entries(d), 2u);  // no temporary left
}

// A run that fails before commit leaves the previous outputs untouched and no temporary files.
TEST(OutputFiles, UncommittedRunLeavesTheOldFilesAndNoTemporaries) {
  const fs::path d = freshDir("fail");
  writeFileAtomic(d / "image.png", "good");
  try {
    OutputFiles out;
    out.write(d / "image.png", "half-writ");
    out.add(d / "missing-folder" / "stats.json");  // throws: the run fails here
    FAIL() << "add into a missing folder must throw";
  } catch (const OutputError& e) {
    EXPECT_NE(std::string(e.what()).find("stats.json"), std::string::npos) << e.what();
  }
  EXPECT_EQ(slurp(d / "image.png"), "good");
  EXPECT_EQ(entries(d), 1u);
}

TEST(OutputFiles, UnwritableDestinationsFailAtAdd) {
  const fs::path d = freshDir("unwritable");
  OutputFiles out;
  EXPECT_THROW(out.add(d / "no" / "such" / "dir.png"), OutputError);
  EXPECT_THROW(out.add(d), OutputError);  // a folder
  out.add(d / "x.pfm");
  EXPECT_THROW(out.add(d / "." / "x.pfm"), OutputError);  // the same file twice
  if (::geteuid() != 0) {                                 // root writes into read-only folders
    const fs::path ro = freshDir("readonly");
    fs::permissions(ro, fs::perms::owner_read | fs::perms::owner_exec);
    EXPECT_THROW(out.add(ro / "x.png"), OutputError);
    fs::permissions(ro, fs::perms::owner_all);
  }
}

// A run ended by a signal before commit (Ctrl-C, kill, a closed pipe as in `halfvec ... | head`)
// leaves the previous outputs untouched and none of its temporary files, and still ends by that
// signal. (Found when a killed `halfvec ltc-fit` left hidden .ltc_table.cpp.XXXXXX files.)
TEST(OutputFilesDeathTest, ASignalRemovesTheTemporaries) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  for (int sig : {SIGINT, SIGTERM, SIGHUP, SIGPIPE}) {
    struct sigaction now {};
    ::sigaction(sig, nullptr, &now);
    if (now.sa_handler == SIG_IGN) continue;  // ignored by whoever started the tests: not ours
    const fs::path d = freshDir("signal" + std::to_string(sig));
    writeFileAtomic(d / "image.png", "good");
    EXPECT_EXIT(
        {
          OutputFiles out;
          out.write(d / "image.png", "half-writ");
          out.write(d / "stats.json", "{");
          ::raise(sig);
          std::exit(0);  // not reached: the signal ends the process
        },
        ::testing::KilledBySignal(sig), "");
    EXPECT_EQ(slurp(d / "image.png"), "good") << "signal " << sig;
    EXPECT_EQ(entries(d), 1u) << "signal " << sig << ": a temporary file was left";
  }
}
