// The pattern graph P_v of a rule scheme's hook darts (002 Def. 20) and
// what an application derives from the scheme alone (SchemeFacts): the
// parts of scheme application that renderers and `dartcheck compile` read.
// The application itself is rewriting/application.hpp's Applier.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "rewriting/match.hpp"
#include "rewriting/rule.hpp"

namespace dartcheck {

/// The pattern graphs of the hook darts (002 Def. 20): W's words and their
/// conjugates as generators, the darts of each P_{v_k} in BFS order
/// (darts[k][0] is the hook dart), and shift[w][p], the position of p·w
/// in P_v. With several hooks every pattern has the same shift tables.
struct PatternGraphs {
  std::vector<ConjWord> gens;
  std::vector<std::vector<Dart>> darts;
  std::vector<std::vector<std::uint32_t>> shift;
  /// The position of p·w for a word w of the scheme (ε stays at p).
  std::uint32_t step(std::size_t p, const ConjWord& w) const { return step(p, generator(w)); }
  /// The index of w in gens, -1 for ε: step(p, generator(w)) spares the
  /// search when one word is followed from every position.
  int generator(const ConjWord& w) const;
  std::uint32_t step(std::size_t p, int generator) const {
    return generator < 0 ? static_cast<std::uint32_t>(p) : shift[static_cast<std::size_t>(generator)][p];
  }
};

/// W's generators: the words of the scheme's arcs, each with its
/// conjugate (P_v takes the darts reachable to and from v), without ε or
/// repeats, in the order the walk of P_v follows them.
std::vector<ConjWord> scheme_generators(const Model& model, const ArcWords& words);

/// What an application of a scheme derives from the rule alone, in the
/// order match_scheme checks it. The interpreter (SchemeRewriter) computes
/// it once per rewriter; `dartcheck compile` generates code from it, so
/// both refuse on the same facts.
struct SchemeFacts {
  std::vector<ConjWord> gens;  // scheme_generators
  /// L is the hook alone with a loop x -(i,i)-> x per non-oriented letter
  /// of W: product node (p, hook) is the p-th dart of P_v.
  bool identity_match = false;
  /// Non-empty when L has two i-arcs out of one node: refused at every match.
  std::string two_arcs_in_l;
  /// A deleted node x without an L arc out of (into) it in dimension i:
  /// its darts must carry no i-arc out (in).
  struct Dangling {
    NodeId x;
    Dim i;
    bool out, in;
  };
  std::vector<Dangling> dangling;
  /// Per arc of R \ K: a refusal of the rule itself (`always`), or the L
  /// node x whose darts must be free in the arc's dimension unless L \ K
  /// frees it and K keeps none.
  struct Added {
    ArcId arc;
    std::string always;
    NodeId x = no_node;
    Dim label = 0;
    bool freed = false, kept = false;
  };
  std::vector<Added> added;
  std::size_t added_nodes = 0;  // nodes of R \ K
};
SchemeFacts scheme_facts(const Rule& core, const ArcWords& words);

/// Refuses when a word has no path from a pattern dart
/// (not-combinatorial) or when two hooks' pattern graphs differ (no-match).
Outcome<PatternGraphs> pattern_graphs(const Model& model, const ArcWords& words, const Map& g, std::span<const Dart> hook_darts);

}  // namespace dartcheck
