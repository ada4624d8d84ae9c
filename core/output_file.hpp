// Files dartcheck writes: one way to write them, and one error when that
// fails (a full device, a directory that cannot be created, a closed
// pipe), so that no command reports success for a result it lost.
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>

namespace dartcheck {

/// An output that could not be written: names the file and the reason.
/// The command line handler turns it into exit status 4.
class OutputError : public std::runtime_error {
 public:
  OutputError(std::string file, const std::string& reason);
  const std::string& file() const { return file_; }

 private:
  std::string file_;
};

/// Writes `bytes` to `path` (replacing it), flushes and closes it; throws
/// OutputError if any step fails.
void write_file(const std::string& path, std::string_view bytes);

/// Creates `dir` and its parents if needed; OutputError if it cannot be or
/// is not a directory. Commands call it before their work starts.
void ensure_directory(const std::string& dir);

/// Checks before the work starts that `path` can be written: its directory
/// exists and is writable. OutputError otherwise.
void check_writable(const std::string& path);

}  // namespace dartcheck
