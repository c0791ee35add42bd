// Output files that appear whole or not at all. Every file a command writes goes first to a
// temporary file in its destination folder and is renamed over the destination only when it is
// complete, so an interrupted or failed run never leaves a truncated file where a good one was.
// OutputFiles groups the outputs of one run: nothing is renamed until every one was written, and
// a run that fails (an exception, an unwritable folder) leaves none of its outputs behind, and
// one ended by SIGINT, SIGTERM, SIGHUP or SIGPIPE none of its temporary files (a handler removes
// them, then the signal ends the process as it would have; installed only where the signal's
// disposition is the default).
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace hv {

// Thrown when an output cannot be created, written or renamed; the message names the file.
struct OutputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class OutputFiles {
 public:
  OutputFiles() = default;
  OutputFiles(const OutputFiles&) = delete;
  OutputFiles& operator=(const OutputFiles&) = delete;
  // Removes the temporary files of outputs that were not committed.
  ~OutputFiles();

  // Reserves `destination`: creates (empty) a temporary file beside it and returns its path, to
  // be written by any writer (writePng, std::ofstream, ...). Creating it checks at once that the
  // folder exists and is writable, so a run can fail before its expensive part. Throws
  // OutputError naming the destination otherwise, or when it was already added.
  std::filesystem::path add(const std::filesystem::path& destination);
  // Writes `bytes` to the temporary file of a new output `destination` (add + write).
  void write(const std::filesystem::path& destination, std::string_view bytes);
  // Renames every temporary file over its destination, in the order added. Throws OutputError if
  // a temporary file is missing or a rename fails; destinations renamed before the failure are
  // then already in place (renames within one folder fail only when the folder changed under us).
  void commit();

  size_t size() const { return files_.size(); }

 private:
  struct File {
    std::filesystem::path destination, temporary;
    int slot = -1;  // its entry in the table the signal handler cleans up (-1: none)
  };
  std::vector<File> files_;
};

// One output written whole: `bytes` to a temporary file beside `path`, then renamed over it.
// Throws OutputError naming the file.
void writeFileAtomic(const std::filesystem::path& path, std::string_view bytes);

}  // namespace hv
