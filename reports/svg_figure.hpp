// Several Graphviz SVGs as one figure (issue 39): a header above a row of
// panels, each panel at its own natural size and all top-aligned, so that
// a counterexample's G, H and rule read side by side instead of being one
// layout whose clusters dot places at different heights.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace dartcheck::reports {

/// The size a Graphviz SVG declares on its root element, in points.
struct SvgSize {
  double width = 0;
  double height = 0;
};

/// Reads width="..pt" height="..pt" of the root <svg>; Error
/// when the text has no such root (not Graphviz output).
SvgSize svg_size(std::string_view svg);

/// One standalone SVG: `head` on top, then `panels` left to right with a
/// gap between them, top-aligned, starting a new row when a row would be
/// wider than `max_width` points. Ids are prefixed per part so that
/// Graphviz's node1, edge1 ... of different parts do not collide.
std::string svg_figure(std::string_view head, const std::vector<std::string>& panels, double max_width = 960);

}  // namespace dartcheck::reports
