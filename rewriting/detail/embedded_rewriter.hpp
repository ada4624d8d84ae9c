// Internal to rewriting/ (the Applier, rewriting/application.hpp, is the
// one way in): application of an embedded rule or rule scheme to an
// embedded G-map (003 Def. 10-13). The topology is the Applier's own match
// and rewrite (a DPO rule, or a (W,D) / Jerboa-style scheme, 002 Sec. 6);
// this adds the values. The terms (core/rule_terms.hpp) are evaluated on
// the map between the match and the rewrite, with each node variable bound
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

#include <memory>
#include <span>

#include "rewriting/application.hpp"

namespace dartcheck {

/// Applies one embedded rule many times to one map, keeping its
/// traversal marks, per-dart tables and evaluator between applications:
/// a loop of small applications on a large map costs the darts each one
/// touches, not the size of the map. The applier (whose topology it uses),
/// the terms and the map must outlive it; the map may change between
/// applications.
class EmbeddedRewriter {
 public:
  EmbeddedRewriter(Applier& topology, const Operation& op, const RuleTerms& terms, EmbeddedMap& g, const EvaluationOptions& options);
  ~EmbeddedRewriter();
  EmbeddedRewriter(const EmbeddedRewriter&) = delete;
  EmbeddedRewriter& operator=(const EmbeddedRewriter&) = delete;

  /// Applier::apply on an embedded map.
  Outcome<EmbeddedApplication> apply(std::span<const Dart> hook_darts, bool record);
  Applier::ShortcutCounts kept_label_shortcuts() const;

 private:
  struct Context;
  std::unique_ptr<Context> c_;
};

}  // namespace dartcheck
