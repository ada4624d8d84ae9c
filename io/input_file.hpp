// Reading an input file: an InputError that names the file when it is
// missing, a directory, a device, unreadable, or larger than
// limits().file_bytes (a stream opened on a directory "succeeds" and fails
// later with the C library's words, without the name; /dev/zero, or a
// symbolic link to it named like a mesh, reads until memory runs out).
#pragma once

#include <cstddef>
#include <fstream>
#include <optional>
#include <string>
#include <string_view>

namespace dartcheck {

std::ifstream open_input(const std::string& file, std::ios::openmode mode = std::ios::in);

/// The whole file, at most limits().file_bytes (--limit-file-bytes); a
/// FIFO is read as it comes, a device is refused.
std::string read_input(const std::string& file);

/// Refuses a text with a NUL byte, at its line and column: `what` names
/// the format ("a YAML file"). A NUL would end a name early in C strings
/// or be read as another character.
void refuse_nul_bytes(const std::string& file, std::string_view text, std::string_view what);

/// The lines of a text held in memory, with their 1-based numbers; a
/// final '\r' (Windows line ends) is dropped.
class TextLines {
 public:
  explicit TextLines(std::string text) : text_(std::move(text)) {}
  /// The next line, or nullopt at the end of the text.
  std::optional<std::string_view> next() {
    if (at_ >= text_.size()) return std::nullopt;
    const std::size_t end = std::min(text_.find('\n', at_), text_.size());
    std::string_view line(text_.data() + at_, end - at_);
    at_ = end + 1;
    ++number_;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    return line;
  }
  bool done() const { return at_ >= text_.size(); }
  int number() const { return number_; }

 private:
  std::string text_;
  std::size_t at_ = 0;
  int number_ = 0;
};

}  // namespace dartcheck
