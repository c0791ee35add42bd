#include "halfvec/core/output_files.hpp"

#include <fcntl.h>
#include <limits.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <mutex>
#include <system_error>

namespace hv {

namespace fs = std::filesystem;

namespace {

std::string why() {
  return std::strerror(errno);
}

// ---- Temporaries removed when a signal ends the process ----
// A run interrupted by Ctrl-C (SIGINT), SIGTERM, SIGHUP or a closed pipe (SIGPIPE: `halfvec ... |
// head`) never reaches commit() or the destructors, which would leave its temporary files (hidden,
// half written) beside the destinations. Every live temporary is registered in a fixed table of
// path buffers that the handler can read without allocating; the handler unlinks them
// (async-signal-safe), then the signal takes its default action (SA_RESETHAND, re-raised), so the
// process still ends as the signal says. Installed only for signals whose disposition is the
// default (a program that handles or ignores one keeps its own).
constexpr size_t kTemporarySlots = 64;  // more live temporaries are not protected
struct TemporarySlot {
  std::atomic<int> state{0};  // 0 free, 1 being filled, 2 registered
  char path[PATH_MAX] = {};
};
std::array<TemporarySlot, kTemporarySlots> g_temporaries;
constexpr int kCleanupSignals[] = {SIGINT, SIGTERM, SIGHUP, SIGPIPE};

extern "C" void removeTemporariesAndDie(int sig) {
  for (TemporarySlot& slot : g_temporaries) {
    if (slot.state.load(std::memory_order_acquire) == 2) ::unlink(slot.path);
  }
  ::raise(sig);  // delivered when the handler returns, with the default action (SA_RESETHAND)
}

void installCleanupHandlers() {
  static std::once_flag once;
  std::call_once(once, [] {
    for (int sig : kCleanupSignals) {
      struct sigaction old {};
      if (::sigaction(sig, nullptr, &old) != 0 || old.sa_handler != SIG_DFL) continue;
      struct sigaction sa {};
      sa.sa_handler = removeTemporariesAndDie;
      sigemptyset(&sa.sa_mask);
      sa.sa_flags = SA_RESETHAND;
      ::sigaction(sig, &sa, nullptr);
    }
  });
}

// The slot holding `path`, or -1 when the table is full or the path too long.
int registerTemporary(const fs::path& path) {
  installCleanupHandlers();
  const std::string s = path.string();
  if (s.size() >= PATH_MAX) return -1;
  for (size_t i = 0; i < g_temporaries.size(); ++i) {
    int expected = 0;
    if (g_temporaries[i].state.compare_exchange_strong(expected, 1)) {
      std::memcpy(g_temporaries[i].path, s.c_str(), s.size() + 1);
      g_temporaries[i].state.store(2, std::memory_order_release);
      return int(i);
    }
  }
  return -1;
}

void unregisterTemporary(int slot) {
  if (slot >= 0) g_temporaries[size_t(slot)].state.store(0, std::memory_order_release);
}

// Creates a new, empty file "<dir>/.<name>.<random>.tmp" beside `destination` (O_EXCL, so two
// runs never share one) and returns its path.
fs::path createTemporary(const fs::path& destination) {
  const fs::path dir = destination.has_parent_path() ? destination.parent_path() : fs::path(".");
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) {
    throw OutputError(destination.string() + ": cannot write: folder " + dir.string() +
                      " does not exist");
  }
  if (fs::is_directory(destination, ec)) {
    throw OutputError(destination.string() + ": cannot write: it is a folder");
  }
  std::string name = destination.filename().string();
  name.insert(name.begin(), '.');
  name.append(".XXXXXX");
  const std::string pattern = (dir / name).string();
  std::vector<char> buf(pattern.begin(), pattern.end());
  buf.push_back('\0');
  const int fd = ::mkstemp(buf.data());
  if (fd < 0) throw OutputError(destination.string() + ": cannot write: " + why());
  // mkstemp creates 0600; give the file the permissions a plain open() would (0666 - umask).
  const mode_t mask = ::umask(0);
  ::umask(mask);
  ::fchmod(fd, 0666 & ~mask);
  ::close(fd);
  return fs::path(buf.data());
}

}  // namespace

OutputFiles::~OutputFiles() {
  for (const File& f : files_) {
    std::error_code ec;
    fs::remove(f.temporary, ec);
    unregisterTemporary(f.slot);
  }
}

fs::path OutputFiles::add(const fs::path& destination) {
  const fs::path abs = fs::absolute(destination).lexically_normal();
  for (const File& f : files_) {
    if (f.destination == abs) {
      throw OutputError(destination.string() + ": named twice as an output of one run");
    }
  }
  const fs::path tmp = createTemporary(abs);
  files_.push_back({abs, tmp, registerTemporary(tmp)});
  return files_.back().temporary;
}

void OutputFiles::write(const fs::path& destination, std::string_view bytes) {
  const fs::path tmp = add(destination);
  std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), std::streamsize(bytes.size()));
  out.flush();
  if (!out) throw OutputError(destination.string() + ": cannot write: " + why());
}

void OutputFiles::commit() {
  for (const File& f : files_) {
    std::error_code ec;
    if (!fs::exists(f.temporary, ec)) {
      throw OutputError(f.destination.string() + ": its temporary file " + f.temporary.string() +
                        " vanished before it was renamed");
    }
  }
  std::vector<File> pending = std::move(files_);
  files_.clear();
  for (size_t i = 0; i < pending.size(); ++i) {
    std::error_code ec;
    fs::rename(pending[i].temporary, pending[i].destination, ec);
    if (ec) {
      // Keep the rest for the destructor to clean up.
      files_.assign(pending.begin() + std::ptrdiff_t(i), pending.end());
      throw OutputError(pending[i].destination.string() + ": cannot rename " +
                        pending[i].temporary.string() + " over it: " + ec.message());
    }
    unregisterTemporary(pending[i].slot);
  }
}

void writeFileAtomic(const fs::path& path, std::string_view bytes) {
  OutputFiles out;
  out.write(path, bytes);
  out.commit();
}

}  // namespace hv
