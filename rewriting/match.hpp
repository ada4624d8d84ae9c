// Matches of a rule's left-hand side in a dense map (002 Def. 3,
// Assumption 1; 000 Sec. 4.2): the unique match built from one hook dart
// per connected component of L, by propagation along incident arcs.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/formatting.hpp"
#include "core/map.hpp"
#include "rewriting/rule.hpp"

namespace dartcheck {

/// An injective morphism L -> G: a dart per node of L; the image of an
/// L arc x -i-> y is the i-arc of dart m(x).
struct Match {
  std::vector<Dart> node;
};

/// Why no match or no derivation exists.
enum class Refusal {
  none,
  bad_hooks,          // wrong number of hook darts or a dart out of range
  not_combinatorial,  // the host breaks I(i) at a matched dart (002 Assumption 3)
  no_match,           // some arc of L has no image (label or shape differs)
  not_injective,      // two nodes or two arcs of L would share an image
  dangling,           // a deleted dart keeps an arc outside the match
  not_representable,  // H would give a dart two i-arcs (not a dense map)
  disconnected,       // schemes: ι(L, P_v) is not connected, so hooks do not fix the match (002 Sec. 6.3)
  label_mismatch,     // embedded rules: a term of L differs from the value of its matched dart
  overlap,            // embedded rules: the match merges two pi-orbits of L (003 Lemma 3)
  no_value,           // embedded rules: a term has no value on the map (an unlabeled dart, center of nothing)
};

std::string_view name_of(Refusal r);

template <class T>
struct Outcome {
  std::optional<T> value;
  Refusal refusal = Refusal::none;
  std::string why;  // a sentence naming the nodes, darts and dimension
  bool ok() const { return value.has_value(); }
};

/// A refused outcome: no value, the refusal and the sentence that says why.
template <class T>
Outcome<T> refuse(Refusal r, std::string why) {
  return {std::nullopt, r, std::move(why)};
}

/// Empty when the i-arcs at d are those of a combinatorial graph, as a DPO
/// match needs for propagation and the dangling condition to see every arc
/// (an i-arc out of d whose target points back, an oriented dimension's
/// predecessor that agrees, no missing arc outside the partial
/// dimensions); otherwise the first that is not.
std::string combinatorial_violation(const Map& g, Dart d);

/// Builds the match that sends hook k of the rule to hook_darts[k].
/// Costs O(|L| * |D|): independent of the size of the map.
Outcome<Match> match_from_hooks(const Rule& rule, const Map& g, std::span<const Dart> hook_darts);

/// The dangling condition (002 Sec. 2.2): no deleted dart m(v), v in L \ K,
/// is the source or target of an arc outside m(L). Empty if it holds.
std::string dangling_violation(const Rule& rule, const Map& g, const Match& m);

}  // namespace dartcheck
