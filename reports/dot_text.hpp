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
/// witnesses and counterexample darts.
inline constexpr std::string_view preserved_color = "black";
inline constexpr std::string_view deleted_color = "#d32f2f";
inline constexpr std::string_view added_color = "#2e7d32";
inline constexpr std::string_view highlight_fill = "#ffd54f";
inline constexpr std::string_view highlight_line = "#ff6f00";
/// The terms under an embedded rule's nodes.
inline constexpr std::string_view term_color = "#455a64";

/// An HTML-like label (for `label=<...>`) with one colored entry per
/// dimension of the model.
std::string dimension_legend(const Model& model);

}  // namespace dartcheck::reports
