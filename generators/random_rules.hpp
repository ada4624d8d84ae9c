// Random small DPO rules, for the property tests of Theorems 1-3 (002
// Sec. 4-5) and for cross-checking the solver against the static checker.
// Drawn with std::mt19937 so that a failing rule is reproduced by its seed.
#pragma once

#include <random>
#include <string>
#include <vector>

#include "rewriting/rule.hpp"

namespace dartcheck {

/// One permutation per dimension of a model, by index in model.dims
/// (sigma[k][v] = target of v's arc).
using Perms = std::vector<std::vector<NodeId>>;

/// The permutations satisfy the model's O (on N), C (on E) and loop ban.
bool perms_in_model(const Model& m, const Perms& s);

/// The first node of each connected component of L: hooks for a rule.
std::vector<std::string> first_node_per_component(const TopoGraph& L);

/// L on 1-3 nodes, usually a subset of the arcs of a host whose links
/// satisfy `arcs_from` (so that matches exist; with `any_arcs_often`, any
/// permutations half of the time), sometimes arbitrary arcs; R keeps a
/// random part of L and adds nodes and arcs, biased towards repairing the
/// incidences it removed so that many rules are combinatorial.
Rule random_rule(std::mt19937& rng, const Model& arcs_from, const Model& model, bool any_arcs_often = false);

/// D-combinatorial rules (Def. 12) by construction: L is part of a host of
/// `host_class`; a node is deleted only if L gives it every incidence; per
/// dimension R joins out-slots to in-slots by a random bijection, half of
/// the time pairing them into reverse arcs.
Rule random_combinatorial_rule(std::mt19937& rng, const Model& host_class, const Model& model);

/// Arbitrary arcs over the model's dimensions, for rules far from valid.
Rule random_rule_for(std::mt19937& rng, const Model& model);

}  // namespace dartcheck
