// Files dartcheck writes: one way to write them, and one error when that
// fails (a full device, a directory that cannot be created, a closed
// pipe), so that no command reports success for a result it lost.
#pragma once

#include <cstddef>
#include <functional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/error.hpp"

namespace dartcheck {

/// An output that could not be written: names the file and the reason.
/// The command line handler turns it into exit status 4.
class OutputError : public Error {
 public:
  OutputError(std::string file, const std::string& reason);
  const std::string& file() const { return file_; }

 private:
  std::string file_;
};

/// Writes `bytes` to `path` (replacing it) atomically: to a temporary file
/// in the same directory, flushed, synced and renamed over the target, so a
/// failed or interrupted write leaves the previous file as it was and no
/// temporary behind (a device or FIFO is written in place). Throws
/// OutputError if any step fails.
void write_file(const std::string& path, std::string_view bytes);

namespace detail {
/// Test-only: called with the bytes written so far after each chunk of a
/// write_file (a test stops a writer part way through).
extern std::function<void(std::size_t)> write_hook;
}  // namespace detail

/// Creates `dir` and its parents if needed; OutputError if it cannot be or
/// is not a directory. Commands call it before their work starts.
void ensure_directory(const std::string& dir);

/// Checks before the work starts that `path` can be written: its directory
/// exists and is writable. OutputError otherwise.
void check_writable(const std::string& path);

/// Refuses (InputError at the command line) two outputs of one run that
/// name one file, after resolving `.`, `..` and links: the second would
/// overwrite the first. Each entry is (option, path); empty paths are unset.
void check_distinct_outputs(const std::vector<std::pair<std::string, std::string>>& outputs);

}  // namespace dartcheck
