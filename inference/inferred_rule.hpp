// The rule scheme of a folded κ(G, H) (000 Sec. 7): nodes whose darts lie
// in G form L, those in H form R, and a κ-arc makes an L node and an R
// node one preserved node; the κ-arcs are then dropped. The result is a
// Jerboa-style Operation (labels translated by rewriting/jerboa_scheme),
// so the static checker, the scheme engine and the writers take it as any
// catalog rule.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "inference/folding.hpp"
#include "rewriting/operation.hpp"

namespace dartcheck::inference {

struct InferredRule {
  Operation operation;
  /// node_of_left[v] / node_of_right[v]: the scheme node of rule node v.
  std::vector<int> node_of_left, node_of_right;
  std::size_t preserved = 0;
  /// The rule's name of each folding node (index of GraphScheme::nodes).
  std::vector<std::string> names;
};

/// Builds the rule scheme named `name`. Nodes are named n<k>, k the node's
/// index in the folding (a preserved R node takes its L node's name), so
/// equal schemes get equal names. Returns a sentence instead when L is
/// not connected (κ(G, H) was connected only through H, and one hook
/// cannot instantiate every component of L).
struct RuleOrWhy {
  std::optional<InferredRule> rule;
  std::string why;
};
RuleOrWhy to_rule(const GraphScheme& scheme, const Model& model, const std::string& name);

/// A canonical text of the scheme: the folding numbers nodes in BFS order
/// from the hook with dimensions in ascending order, so two foldings give
/// the same text iff their schemes are isomorphic hook onto hook, labels
/// and sides kept. Used to deduplicate multi-start results (000 Sec. 10.3).
std::string canonical_form(const GraphScheme& scheme);

/// True when the rule rewrites every match into itself: every node
/// preserved with the same label, the same explicit arcs on both sides.
bool does_nothing(const Operation& op);

/// The same for any Jerboa-style rule with one hook, independent of node
/// names and arc order: nodes numbered breadth-first from the hook (explicit
/// arcs by ascending dimension, then the node of the same name on the other
/// side), each with its side and label, then the sorted arcs. Two rules
/// have equal forms iff they are the same scheme up to renaming. nullopt
/// for a rule without Jerboa labels, with several hooks, or whose nodes are
/// not all reached so.
std::optional<std::string> canonical_form(const Operation& op);

}  // namespace dartcheck::inference
