#include "core/terminal.hpp"

#include <sys/ioctl.h>
#include <unistd.h>

#include <charconv>
#include <cstdlib>

namespace dartcheck {

namespace {

Terminal& settings() {
  static Terminal t;
  return t;
}

bool colour_allowed(int fd) {
  const char* no_color = std::getenv("NO_COLOR");
  if (no_color && *no_color) return false;
  const char* term = std::getenv("TERM");
  if (term && std::string_view(term) == "dumb") return false;
  return isatty(fd) != 0;
}

std::size_t output_width() {
  if (const char* env = std::getenv("COLUMNS")) {
    std::size_t n = 0;
    const std::string_view s(env);
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), n);
    if (ec == std::errc() && end == s.data() + s.size() && n >= 40) return n;
  }
  winsize w{};
  if (isatty(STDOUT_FILENO) && ioctl(STDOUT_FILENO, TIOCGWINSZ, &w) == 0 && w.ws_col >= 40) return w.ws_col;
  return 100;
}

}  // namespace

const Terminal& terminal() { return settings(); }

void set_terminal(ColorChoice color, bool quiet) {
  Terminal& t = settings();
  t.quiet = quiet;
  t.color_stdout = color == ColorChoice::always || (color == ColorChoice::automatic && colour_allowed(STDOUT_FILENO));
  t.color_stderr = color == ColorChoice::always || (color == ColorChoice::automatic && colour_allowed(STDERR_FILENO));
  t.width = output_width();
}

std::string paint(std::string_view text, Tone tone, bool on) {
  if (!on) return std::string(text);
  const char* code = tone == Tone::error ? "\x1b[1;31m" : tone == Tone::warning ? "\x1b[33m" : "\x1b[32m";
  return std::string(code).append(text).append("\x1b[0m");
}

std::string painted_diagnostic(std::string_view line) {
  if (!terminal().color_stderr) return std::string(line);
  constexpr std::string_view word = "error:";
  std::size_t at = std::string_view::npos;
  if (line.substr(0, word.size()) == word)
    at = 0;
  else if (const auto k = line.find(": error: "); k != std::string_view::npos)
    at = k + 2;
  if (at == std::string_view::npos) return std::string(line);
  return std::string(line.substr(0, at)) + paint(word, Tone::error, true) + std::string(line.substr(at + word.size()));
}

std::size_t columns(std::string_view text) {
  std::size_t n = 0;
  for (unsigned char c : text) n += (c & 0xC0) != 0x80;
  return n;
}

std::vector<std::string> wrap_words(std::string_view text, std::size_t width) {
  std::vector<std::string> lines;
  std::string line;
  std::size_t k = 0;
  while (k < text.size()) {
    const std::size_t space = text.find(' ', k);
    const std::string_view word = text.substr(k, space == std::string_view::npos ? std::string_view::npos : space - k);
    k = space == std::string_view::npos ? text.size() : space + 1;
    if (word.empty()) continue;
    if (!line.empty() && columns(line) + 1 + columns(word) > width) {
      lines.push_back(line);
      line.clear();
    }
    if (!line.empty()) line += ' ';
    line += word;
  }
  if (!line.empty() || lines.empty()) lines.push_back(std::move(line));
  return lines;
}

std::string hanging(std::string_view head, std::string_view text, std::size_t indent) {
  const std::size_t width = terminal().width, room = width > indent + 20 ? width - indent : 20;
  const std::string pad(indent, ' ');
  std::string out;
  std::vector<std::string> lines;
  if (columns(head) > indent) {
    // A head longer than the indent: head and text wrap as one paragraph,
    // its first line from column 0 as wide as the terminal.
    std::string all(head);
    all += ' ';
    all += text;
    lines = wrap_words(all, width);
    if (lines.size() > 1) {
      std::string rest;
      for (std::size_t k = 1; k < lines.size(); ++k) rest += (k > 1 ? " " : "") + lines[k];
      lines.resize(1);
      for (auto& line : wrap_words(rest, room)) lines.push_back(std::move(line));
    }
  } else {
    out = head;
    out.append(indent - columns(head), ' ');
    lines = wrap_words(text, room);
  }
  for (std::size_t k = 0; k < lines.size(); ++k) {
    if (k > 0) out += pad;
    out += lines[k];
    out += '\n';
  }
  return out;
}

}  // namespace dartcheck
