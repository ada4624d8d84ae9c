// Exhaustive dynamic check of a DPO rule on small hosts: every map of a
// model whose darts are the nodes of L plus up to `extra` more, matched by
// the identity on L's nodes (every match is one of these up to renaming).
// Each derivation is checked against the model; the first failing one is a
// counterexample. This is the semantic side of Theorems 1-3 and what
// `dartcheck check` runs to confirm a failing condition on real maps.
#pragma once

#include <functional>
#include <optional>
#include <span>

#include "checkers/violation.hpp"
#include "rewriting/operation.hpp"
#include "rewriting/rule.hpp"

namespace dartcheck {

struct HostSearch {
  bool matched = false;           // some host admits the match with the dangling condition
  bool exhausted = true;          // false if the host budget stopped the search
  std::size_t hosts = 0;          // hosts of the class enumerated
  std::size_t derivations = 0;    // matches that satisfied the dangling condition
  std::size_t largest_host = 0;   // nodes of the largest host tried
  std::optional<TopoGraph> host;  // first counterexample: G, H and what H breaks
  std::optional<TopoGraph> result;
  std::vector<Violation> violations;
};

/// Hosts: D-combinatorial graphs (one permutation per dimension of
/// `host_model`) satisfying O on its N, C on its E, and no loops if it is
/// loop-free. `relevant` selects the violations of H that count (all by
/// default). Stops after `budget` hosts.
HostSearch search_hosts(const Rule& rule, const Model& host_model, std::size_t extra, const std::function<bool(const Violation&)>& relevant = {},
                        std::size_t budget = 2'000'000);

/// Calls `visit` with every map of `model` on exactly `n` darts (the same
/// class as search_hosts: one permutation per dimension, sigma[k][v] for
/// model.dims[k], satisfying O, C and loop-freeness), until it returns
/// false or `budget` maps were visited. With `containing`, only the maps
/// in which the identity on its nodes is an image of its arcs (its nodes
/// are darts 0..|nodes|-1). Returns the number of maps visited; fewer than
/// `budget` and no early stop means every such map was visited.
std::size_t for_each_small_map(const Model& model, std::size_t n, const std::function<bool(const std::vector<std::vector<NodeId>>&)>& visit,
                               std::size_t budget = 2'000'000, const TopoGraph* containing = nullptr);

/// Every host of an operation up to `max_darts` darts, each with the hooks
/// to apply it at, smallest hosts first: for a DPO rule the maps containing
/// L with its nodes as darts 0..|L|-1 (every match is one of these up to
/// renaming), for a scheme the maps with the first hook at dart 0 and the
/// others at every dart; only hosts connected to the hooks (another
/// component is left as it is). `visit` returns false to stop.
struct RootedHosts {
  std::size_t hosts = 0;     // maps visited
  std::size_t complete = 0;  // every host of up to this many darts was visited
  bool budget_hit = false;   // `budget` maps stopped the search
};
RootedHosts for_each_rooted_host(const Operation& op, std::size_t max_darts, const std::function<bool(const Map&, std::span<const Dart>)>& visit,
                                 std::size_t budget = 2'000'000);

}  // namespace dartcheck
