// A D-graph (a map, a host, a derived graph) as DOT: one node per dart,
// links colored by dimension (002's convention), a non-oriented pair of
// arcs drawn once as an undirected edge, oriented arcs as arrows.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "core/graph.hpp"
#include "core/model.hpp"
#include "reports/dot_text.hpp"

namespace dartcheck::reports {

struct GraphPicture {
  std::string prefix;             // prefixes node ids, so several panels share one picture
  std::string title;              // the panel's label
  std::vector<bool> highlight;    // per node: drawn filled, with the attribute highlight="true"
  std::string highlight_label;    // what the highlight means, for the panel's label
  std::vector<std::string> tags;  // per node: text under the dart's number (e.g. the L node it matches), may be empty
  /// The highlight's fill and border (dot_text.hpp: one colour per meaning).
  std::string_view fill = broken_fill, line = broken_line;
  /// Per node, where to pin it (inches; map_layout.hpp), for an engine
  /// that honours positions (neato); empty: the engine lays it out.
  std::vector<std::array<double, 2>> positions = {};
};

/// A cluster subgraph holding the graph (to embed in a larger picture).
std::string graph_cluster(const TopoGraph& g, const Model& model, const GraphPicture& p);

/// A whole picture: the graph and a legend of the dimensions.
std::string graph_dot(const TopoGraph& g, const Model& model, const GraphPicture& p);

}  // namespace dartcheck::reports
