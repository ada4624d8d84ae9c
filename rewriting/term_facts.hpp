// What an embedded application derives from a rule and its terms alone
// (TermFacts), and how it evaluates R's terms (Evaluation): shared by the
// interpreter (rewriting/embedded_rewriter.cpp, behind the Applier) and
// `dartcheck compile`, so both decide alike.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "rewriting/rule.hpp"
#include "rewriting/rule_terms.hpp"

namespace dartcheck {

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

}  // namespace dartcheck
