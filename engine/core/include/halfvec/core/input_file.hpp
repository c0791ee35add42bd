// Input files read as hostile (docs/hostile-input.md): a path given by a user may name a
// directory, a FIFO (opening it for reading blocks until a writer comes), a character device such
// as /dev/zero (endless) or a file that grows while it is read. Every loader reads through these
// functions: the path must name a regular file after symlinks, its size is checked against the
// loader's documented limit before anything is read, and reading stops at that limit.
#pragma once

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>

namespace hv {

// Thrown when an input cannot be read; the message starts with the path ("x.json: is a FIFO ...").
// Loaders rethrow it as their own error type (SceneError, ImageError, IblError).
struct InputError : std::runtime_error {
  InputError(const std::string& path, const std::string& why)
      : std::runtime_error(path + ": " + why), reason(why) {}
  std::string reason;  // the message without the path, for loaders with their own style
};

// Checks that `path` names a regular file (symlinks followed) of at most `max_bytes` and returns
// its size. `limit_name` names the limit in the message ("kMaxSceneFileBytes"). The file is
// opened without blocking (a FIFO is reported, not waited on) and closed again; for readers that
// open the file themselves.
uint64_t checkInputFile(const std::filesystem::path& path, uint64_t max_bytes,
                        std::string_view limit_name);

// Reads the whole regular file at `path` (checked as by checkInputFile); a file that grows past
// `max_bytes` while it is read is an error, so no more than max_bytes + 1 bytes are ever held.
std::string readInputFile(const std::filesystem::path& path, uint64_t max_bytes,
                          std::string_view limit_name);

// Line and column (both from 1; the column counts bytes) of byte `offset` in `text`.
struct TextPosition {
  size_t line = 1, column = 1;
};
TextPosition textPosition(std::string_view text, size_t offset);

// The offset of the first '[' or '{' that opens level max_depth + 1 of `text` read as JSON
// (strings and their escapes skipped), or std::string_view::npos when the nesting stays within
// max_depth. Lets a loader bound nesting before a recursive parser, converter or printer sees it.
size_t jsonNestingBeyond(std::string_view text, int max_depth);

}  // namespace hv
