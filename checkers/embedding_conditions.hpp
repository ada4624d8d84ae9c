// Static embedding consistency conditions of rules and rule schemes with
// terms (003 Theorem 2 and Theorem 4), per embedding pi : <o> -> tau:
//
//  - A(pi)  embedding consistency: in each <o>-orbit of L, K and R, the
//           labeled nodes carry one term (syntactic equality, 003 Sec. 6.1).
//  - B(pi)  full match of transformed embeddings (Theorem 2 only, direct
//           instantiation): a preserved node whose term changes has its
//           R-orbit fully labeled and complete (one i-arc per i of <o>).
//  - C(pi)  labeling of extended embedding orbits: a preserved node whose
//           R-orbit gains nodes has a node of K, in its L- and R-orbits,
//           labeled in L.
//  - label(pi)  the labeling of Def. 1 that Theorem 2 assumes: a preserved
//           node labeled in L keeps a label in R, and an added node is
//           labeled (direct) or, once propagated (extended, Def. 12), its
//           R-orbit holds a labeled node.
//
// Theorem 4 (extended instantiation) asks for A, C and the topological
// conditions on the scheme, plus non-overlap of each match (Lemma 3),
// which the Applier (rewriting/application.hpp) checks at application time.
//
// For a topological rule scheme (002 Sec. 6, Jerboa-style or (W,D)) the
// instantiated rule has one copy of each node per pattern dart, and a term
// is evaluated once per copy. The checks are made on the scheme so that
// they imply the conditions on every instance: orbits for A are joined by
// every arc labeled in <o> and a term must moreover be copy-invariant
// (every variable read through a collect or access whose orbit contains
// the L loop that moves the copy); orbits for C and label are joined by
// explicit (ε) arcs only, and C asks the node itself to be labeled in L.
//
// All conditions are sufficient, not necessary: two different terms may
// evaluate to equal values on every map.
#pragma once

#include <string>
#include <vector>

#include "checkers/rule_conditions.hpp"
#include "rewriting/rule_terms.hpp"

namespace dartcheck {

struct TermConditionVerdict {
  std::string condition;  // "A", "B", "C", "label"
  std::string embedding;
  bool holds = true;
  bool required = true;  // false: B under extended instantiation (Theorem 4 drops it)
  std::vector<RuleWitness> witnesses;
  std::string name() const;  // "A(pos)"
};

/// One verdict per condition and embedding declared in `terms`, in the
/// order A, B, C, label for each embedding.
std::vector<TermConditionVerdict> check_term_conditions(const Rule& rule, const ArcWords& words, const RuleTerms& terms);

/// Names of the required verdicts that fail.
std::vector<std::string> failing_names(const std::vector<TermConditionVerdict>& v);

}  // namespace dartcheck
