#include "reports/dot_text.hpp"

#include <array>

#include <fmt/format.h>

namespace dartcheck::reports {

std::string quote(std::string_view s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '\n') {  // a line break of a label
      out += "\\n";
      continue;
    }
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + '"';
}

std::string_view loop_port(std::size_t k, bool left_to_right) {
  // Across a left-to-right flow, then across a top-to-bottom one.
  static constexpr std::array<std::string_view, 8> ports = {"n", "s", "w", "e", "e", "w", "n", "s"};
  return ports[(left_to_right ? 0 : 4) + k % 4];
}

std::string_view dimension_color(Dim d) {
  static constexpr std::array<std::string_view, 8> colors = {"black", "#d32f2f", "#1565c0", "#2e7d32", "#6a1b9a", "#ef6c00", "#00838f", "#795548"};
  return colors[static_cast<std::size_t>(d) % colors.size()];
}

std::string dimension_legend(const Model& model) {
  std::string cells;
  for (Dim d : model.dims)
    cells += fmt::format(R"(<td><font color="{}">&#9472;&#9472; {}{}</font></td>)", dimension_color(d), d, model.is_oriented(d) ? " (oriented)" : "");
  return fmt::format(R"(<table border="0" cellspacing="6"><tr><td>{}</td>{}</tr></table>)", html_text(model.name), cells);
}

}  // namespace dartcheck::reports
