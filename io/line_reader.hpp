// Reading whitespace-separated text meshes line by line, with the line and
// column of every token for error messages: shared by the OFF/OBJ and the
// tetrahedral mesh readers.
#pragma once

#include <cctype>
#include <charconv>
#include <fstream>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "core/input_error.hpp"
#include "io/input_file.hpp"

namespace dartcheck::text_mesh {

// A line split into tokens with their 1-based columns; '#' starts a comment.
struct Line {
  int number = 0;
  std::vector<std::pair<std::string_view, int>> tokens;
};

class LineReader {
 public:
  explicit LineReader(const std::string& file) : file_(file), lines_(read_input(file)) {}
  // Next line with at least one token, or nullopt at the end of the file.
  std::optional<Line> next() {
    while (const auto text = lines_.next()) {
      number_ = lines_.number();
      if (text->find('\0') != std::string_view::npos)
        throw InputError(file_, number_, static_cast<int>(text->find('\0')) + 1, "binary data (a NUL byte) in a text mesh file");
      Line l{number_, {}};
      std::string_view s(*text);
      if (auto hash = s.find('#'); hash != std::string_view::npos) s = s.substr(0, hash);
      std::size_t k = 0;
      while (k < s.size()) {
        while (k < s.size() && std::isspace(static_cast<unsigned char>(s[k]))) ++k;
        std::size_t b = k;
        while (k < s.size() && !std::isspace(static_cast<unsigned char>(s[k]))) ++k;
        if (k > b) l.tokens.emplace_back(s.substr(b, k - b), static_cast<int>(b) + 1);
      }
      if (!l.tokens.empty()) return l;
    }
    return std::nullopt;
  }
  int line() const { return number_; }
  [[noreturn]] void fail(int line, int column, const std::string& msg) const { throw InputError(file_, line, column, msg); }

 private:
  std::string file_;
  TextLines lines_;  // the file's text: tokens are views into it
  int number_ = 0;
};

template <class T>
T number(const LineReader& r, const Line& l, std::size_t k, std::string_view what) {
  if (k >= l.tokens.size()) r.fail(l.number, 0, fmt::format("expected {} but the line ends", what));
  auto [tok, col] = l.tokens[k];
  T v{};
  auto [end, ec] = std::from_chars(tok.data(), tok.data() + tok.size(), v);
  if (ec != std::errc{} || end != tok.data() + tok.size()) r.fail(l.number, col, fmt::format("expected {}, got '{}'", what, tok));
  return v;
}

}  // namespace dartcheck::text_mesh
