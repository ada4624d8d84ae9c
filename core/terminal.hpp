// How text output fits its reader: colour, width and verbosity, decided
// once from the global options (--color, --quiet), the environment
// (NO_COLOR, TERM, COLUMNS) and whether each stream is a terminal. Machine
// formats (JSON, SARIF, JUnit, files) never depend on it.
#pragma once

#include <cstddef>
#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

namespace dartcheck {

enum class ColorChoice { automatic, always, never };

struct Terminal {
  bool quiet = false;  // --quiet: no tables, summaries or progress; diagnostics stay
  bool color_stdout = false;
  bool color_stderr = false;
  std::size_t width = 100;  // columns the text tables fit in
};

/// The process's settings; the defaults until set_terminal runs.
const Terminal& terminal();

/// --color: `always` and `never` decide; `automatic` colours a stream that
/// is a terminal unless NO_COLOR is set and not empty (no-color.org) or
/// TERM is "dumb". Width: COLUMNS when it is a number of at least 40, else
/// the terminal's width when stdout is one, else 100.
void set_terminal(ColorChoice color, bool quiet);

/// A diagnostic's or a verdict's tone, one ANSI colour each.
enum class Tone { error, warning, good };

/// `text` in its tone's colour when `on`, unchanged otherwise.
std::string paint(std::string_view text, Tone tone, bool on);

/// The "error:" of a diagnostic line ("error: ...", "file:1:2: error: ...")
/// painted for stderr when stderr takes colour.
std::string painted_diagnostic(std::string_view line);

/// `text` broken at spaces into lines of at most `width` characters (a
/// longer word gets a line of its own); UTF-8 sequences count as one.
std::vector<std::string> wrap_words(std::string_view text, std::size_t width);

/// A row whose last cell wraps: `head` padded to `indent` columns, then
/// `text` wrapped at the terminal's width with its continuation lines
/// indented to `indent` (at least 20 columns are kept for the text). A
/// head longer than `indent` wraps with the text as one paragraph from
/// column 0, continued at `indent`. Ends with a newline.
std::string hanging(std::string_view head, std::string_view text, std::size_t indent);

/// Display columns of UTF-8 text (one per code point).
std::size_t columns(std::string_view text);

}  // namespace dartcheck
