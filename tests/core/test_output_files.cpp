// Outputs that appear whole or not at all (halfvec/core/output_files.hpp).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include <signal.h>
#include <sys/stat.h>
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

namespace {

// A private character device with the numbers of `like` (/dev/null, /dev/full), made with mknod
// in `dir`; "" (and the reason in `why`) where that is not possible.
fs::path privateDevice(const fs::path& dir, const char* like, std::string& why) {
  if (::geteuid() != 0) {
    why = "mknod of a character device needs root";
    return {};
  }
  struct stat st {};
  if (::stat(like, &st) != 0 || !S_ISCHR(st.st_mode)) {
    why = std::string("no ") + like;
    return {};
  }
  const fs::path p = dir / fs::path(like).filename();
  if (::mknod(p.c_str(), S_IFCHR | 0600, st.st_rdev) != 0) {
    why = "mknod refused here (a container without CAP_MKNOD?)";
    return {};
  }
  return p;
}

bool isCharDevice(const fs::path& p) {
  struct stat st {};
  return ::lstat(p.c_str(), &st) == 0 && S_ISCHR(st.st_mode);
}

bool has(const std::string& s, const std::string& what) {
  return s.find(what) != std::string::npos;
}

}  // namespace

// Regression: `--out /dev/full` replaced the device node with a regular file, exit 0. A character
// device is written directly (its node stays), and a failed device write fails the commit
// before any file was replaced.
TEST(OutputFiles, CharacterDevicesAreWrittenNotReplaced) {
  const fs::path d = freshDir("device");
  std::string why;
  const fs::path null_dev = privateDevice(d, "/dev/null", why);
  if (null_dev.empty()) GTEST_SKIP() << why;
  writeFileAtomic(null_dev, "discarded");
  EXPECT_TRUE(isCharDevice(null_dev)) << "the device node was replaced";
  EXPECT_EQ(entries(d), 1u) << "a temporary was left beside the device";

  const fs::path full_dev = privateDevice(d, "/dev/full", why);
  if (full_dev.empty()) GTEST_SKIP() << why;
  writeFileAtomic(d / "image.png", "good");
  std::string err;
  try {
    OutputFiles out;
    out.write(d / "image.png", "new");
    out.write(full_dev, "no room");
    out.commit();
  } catch (const OutputError& e) {
    err = e.what();
  }
  EXPECT_TRUE(has(err, full_dev.string()) && has(err, "No space left")) << err;
  EXPECT_TRUE(isCharDevice(full_dev));
  EXPECT_EQ(slurp(d / "image.png"), "good") << "a file was replaced although a device failed";
  EXPECT_EQ(entries(d), 3u) << "a temporary was left";  // image.png, null, full
}

TEST(OutputFiles, FifoFolderAndSocketDestinationsAreRefused) {
  const fs::path d = freshDir("special");
  ASSERT_EQ(::mkfifo((d / "pipe.png").c_str(), 0600), 0);
  OutputFiles out;
  std::string err;
  try {
    out.add(d / "pipe.png");
  } catch (const OutputError& e) {
    err = e.what();
  }
  EXPECT_TRUE(has(err, "pipe.png") && has(err, "FIFO")) << err;
  fs::create_directory(d / "folder.png");
  EXPECT_THROW(out.add(d / "folder.png"), OutputError);
  EXPECT_EQ(entries(d), 2u);
}

// A symlink destination: the file it names is replaced, the link stays a link.
TEST(OutputFiles, SymlinkDestinationReplacesItsTarget) {
  const fs::path d = freshDir("symlink");
  writeFileAtomic(d / "real.png", "old");
  fs::create_symlink(d / "real.png", d / "link.png");
  writeFileAtomic(d / "link.png", "new");
  EXPECT_TRUE(fs::is_symlink(d / "link.png"));
  EXPECT_EQ(slurp(d / "real.png"), "new");
}

// Regression: `render scene.json --out scene.json` overwrote the scene. An output that is an input
// (the same path, a hard link or a symlink of it) is refused when added, either order.
TEST(OutputFiles, AnInputCannotBeAnOutput) {
  const fs::path d = freshDir("inputs");
  writeFileAtomic(d / "scene.json", "{}");
  fs::create_hard_link(d / "scene.json", d / "hard.json");
  fs::create_symlink(d / "scene.json", d / "soft.json");
  for (const char* name : {"scene.json", "hard.json", "soft.json", "./scene.json"}) {
    OutputFiles out;
    out.protectInput(d / "scene.json");
    std::string err;
    try {
      out.add(d / name);
    } catch (const OutputError& e) {
      err = e.what();
    }
    EXPECT_TRUE(has(err, "is also an input")) << name << ": " << err;
  }
  {
    OutputFiles out;  // output first, then the input
    out.add(d / "hard.json");
    EXPECT_THROW(out.protectInput(d / "scene.json"), OutputError);
  }
  OutputFiles out;
  out.protectInput(d / "scene.json");
  out.protectInput(d / "missing.json");  // ignored: reading it fails
  out.write(d / "other.json", "x");
  out.commit();
  EXPECT_EQ(slurp(d / "scene.json"), "{}");
  EXPECT_EQ(slurp(d / "other.json"), "x");
}

// Regression: every SIGKILL left a ".NAME.XXXXXX" temporary beside the output, never cleaned up.
// A run killed outright cannot remove its temporaries, but its lock on them goes with it: the
// next run writing the same destination removes them, and never one a live run holds.
TEST(OutputFilesDeathTest, AKilledRunsTemporaryIsRemovedByTheNext) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  const fs::path d = freshDir("killed");
  writeFileAtomic(d / "image.png", "good");
  EXPECT_EXIT(
      {
        OutputFiles out;
        out.write(d / "image.png", "half-writ");
        ::raise(SIGKILL);
      },
      ::testing::KilledBySignal(SIGKILL), "");
  ASSERT_EQ(entries(d), 2u) << "the killed run left no temporary (nothing to test)";
  {
    OutputFiles live;  // a run in progress on the same destination: its temporary is kept
    live.write(d / "image.png", "in progress");
    OutputFiles next;
    next.write(d / "image.png", "next");  // removes the killed run's temporary only
    EXPECT_EQ(entries(d), 3u);            // image.png, live's and next's temporaries
    next.commit();
  }
  EXPECT_EQ(slurp(d / "image.png"), "next");
  EXPECT_EQ(entries(d), 1u);
  // An unrelated dot file with a similar name is not touched.
  std::ofstream(d / ".image.png.backup", std::ios::binary) << "mine";
  writeFileAtomic(d / "image.png", "again");
  EXPECT_EQ(slurp(d / ".image.png.backup"), "mine");
}
