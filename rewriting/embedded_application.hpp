// Application of an embedded rule or rule scheme to an embedded G-map
// (003 Def. 10-13). The rule's topology is a DPO rule or a (W,D) /
// Jerboa-style scheme (002 Sec. 6); its terms (core/rule_terms.hpp) are
// evaluated on the map before the rewrite, with each node variable bound
// to the dart its node matched (for a scheme, in the same pattern copy).
//
// Checks before any write: L's terms must equal the values of the matched
// darts (the labeled match of the evaluated rule), every term must have a
// value, and, for `extended` instantiation, the match must not merge two
// pi-orbits of L (Lemma 3, non-overlap) for any embedding the rule labels.
//
// Writes after the topological rewrite:
// - `direct`: each labeled instance of an R node gives its value to its
//   own dart; a preserved node labeled in L but not in R loses its value
//   (K is unlabeled there, 003 Def. 1), an unlabeled added node has none.
// - `extended`: each labeled instance gives its value to its whole
//   pi-orbit in H, which is the orbit of the extended rule R^{⊕m} (the
//   o-completion of the match, Def. 11) propagated through the quotient
//   (Def. 12). When two instances give one orbit two values, the extended
//   rule breaks (A) and the propagation does not exist (Def. 13): the
//   conflict is reported and H keeps both values, so the map itself shows
//   the inconsistency.
#pragma once

#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "rewriting/derivation.hpp"
#include "rewriting/embedded_map.hpp"
#include "rewriting/rule_terms.hpp"
#include "rewriting/scheme_application.hpp"

namespace dartcheck {

struct WrittenValue {
  std::string embedding, node;  // node: "y" for a DPO rule, "y@d" for pattern dart d of a scheme
  Dart dart = no_dart;          // in H
  Value value;
};

struct EmbeddedDerivation {
  std::size_t matched = 0, added = 0;
  std::vector<std::pair<Dart, Dart>> moved;  // renumbered darts of H
  std::vector<WrittenValue> written;         // in R's node order (with `record`)
  std::vector<std::string> conflicts;        // orbits given two values (Def. 13 undefined)
  /// With `record`: R -> H, comatch[y][p] the dart of H of node y (of
  /// pattern dart p for a scheme), in H's numbering.
  std::vector<std::vector<Dart>> comatch;
};

/// How the terms of R are evaluated under `extended` instantiation.
enum class Evaluation : std::uint8_t {
  /// Every instance of every labeled R node; instances of one orbit that
  /// disagree are reported as conflicts. The dynamic check (fuzz) uses it.
  every_instance,
  /// One instance per orbit of the instantiated R (its arcs in <o> join
  /// instances that share a pi-orbit of H); the others take its value.
  /// Only for a rule whose (A) holds (checkers/embedding_conditions):
  /// then the instances of one orbit have one value (003 Thm 2, 4), so
  /// nothing is lost but the evaluations. A `direct` rule ignores it.
  one_per_orbit,
};

/// What an embedded application derives from the rule and its terms alone:
/// computed once per EmbeddedRewriter, and by `dartcheck compile`, which
/// generates code from it, so both decide alike.
struct TermFacts {
  std::vector<NodeId> left_node, right_node;  // the node of terms.left[k], terms.right[k]
  /// stored_at[k]: the L node whose matched dart's stored value is R term
  /// k's value, or no_node when the term is evaluated. Either the term
  /// repeats the L label of its preserved node (same embedding, same term:
  /// the labeled match checked it), or it is `x.pi` for its own embedding
  /// pi: no evaluation, and the orbit shares the stored pool entry.
  std::vector<NodeId> stored_at;
  std::vector<const EmbeddingSignature*> used;  // terms.used()
  /// closed[u]: every node of R has one out-arc of each dimension of
  /// used[u]'s orbit. A successful rewrite makes every arc of R a link of H
  /// between the comatched darts, so the links of H in that orbit from an
  /// instance of R lead to instances of R: a class of the instantiated R is
  /// a whole pi-orbit of H, written without a walk.
  std::vector<char> closed;
  /// left_closed[u]: every node of L has an out-arc of each dimension of
  /// used[u]'s orbit. A match maps arcs to links, so the matched darts are
  /// then closed under that orbit's links and each class of the
  /// instantiated L is a whole pi-orbit of G: Lemma 3 cannot fail.
  std::vector<char> left_closed;
};
TermFacts term_facts(const Rule& rule, const RuleTerms& terms);

/// The L node whose matched dart's stored value every term of `embedding`
/// on the R nodes `in_group` accepts reads (TermFacts::stored_at), or
/// no_node when there is no such term, or one is evaluated or reads another
/// node: the kept-label shortcut's group condition, shared by
/// EmbeddedRewriter and `dartcheck compile`.
NodeId kept_source(const TermFacts& facts, const RuleTerms& terms, const std::string& embedding, const std::function<bool(NodeId)>& in_group);

/// Applies one embedded rule many times to one map, keeping its
/// traversal marks, per-dart tables and evaluator between applications:
/// a loop of small applications on a large map costs the darts each one
/// touches, not the size of the map. The rule, words, terms and map must
/// outlive it; the map may change between applications.
class EmbeddedRewriter {
 public:
  EmbeddedRewriter(const Rule& rule, const ArcWords& words, const RuleTerms& terms, EmbeddedMap& g,
                   Evaluation evaluation = Evaluation::every_instance);
  ~EmbeddedRewriter();
  EmbeddedRewriter(const EmbeddedRewriter&) = delete;
  EmbeddedRewriter& operator=(const EmbeddedRewriter&) = delete;

  /// Applies the rule at `hook_darts`. On refusal the map is unchanged.
  /// With `record`, `written` lists every value the rule wrote.
  Outcome<EmbeddedDerivation> apply(std::span<const Dart> hook_darts, bool record = true);

  /// The kept-label shortcut (on by default). Under one evaluation per
  /// orbit, for an embedding R closes, of a rule that deletes no node of
  /// L: a group of R's nodes whose terms all read one L node's stored
  /// value (`n0.pos`) is not walked for its classes when that value's pool
  /// index i(p) at each pattern copy p is defined and equals i(p·w) for
  /// each of the group's steps w; each copy is then its own class, valued
  /// i(p). The result is the walk's, index for index: a class is connected
  /// by those steps, so i is constant on it, and the walk gives every
  /// instance the index of the class's first instance, i(p) again. When
  /// the check fails (G not consistent along the group, equal values in
  /// distinct pool entries, a missing value) the group is walked.
  void use_kept_label_shortcut(bool on);
  /// How often the shortcut's check held, and failed (the walk ran).
  struct ShortcutCounts {
    std::size_t taken = 0, refused = 0;
  };
  ShortcutCounts kept_label_shortcuts() const;

 private:
  struct Context;
  std::unique_ptr<Context> c_;
};

/// One application with a fresh context (EmbeddedRewriter::apply).
Outcome<EmbeddedDerivation> apply_embedded(const Rule& rule, const ArcWords& words, const RuleTerms& terms, EmbeddedMap& g,
                                           std::span<const Dart> hook_darts, bool record = true);

}  // namespace dartcheck
