// Jerboa-style rule schemes (000 Sec. 4.3) as (W,D)-rule schemes (002 Sec.
// 10.1).
//
// A Jerboa scheme labels each node with a generalized orbit type such as
// <_,1,2>: a relabeling of the parameter orbit type <o> carried by the hook
// (<0,1,2> maps 0 to "removed", 1 to 1, 2 to 2). Its arcs are explicit
// links between copies of the same dart. The translation is the one of 002
// Sec. 10.1: an explicit i-arc becomes an (ε,i)-arc, and position k of a
// node label, o_k relabeled to j, becomes an (o_k, j)-loop on the node. So
// one checker and one application engine serve both notations.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/error.hpp"
#include "core/conjugate_words.hpp"
#include "core/graph.hpp"
#include "core/model.hpp"
#include "core/orbit_notation.hpp"

namespace dartcheck {

/// Adds to `g` (whose arc words are `words`, one per arc) the implicit arcs
/// of node v labeled `label` under the parameter orbit type `parameter`: an
/// (o_k, label_k)-loop for each position k whose label is not '_'. Throws
/// ValueError if the lengths differ (000 Def. 4.2's size
/// condition), the parameter has a '_', or a dimension is not in the model.
/// A Jerboa scheme's node labels, kept beside their translation so that
/// pictures and writers show the notation the user wrote: one orbit type
/// per node of L and of R (indexed by node id), and the parameter orbit
/// type (the hook's label).
struct JerboaLabels {
  OrbitType parameter;
  std::vector<OrbitType> left, right;
};

void add_implicit_arcs(TopoGraph& g, std::vector<ConjWord>& words, NodeId v, const OrbitType& parameter, const OrbitType& label, const Model& model);

}  // namespace dartcheck
