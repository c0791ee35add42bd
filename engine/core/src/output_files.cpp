#include "halfvec/core/output_files.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <system_error>

namespace hv {

namespace fs = std::filesystem;

namespace {

std::string why() {
  return std::strerror(errno);
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
  }
}

fs::path OutputFiles::add(const fs::path& destination) {
  const fs::path abs = fs::absolute(destination).lexically_normal();
  for (const File& f : files_) {
    if (f.destination == abs) {
      throw OutputError(destination.string() + ": named twice as an output of one run");
    }
  }
  files_.push_back({abs, createTemporary(abs)});
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
  }
}

void writeFileAtomic(const fs::path& path, std::string_view bytes) {
  OutputFiles out;
  out.write(path, bytes);
  out.commit();
}

}  // namespace hv
