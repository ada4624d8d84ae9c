// The embedding-presence checks of Jerboa's rule editor (003 Sec. 5.2,
// Theorem 2), on rules whose R nodes carry opaque embedding expressions.
// For an embedding pi : <o> -> tau, the pi-orbit of a node of a side is its
// connected component through explicit arcs labeled in <o>: a Jerboa
// node's implicit arcs only join copies of the same node, so they never
// join two nodes' orbits.
//
//  - defined(pi): an added node whose pi-orbit in R holds no preserved
//    node gets its value from nowhere unless some node of that orbit
//    carries a pi-expression (the value is then propagated, 003 Def. 12).
//  - merge(pi): preserved nodes in different pi-orbits of L that share one
//    pi-orbit of R bring two values into one orbit unless some node of
//    that orbit carries a pi-expression (Theorem 2 (C)).
//  - one-value(pi): two nodes of one pi-orbit of R carry different
//    pi-expressions (Theorem 2 (A), terms compared as text).
//
// Like Theorem 2's conditions these are sufficient, not necessary: merged
// orbits may hold equal values on a given map, and two different texts
// may compute one value.
#pragma once

#include <string>
#include <vector>

#include "checkers/rule_conditions.hpp"
#include "rewriting/operation.hpp"

namespace dartcheck {

enum class EmbeddingCondition { defined, merge, one_value };

struct EmbeddingVerdict {
  EmbeddingCondition condition;
  std::string embedding;
  bool holds = true;
  std::vector<RuleWitness> witnesses;  // side 'R' (or 'L'), nodes named
  /// "defined(pos)", "merge(pos)", "one-value(pos)".
  std::string name() const;
};

/// One verdict per condition and embedding of `embeddings`, in that order.
std::vector<EmbeddingVerdict> check_embedding_presence(const Rule& rule, const ArcWords& words, const std::vector<EmbeddingDecl>& embeddings,
                                                       const std::vector<NodeExpression>& expressions);

/// The names of the verdicts that fail.
std::vector<std::string> failing_names(const std::vector<EmbeddingVerdict>& v);

}  // namespace dartcheck
