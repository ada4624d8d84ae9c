// Small pieces of DOT text shared by the pictures.
#pragma once

#include <string>
#include <string_view>

#include "core/model.hpp"
#include "reports/html_page.hpp"  // html_text: also the text of Graphviz HTML-like labels

namespace dartcheck::reports {

/// A DOT double-quoted string; a newline becomes DOT's line break "\n".
std::string quote(std::string_view s);

/// The papers' colors for links: 0 black, 1 red, 2 blue, 3 green; higher
/// dimensions get further distinct colors.
std::string_view dimension_color(Dim d);

/// Rule elements: preserved, deleted, added, and the highlight of
/// witnesses. One fill, one meaning: amber for a rule's witnesses, blue for
/// the match in a host G, red for the darts of a result H that break a
/// constraint (the legends say which).
inline constexpr std::string_view preserved_color = "black";
inline constexpr std::string_view deleted_color = "#d32f2f";
inline constexpr std::string_view added_color = "#2e7d32";
inline constexpr std::string_view highlight_fill = "#ffd54f";
inline constexpr std::string_view highlight_line = "#ff6f00";
inline constexpr std::string_view match_fill = "#90caf9";
inline constexpr std::string_view match_line = "#1565c0";
inline constexpr std::string_view broken_fill = "#ef9a9a";
inline constexpr std::string_view broken_line = "#b71c1c";
/// The terms under an embedded rule's nodes.
inline constexpr std::string_view term_color = "#455a64";

/// The compass point of a node's k-th loop: Graphviz stacks a node's loops
/// on one side, where their labels overlap. The sides across the layout's
/// flow come first (n, s, then w, e for a left-to-right picture; e, w, then
/// n, s top to bottom), where the edges between nodes do not run.
std::string_view loop_port(std::size_t k, bool left_to_right);

/// An HTML-like label (for `label=<...>`) with one colored entry per
/// dimension of the model.
std::string dimension_legend(const Model& model);

}  // namespace dartcheck::reports
