// DPO rewriting on small labeled graphs (002 Def. 2-4): hosts that are
// arbitrary D-graphs, where a node may have several arcs with one label and
// a match is not determined by hooks. Exhaustive, for the small hosts of
// examples and brute-force checks (proofs, host search): the one
// documented variant of application. Dense maps use the Applier
// (application.hpp).
#pragma once

#include <vector>

#include "core/graph.hpp"
#include "core/map.hpp"
#include "rewriting/rule.hpp"

namespace dartcheck {

/// A monomorphism L -> G: an image per node and per arc of L.
struct GraphMatch {
  std::vector<NodeId> node;
  std::vector<ArcId> arc;
};

/// Every monomorphism from L into G (Assumption 1), by backtracking.
std::vector<GraphMatch> all_matches(const TopoGraph& L, const TopoGraph& G);

/// The dangling condition: no node of m(L \ K) is the source or target of
/// an arc of G outside m(L).
bool satisfies_dangling(const Rule& rule, const TopoGraph& G, const GraphMatch& m);

/// The derived graph H of G =>(r,m) H, for a match satisfying the dangling
/// condition: G without m(L \ K), plus R \ K glued along K. Nodes of G keep
/// their names and order; added nodes are appended under their R names.
/// `comatch`, if given, receives the image of each node of R.
TopoGraph derive(const Rule& rule, const TopoGraph& G, const GraphMatch& m, std::vector<NodeId>* comatch = nullptr);

/// The D-graph of a dense map: node d is dart d (named by its index), arc
/// ids in order (dart, dimension) for every dart with an i-arc.
TopoGraph to_graph(const Map& map);

}  // namespace dartcheck
