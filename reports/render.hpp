// Graphviz rendering through libgvc (no `dot` process): DOT text in, SVG,
// PNG or laid-out DOT out.
#pragma once

#include <array>
#include <string>
#include <vector>
#include <string_view>

#include "core/error.hpp"

namespace dartcheck::reports {

/// Lays out `dot` with `engine` ("dot", "neato", ...) and renders it in
/// `format` ("svg", "png", "dot" for the laid-out graph, ...). Throws
/// Error with Graphviz's message if the text does not parse
/// or the format or engine is unknown.
std::string render(std::string_view dot, std::string_view format, std::string_view engine = "dot");

/// Each node's name and position after the layout, in points (z: 0 unless
/// the graph sets dimen=3), in the graph's node order; for pictures whose
/// nodes are placed from another layout (map_layout, rule_dot). Throws as
/// render does.
struct NodePosition {
  std::string name;
  std::array<double, 3> at;
  double width = 0, height = 0;  // inches
};
std::vector<NodePosition> node_positions(std::string_view dot, std::string_view engine);

/// The output format a file name asks for: its extension (svg, png, dot,
/// gv as dot, pdf). Throws ValueError naming the extensions
/// accepted.
std::string format_of(std::string_view file);

/// Writes `dot` to `file` in the format its extension names (.dot/.gv:
/// the DOT text itself), rendered by `engine`; returns the bytes written.
/// InputError for an extension that names no format (-o), OutputError.
std::size_t write_picture(std::string_view dot, const std::string& file, std::string_view engine);

}  // namespace dartcheck::reports
