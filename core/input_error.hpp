// Errors in user input, always with the file position and what was
// expected (GUIDE: bad input gets file:line:column and a non-zero exit).
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>

namespace dartcheck {

class InputError : public std::runtime_error {
 public:
  /// `line` and `column` are 1-based; 0 means unknown.
  InputError(std::string file, int line, int column, const std::string& message);
  const std::string& file() const { return file_; }
  int line() const { return line_; }
  int column() const { return column_; }

 private:
  std::string file_;
  int line_, column_;
};

/// `text` with control characters and bytes that are not UTF-8 written as
/// \xNN, so that a binary file's bytes never reach a terminal.
std::string printable(std::string_view text);

/// Where something was read: file, 1-based line and column (0 = unknown).
struct SourceLocation {
  std::string file;
  int line = 0, column = 0;
  /// "file:line:column"
  std::string str() const;
};

}  // namespace dartcheck
