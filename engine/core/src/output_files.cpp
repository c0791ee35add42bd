#include "halfvec/core/output_files.hpp"

#include <fcntl.h>
#include <limits.h>
#include <signal.h>
#include <sys/file.h>
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

// Temporaries are named "<dir>/.<name>.hv-XXXXXX.tmp" and held under an exclusive flock(2) by the
// process writing them until they are renamed or removed. A run killed by SIGKILL (or a crash)
// cannot remove its temporaries, but the kernel drops its locks: a later run writing the same
// destination removes every temporary of that destination that nobody holds.
constexpr std::string_view kTemporaryTag = ".hv-";
constexpr std::string_view kTemporarySuffix = ".tmp";
constexpr size_t kTemporaryRandom = 6;  // mkstemps' XXXXXX

bool isTemporaryOf(const std::string& entry, const std::string& name) {
  const size_t want =
      1 + name.size() + kTemporaryTag.size() + kTemporaryRandom + kTemporarySuffix.size();
  return entry.size() == want && entry[0] == '.' && entry.compare(1, name.size(), name) == 0 &&
         entry.compare(1 + name.size(), kTemporaryTag.size(), kTemporaryTag) == 0 &&
         entry.compare(entry.size() - kTemporarySuffix.size(), kTemporarySuffix.size(),
                       kTemporarySuffix) == 0;
}

// Removes the temporaries of `destination` that no live process holds (left by a killed run).
void removeStaleTemporaries(const fs::path& destination) {
  const fs::path dir = destination.parent_path();
  const std::string name = destination.filename().string();
  std::error_code ec;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string entry = it->path().filename().string();
    if (!isTemporaryOf(entry, name)) continue;
    const int fd = ::open(it->path().c_str(), O_RDONLY | O_NOFOLLOW | O_CLOEXEC | O_NONBLOCK);
    if (fd < 0) continue;
    struct stat st {};
    if (::fstat(fd, &st) == 0 && S_ISREG(st.st_mode) && ::flock(fd, LOCK_EX | LOCK_NB) == 0) {
      ::unlink(it->path().c_str());  // unlocked: its writer is gone
    }
    ::close(fd);
  }
}

// Creates a new, empty, locked temporary file beside `destination` (in `dir`; O_EXCL, so two runs
// never share one) and returns its path and the descriptor holding the lock.
fs::path createTemporary(const fs::path& destination, const fs::path& dir, int& lock_fd) {
  std::string name = destination.filename().string();
  name.insert(name.begin(), '.');
  name.append(kTemporaryTag);
  name.append(kTemporaryRandom, 'X');
  name.append(kTemporarySuffix);
  const std::string pattern = (dir / name).string();
  for (int attempt = 0; attempt < 16; ++attempt) {
    std::vector<char> buf(pattern.begin(), pattern.end());
    buf.push_back('\0');
    const int fd = ::mkstemps(buf.data(), int(kTemporarySuffix.size()));
    if (fd < 0) throw OutputError(destination.string() + ": cannot write: " + why());
    ::fcntl(fd, F_SETFD, FD_CLOEXEC);
    // Between mkstemps and flock another run may have found the file unlocked and removed it:
    // then it has no link left, and another name is tried.
    struct stat st {};
    if (::flock(fd, LOCK_EX) != 0 || ::fstat(fd, &st) != 0 || st.st_nlink == 0) {
      ::close(fd);
      continue;
    }
    // mkstemp creates 0600; give the file the permissions a plain open() would (0666 - umask).
    const mode_t mask = ::umask(0);
    ::umask(mask);
    ::fchmod(fd, 0666 & ~mask);
    lock_fd = fd;
    return fs::path(buf.data());
  }
  throw OutputError(destination.string() + ": cannot create a temporary file beside it");
}

// The file type of `st` in the words of an error message.
std::string kindOf(const struct stat& st) {
  if (S_ISDIR(st.st_mode)) return "a folder";
  if (S_ISFIFO(st.st_mode)) return "a FIFO (named pipe)";
  if (S_ISSOCK(st.st_mode)) return "a socket";
  if (S_ISBLK(st.st_mode)) return "a block device";
  if (S_ISCHR(st.st_mode)) return "a character device";
  return "not a regular file";
}

// Copies the temporary `from` into the character device `device` (opened without O_CREAT: it
// must still be a character device). Throws OutputError naming the device.
void copyToDevice(const fs::path& from, const fs::path& device) {
  const int in = ::open(from.c_str(), O_RDONLY | O_CLOEXEC);
  if (in < 0) throw OutputError(device.string() + ": cannot read its temporary file: " + why());
  const int out = ::open(device.c_str(), O_WRONLY | O_NOCTTY | O_CLOEXEC);
  struct stat st {};
  if (out < 0 || ::fstat(out, &st) != 0 || !S_ISCHR(st.st_mode)) {
    const std::string msg = out < 0 ? why() : "no longer a character device";
    ::close(in);
    if (out >= 0) ::close(out);
    throw OutputError(device.string() + ": cannot write: " + msg);
  }
  std::vector<char> buf(1 << 16);
  std::string error;
  for (;;) {
    const ssize_t n = ::read(in, buf.data(), buf.size());
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      error = why();
      break;
    }
    if (n == 0) break;
    for (ssize_t done = 0; done < n;) {
      const ssize_t w = ::write(out, buf.data() + done, size_t(n - done));
      if (w < 0 && errno == EINTR) continue;
      if (w <= 0) {
        error = w < 0 ? why() : "short write";
        break;
      }
      done += w;
    }
    if (!error.empty()) break;
  }
  ::close(in);
  if (::close(out) != 0 && error.empty()) error = why();
  if (!error.empty()) throw OutputError(device.string() + ": cannot write: " + error);
}

}  // namespace

OutputFiles::~OutputFiles() {
  for (const File& f : files_) {
    std::error_code ec;
    fs::remove(f.temporary, ec);
    unregisterTemporary(f.slot);
    if (f.lock_fd >= 0) ::close(f.lock_fd);
  }
}

void OutputFiles::protectInput(const fs::path& input) {
  struct stat st {};
  if (::stat(input.c_str(), &st) != 0) return;  // a missing input fails where it is read
  for (const File& f : files_) {
    struct stat out {};
    if (::stat(f.destination.c_str(), &out) == 0 && out.st_dev == st.st_dev &&
        out.st_ino == st.st_ino) {
      throw OutputError(f.named.string() + ": is also an input of this command (" + input.string() +
                        "); write the output to another file");
    }
  }
  inputs_.push_back({input, uint64_t(st.st_dev), uint64_t(st.st_ino)});
}

fs::path OutputFiles::add(const fs::path& destination) {
  fs::path abs = fs::absolute(destination).lexically_normal();
  std::error_code ec;
  // A symlink is followed: the file it names is replaced, the link stays.
  if (fs::exists(abs, ec)) {
    const fs::path real = fs::canonical(abs, ec);
    if (!ec) abs = real;
  }
  for (const File& f : files_) {
    if (f.destination == abs) {
      throw OutputError(destination.string() + ": named twice as an output of one run");
    }
  }
  const fs::path dir = abs.parent_path();
  if (!fs::is_directory(dir, ec)) {
    throw OutputError(destination.string() + ": cannot write: folder " + dir.string() +
                      " does not exist");
  }
  struct stat st {};
  bool device = false;
  if (::stat(abs.c_str(), &st) == 0) {
    for (const Input& in : inputs_) {
      if (uint64_t(st.st_dev) == in.dev && uint64_t(st.st_ino) == in.ino) {
        throw OutputError(destination.string() + ": is also an input of this command (" +
                          in.path.string() + "); write the output to another file");
      }
    }
    if (S_ISDIR(st.st_mode)) {
      throw OutputError(destination.string() + ": cannot write: it is a folder");
    }
    // A character device (/dev/null, /dev/stdout on a terminal) is written directly at commit,
    // as a shell redirection would; renaming over it would replace the device node with a file.
    // A FIFO, socket or block device is refused: waiting for a reader, or overwriting a disk.
    device = S_ISCHR(st.st_mode);
    if (!device && !S_ISREG(st.st_mode)) {
      throw OutputError(destination.string() + ": cannot write: it is " + kindOf(st) +
                        "; an output must be a regular file (or a character device such as "
                        "/dev/null)");
    }
  }
  // A device's contents wait in the temporary folder, not in /dev.
  const fs::path tmp_dir = device ? fs::temp_directory_path(ec) : dir;
  if (!device) removeStaleTemporaries(abs);
  int lock_fd = -1;
  const fs::path tmp = createTemporary(abs, tmp_dir, lock_fd);
  files_.push_back({abs, destination, tmp, registerTemporary(tmp), lock_fd, device});
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
  // Devices first: writing one can fail (/dev/full: no space), and then no file was replaced.
  for (File& f : files_) {
    if (!f.device) continue;
    copyToDevice(f.temporary, f.destination);
    std::error_code ec;
    fs::remove(f.temporary, ec);
  }
  std::vector<File> pending;
  for (File& f : files_) {
    if (f.device) {
      unregisterTemporary(f.slot);
      if (f.lock_fd >= 0) ::close(f.lock_fd);
    } else {
      pending.push_back(f);
    }
  }
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
    if (pending[i].lock_fd >= 0) ::close(pending[i].lock_fd);
  }
}

void writeFileAtomic(const fs::path& path, std::string_view bytes) {
  OutputFiles out;
  out.write(path, bytes);
  out.commit();
}

}  // namespace hv
