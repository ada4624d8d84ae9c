// Pieces of the HTML report: escaping, Graphviz SVG made fit to inline,
// and the page around a body. The page is self-contained (inline style, no
// script, no external font or image) and well-formed XML, so that tools
// and tests can parse it.
#pragma once

#include <string>
#include <string_view>

namespace dartcheck::reports {

/// Text or attribute value (HTML and XML): &, <, >, " escaped; control
/// characters other than tab and newline become spaces.
std::string html_text(std::string_view s);

/// An id/fragment for a name ("fig26d-scheme/missing-2" ->
/// "fig26d-scheme-missing-2"): letters, digits, '-', '_' and '.' kept,
/// anything else '-'.
std::string html_id(std::string_view name);

/// Graphviz's SVG without the XML declaration, doctype and comments, its
/// ids prefixed with `id_prefix` so several pictures share a page.
std::string inline_svg(std::string_view svg, std::string_view id_prefix);

/// The whole page: doctype, head with title and style, the body.
std::string html_document(std::string_view title, std::string_view body);

}  // namespace dartcheck::reports
