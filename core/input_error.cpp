#include "core/input_error.hpp"

#include "core/error.hpp"

#include <fmt/format.h>

namespace dartcheck {

static std::string position(const std::string& file, int line, int column) {
  if (line <= 0) return file;
  return column > 0 ? fmt::format("{}:{}:{}", file, line, column) : fmt::format("{}:{}", file, line);
}

// The length of the UTF-8 sequence starting at s[k], 0 if it is not one.
static std::size_t utf8_length(std::string_view s, std::size_t k) {
  const auto b = static_cast<unsigned char>(s[k]);
  const std::size_t n = b < 0x80 ? 1 : (b >> 5) == 0x6 ? 2 : (b >> 4) == 0xe ? 3 : (b >> 3) == 0x1e ? 4 : 0;
  if (n == 0 || k + n > s.size()) return 0;
  for (std::size_t j = 1; j < n; ++j)
    if ((static_cast<unsigned char>(s[k + j]) >> 6) != 0x2) return 0;
  return n;
}

// Tab and newline pass: multi-line messages (a term's known profiles) use them.
std::string printable(std::string_view text) {
  std::string out;
  for (std::size_t k = 0; k < text.size();) {
    const auto b = static_cast<unsigned char>(text[k]);
    const std::size_t n = utf8_length(text, k);
    if ((b < 0x20 && b != '\t' && b != '\n') || b == 0x7f || n == 0) {
      out += fmt::format("\\x{:02x}", b);
      ++k;
    } else {
      out.append(text.substr(k, n));
      k += n;
    }
  }
  return out;
}

// Messages may quote the input: they are made printable here, once for all.
InputError::InputError(std::string file, int line, int column, const std::string& message)
    : Error(printable(position(file, line, column)) + ": " + printable(message)),
      file_(std::move(file)),
      message_(printable(message)),
      line_(line),
      column_(column) {}

InputErrors::InputErrors(std::vector<InputError> all, bool stopped) : InputError(all.at(0)), all_(std::move(all)), stopped_(stopped) {}

std::string InputError::diagnostic() const { return dartcheck::diagnostic("error", printable(file_), line_, column_, message_); }

std::string diagnostic(std::string_view severity, std::string_view file, int line, int column, std::string_view message) {
  if (file.empty() || file == command_line) return fmt::format("dartcheck: {}: {}", severity, message);
  return fmt::format("{}: {}: {}", position(std::string(file), line, column), severity, message);
}

std::string SourceLocation::str() const { return fmt::format("{}:{}:{}", file, line, column); }

}  // namespace dartcheck
