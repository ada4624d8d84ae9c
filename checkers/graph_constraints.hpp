// The per-node constraints of 002 Def. 9 on small labeled multigraphs
// (rule sides, patterns, brute-force hosts).
#pragma once

#include <vector>

#include "checkers/violation.hpp"
#include "core/graph.hpp"

namespace dartcheck {

/// I(i) at v: v is the source of a unique i-arc and the target of a unique
/// i-arc. Appends the failing sides of v.
void check_incidence(const TopoGraph& g, NodeId v, Dim i, bool at_most_one, std::vector<Violation>& out);
/// O(i) at v: every i-arc incident to v has a reverse arc.
bool non_oriented_at(const TopoGraph& g, NodeId v, Dim i);
/// C(i,j) at v: v is the source of an ijij-cycle.
bool cycle_at(const TopoGraph& g, NodeId v, Dim i, Dim j);

/// Every violation of the model's constraints in g, by node.
ValidityReport check_graph(const TopoGraph& g, const Model& model);

}  // namespace dartcheck
