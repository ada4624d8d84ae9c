// A rule as 004 reads it (Sec. 2.2): nodes whose labels are implicit links
// and explicit arcs between nodes.
//
// dartcheck keeps every operation as a (W,D)-rule scheme (002 Sec. 10.1),
// so this view undoes that translation: an (ε,i)-arc is an explicit link
// (a loop marks a free dart), an (o_k,j)-loop is position k of the node's
// label relabeled to j, and a DPO rule is a scheme with an empty parameter
// orbit type (every node matches one dart, every link is explicit). Arcs
// no Jerboa rule can draw (a word between two distinct nodes, a word of
// two letters, as in the O-map schemes of 002 Fig. 30) have no such view.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/orbit.hpp"
#include "rewriting/operation.hpp"

namespace dartcheck::events {

/// One side of the rule: labels[v][k] is the dimension of node v's k-th
/// implicit link (nullopt: '_', the link is removed); `explicit_arcs` are
/// the ids of the arcs of the rule's graph that are explicit links.
struct EventSide {
  const TopoGraph* graph = nullptr;
  std::vector<std::vector<std::optional<Dim>>> labels;
  std::vector<ArcId> explicit_arcs;
};

struct EventRule {
  const Rule* rule = nullptr;
  /// The hook's orbit type <o_1,...,o_p>: empty for a DPO rule.
  std::vector<Dim> parameter;
  /// The word of position k ({o_k}), as the scheme engine's W names it.
  std::vector<ConjWord> position_words;
  EventSide left, right;
  /// Instantiated over a parameter: a scheme whose hook orbit type is
  /// not empty (a scheme on <> has one instance, and events read it as a
  /// DPO rule's; Operation::is_scheme says what the rule is).
  bool has_parameter() const { return !parameter.empty(); }
};

/// The view of `op`, or a sentence saying why it has none.
struct EventRuleOutcome {
  std::optional<EventRule> rule;
  std::string why;
};
EventRuleOutcome event_rule(const Operation& op);

}  // namespace dartcheck::events
