// Output files that appear whole or not at all. Every file a command writes goes first to a
// temporary file in its destination folder and is renamed over the destination only when it is
// complete, so an interrupted or failed run never leaves a truncated file where a good one was.
// OutputFiles groups the outputs of one run: nothing is renamed until every one was written, and
// a run that fails (an exception, an unwritable folder) leaves none of its outputs behind, and
// one ended by SIGINT, SIGTERM, SIGHUP or SIGPIPE none of its temporary files (a handler removes
// them, then the signal ends the process as it would have; installed only where the signal's
// disposition is the default). A run killed outright (SIGKILL) leaves its temporaries
// (".NAME.hv-XXXXXX.tmp"); the next run writing NAME removes them.
#pragma once

#include <cstdint>
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

  // Declares `input` (a file the run reads) off limits: add() refuses a destination that is the
  // same file, by its path, a hard link or a symlink (the same device and inode), and so does
  // this call for an output already added. An input that does not exist is ignored (reading it
  // fails). Call it for every input before adding the outputs, so the run fails before its work.
  void protectInput(const std::filesystem::path& input);

  // Reserves `destination`: creates (empty) a temporary file beside it and returns its path, to
  // be written by any writer (writePng, std::ofstream, ...). Creating it checks at once that the
  // folder exists and is writable, so a run can fail before its expensive part. A symlink is
  // followed (the file it names is replaced). The destination must be a regular file or nothing:
  // a folder, FIFO, socket or block device is refused; a character device (/dev/null) is written
  // directly by commit(), its temporary kept in the temporary folder. Temporaries of the same
  // destination left by a killed run (their writer gone: unlocked) are removed first. Throws
  // OutputError naming the destination otherwise, when it was already added, or when it is an
  // input (protectInput).
  std::filesystem::path add(const std::filesystem::path& destination);
  // Writes `bytes` to the temporary file of a new output `destination` (add + write).
  void write(const std::filesystem::path& destination, std::string_view bytes);
  // Writes the character devices (a failed write, as to /dev/full, throws before any file is
  // replaced), then renames every temporary file over its destination, in the order added.
  // Throws OutputError if a temporary file is missing, a device write or a rename fails;
  // destinations renamed before a failed rename are then already in place (renames within one
  // folder fail only when the folder changed under us).
  void commit();

  size_t size() const { return files_.size(); }

 private:
  struct File {
    std::filesystem::path destination;  // absolute, symlinks resolved
    std::filesystem::path named;        // as given, for messages
    std::filesystem::path temporary;
    int slot = -1;        // its entry in the table the signal handler cleans up (-1: none)
    int lock_fd = -1;     // holds the temporary's flock while this run owns it
    bool device = false;  // a character device: written directly by commit()
  };
  struct Input {
    std::filesystem::path path;
    uint64_t dev = 0, ino = 0;
  };
  std::vector<File> files_;
  std::vector<Input> inputs_;
};

// One output written whole: `bytes` to a temporary file beside `path`, then renamed over it.
// Throws OutputError naming the file.
void writeFileAtomic(const std::filesystem::path& path, std::string_view bytes);

}  // namespace hv
