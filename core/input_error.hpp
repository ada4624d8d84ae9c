// Errors in user input, always with the file position and what was
// expected (GUIDE: bad input gets file:line:column and a non-zero exit).
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "core/error.hpp"
#include "core/formatting.hpp"

namespace dartcheck {

/// The file name of errors in the command's arguments and options.
inline constexpr std::string_view command_line = "<command line>";

/// A diagnostic line in gcc's style, which editors and CI problem matchers
/// read: "file:line:column: SEVERITY: message" ("file:line:" without a
/// column, "file:" without a line), or "dartcheck: SEVERITY: message" when
/// the file is empty or the command line. `severity` is error, warning or
/// note; the message is written as given (make it printable first).
std::string diagnostic(std::string_view severity, std::string_view file, int line, int column, std::string_view message);

class InputError : public Error {
 public:
  /// `line` and `column` are 1-based; 0 means unknown. what() is
  /// "file:line:column: message".
  InputError(std::string file, int line, int column, const std::string& message);
  const std::string& file() const { return file_; }
  int line() const { return line_; }
  int column() const { return column_; }
  /// The message without its position (printable).
  const std::string& message() const { return message_; }
  /// As dartcheck prints it: diagnostic("error", ...).
  std::string diagnostic() const;

 private:
  std::string file_, message_;
  int line_, column_;
};

/// An error in the command's arguments and options (a bad --strategy, two
/// outputs naming one file), which a library reports without knowing the
/// command: an InputError at command_line, printed "dartcheck: error: ..."
/// and exit 2 as every input error.
class UsageError : public InputError {
 public:
  explicit UsageError(const std::string& message) : InputError(std::string(command_line), 0, 0, message) {}
};

/// Several errors of one input, for a reader that goes on after an error
/// where the rest does not depend on what failed (a catalog's maps and
/// rules, each on its own), up to a bound. It is the first of them, so a
/// caller that wants one error sees that one; all() lists them in order.
class InputErrors : public InputError {
 public:
  explicit InputErrors(std::vector<InputError> all, bool stopped);
  const std::vector<InputError>& all() const { return all_; }
  /// Whether the reader stopped at the bound, with more input unread.
  bool stopped() const { return stopped_; }

 private:
  std::vector<InputError> all_;
  bool stopped_;
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

// fmt::format("{}", x) prints x.str() (core/formatting.hpp).
template <>
inline constexpr bool formatted_by_str<SourceLocation> = true;

}  // namespace dartcheck
