#include "halfvec/core/input_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

namespace hv {

namespace {

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& msg) {
  throw InputError(path.string(), msg);
}

// What a path names when it is not a regular file, in the words of the error message.
std::string kindOf(mode_t mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISFIFO(mode)) return "a FIFO (named pipe)";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

class Fd {
 public:
  explicit Fd(int fd) : fd_(fd) {}
  Fd(const Fd&) = delete;
  Fd& operator=(const Fd&) = delete;
  ~Fd() {
    if (fd_ >= 0) ::close(fd_);
  }
  int get() const { return fd_; }
  void reset(int fd) {
    if (fd_ >= 0) ::close(fd_);
    fd_ = fd;
  }

 private:
  int fd_;
};

// Opens `path` for reading and checks it is a regular file within the limit; returns the size.
// O_NONBLOCK: opening a FIFO for reading would otherwise wait for a writer (forever).
uint64_t openChecked(const std::filesystem::path& path, uint64_t max_bytes,
                     std::string_view limit_name, Fd& out) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
  if (fd < 0) {
    const int err = errno;
    if (err == ENOENT) fail(path, "cannot open: no such file");
    if (err == ENOTDIR) fail(path, "cannot open: no such file (a folder in the path is a file)");
    if (err == ENXIO) fail(path, "is not a regular file (a device or socket without a reader)");
    fail(path, std::string("cannot open: ") + std::strerror(err));
  }
  out.reset(fd);
  struct stat st {};
  if (::fstat(fd, &st) != 0) fail(path, std::string("cannot read: ") + std::strerror(errno));
  if (!S_ISREG(st.st_mode)) {
    const std::string kind = kindOf(st.st_mode);
    fail(path, (kind == "not a regular file" ? kind : "is " + kind + ", not a regular file") +
                   " (an input must be a file)");
  }
  const uint64_t size = uint64_t(st.st_size);
  if (size > max_bytes) {
    fail(path, std::to_string(size) + " bytes exceed the limit of " + std::to_string(max_bytes) +
                   " (" + std::string(limit_name) + ")");
  }
  return size;
}

}  // namespace

uint64_t checkInputFile(const std::filesystem::path& path, uint64_t max_bytes,
                        std::string_view limit_name) {
  Fd fd(-1);
  return openChecked(path, max_bytes, limit_name, fd);
}

std::string readInputFile(const std::filesystem::path& path, uint64_t max_bytes,
                          std::string_view limit_name) {
  Fd fd(-1);
  const uint64_t size = openChecked(path, max_bytes, limit_name, fd);
  // Back to blocking reads: a regular file never blocks, and EAGAIN would only complicate the loop.
  const int flags = ::fcntl(fd.get(), F_GETFL);
  if (flags >= 0) ::fcntl(fd.get(), F_SETFL, flags & ~O_NONBLOCK);
  std::string out;
  out.resize(size_t(std::min<uint64_t>(size, max_bytes)));
  size_t have = 0;
  for (;;) {
    if (have == out.size()) {
      if (out.size() > max_bytes) break;  // grew past the limit: reported below
      // The file may have grown since fstat: read on, one byte past the limit at most.
      out.resize(
          size_t(std::min<uint64_t>(max_bytes + 1, std::max<uint64_t>(out.size() * 2, 4096))));
      if (have == out.size()) break;
    }
    const ssize_t n = ::read(fd.get(), out.data() + have, out.size() - have);
    if (n < 0) {
      if (errno == EINTR) continue;
      fail(path, std::string("cannot read: ") + std::strerror(errno));
    }
    if (n == 0) break;
    have += size_t(n);
  }
  if (have > max_bytes) {
    fail(path, "grew past the limit of " + std::to_string(max_bytes) +
                   " bytes while it was read (" + std::string(limit_name) + ")");
  }
  out.resize(have);
  return out;
}

TextPosition textPosition(std::string_view text, size_t offset) {
  offset = std::min(offset, text.size());
  TextPosition p;
  const std::string_view before = text.substr(0, offset);
  p.line = 1 + size_t(std::count(before.begin(), before.end(), '\n'));
  const size_t line_start = before.rfind('\n');
  p.column = offset - (line_start == std::string_view::npos ? 0 : line_start + 1) + 1;
  return p;
}

size_t jsonNestingBeyond(std::string_view text, int max_depth) {
  int depth = 0;
  bool in_string = false, escape = false;
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (in_string) {
      if (escape) {
        escape = false;
      } else if (c == '\\') {
        escape = true;
      } else if (c == '"') {
        in_string = false;
      }
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      if (++depth > max_depth) return i;
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
  return std::string_view::npos;
}

}  // namespace hv
