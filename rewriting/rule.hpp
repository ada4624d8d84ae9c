// DPO rules L ⊇ K ⊆ R with K = L ∩ R (002 Def. 2, Assumption 2).
//
// Nodes are identified across the two sides by name. Arcs are identified by
// (source name, target name, label) counted with multiplicity: if L has two
// a -0-> b arcs and R one, one is preserved and one deleted.
#pragma once

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "core/conjugate_words.hpp"
#include "core/graph.hpp"
#include "core/model.hpp"

namespace dartcheck {

inline constexpr NodeId no_node = static_cast<NodeId>(-1);

class Rule {
 public:
  /// Builds a rule and its interface. Throws ValueError when an
  /// arc label is not a dimension of the model, a side repeats a node name,
  /// a hook is not a node of L, or a connected component of L has no hook
  /// or several (002 Sec. 6.3: one hook per component).
  Rule(std::string name, Model model, TopoGraph left, TopoGraph right, std::vector<std::string> hooks);
  /// A rule scheme's core (002 Def. 18): arcs are identified by their full
  /// label (w, d), so `left_words` and `right_words` (one word per arc) take
  /// part in K = L ∩ R; the core itself keeps the D-labels.
  Rule(std::string name, Model model, TopoGraph left, TopoGraph right, std::vector<std::string> hooks, const std::vector<ConjWord>& left_words,
       const std::vector<ConjWord>& right_words);

  const std::string& name() const { return name_; }
  const Model& model() const { return model_; }
  const TopoGraph& left() const { return left_; }
  const TopoGraph& right() const { return right_; }
  /// Hooks as nodes of L, one per connected component.
  const std::vector<NodeId>& hooks() const { return hooks_; }

  /// The R node with the same name as L node v (no_node: v is deleted).
  NodeId to_right(NodeId v) const { return left_to_right_[v]; }
  /// The L node with the same name as R node v (no_node: v is added).
  NodeId to_left(NodeId v) const { return right_to_left_[v]; }
  bool preserved_left_arc(ArcId e) const { return left_arc_kept_[e]; }
  bool preserved_right_arc(ArcId e) const { return right_arc_kept_[e]; }
  /// Whether some node of L is deleted (has no R node).
  bool deletes_nodes() const { return std::find(left_to_right_.begin(), left_to_right_.end(), no_node) != left_to_right_.end(); }

  /// The inverse rule R ⊇ K ⊆ L with the given hooks (nodes of R by name).
  Rule inverse(std::vector<std::string> hooks) const;

  /// Connected components of L (arcs taken in both directions), as a
  /// component index per node.
  static std::vector<int> components(const TopoGraph& g, int* count);

 private:
  std::string name_;
  Model model_;
  TopoGraph left_, right_;
  std::vector<NodeId> hooks_;
  std::vector<NodeId> left_to_right_, right_to_left_;
  std::vector<bool> left_arc_kept_, right_arc_kept_;
};

/// The W-labels of the arcs of both sides of a rule scheme, in arc order.
/// For a DPO rule (`scheme` false) the vectors are empty and every word is
/// ε.
struct ArcWords {
  bool scheme = false;
  std::vector<ConjWord> left, right;
};

/// The W-label of arc e of a side whose words are `words` (ArcWords::left
/// or right): ε when the vector is empty, as for a DPO rule.
const ConjWord& arc_word(const std::vector<ConjWord>& words, ArcId e);

}  // namespace dartcheck
