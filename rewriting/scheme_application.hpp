// Application of a rule scheme to a dense map (002 Sec. 6.3): the pattern
// graph P_v of the hook dart (the darts reachable along the words of the
// scheme, 002 Def. 20), the instantiated rule ι(S, P_v) = π_D(E_D(P_v) × S)
// (Def. 19), its unique match sending (v, hook) to v, and the direct
// derivation. The instantiated rule is never built as a graph: node (p, x)
// of the product is the pair (pattern node, scheme node), so application
// costs O(|P_v| · (|L| + |R|)) link operations, linear in the size of the
// instantiated rule.
#pragma once

#include <memory>
#include <span>

#include "core/dart_table.hpp"
#include "rewriting/derivation.hpp"

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

/// The match of the instantiated L: node[x][p] is the dart matched by
/// product node (p, x), p a position in the first hook's pattern.
struct SchemeMatch {
  PatternGraphs pattern;
  std::vector<std::vector<Dart>> node;
};

struct SchemeDerivation {
  std::size_t pattern_nodes = 0;  // |P_v|
  std::size_t matched_darts = 0;  // |P_v| · |V_L|
  std::size_t added_darts = 0;
  std::vector<std::pair<Dart, Dart>> moved;  // renumbered darts of H
  /// comatch[y][p]: the dart of H of product node (p, y), y in R.
  std::vector<std::vector<Dart>> comatch;
};

/// Everything apply_scheme checks before it writes: the match and its
/// refusals. `g` is not modified. (A SchemeRewriter keeps its tables for
/// the next match.)
Outcome<SchemeMatch> match_scheme(const Rule& core, const ArcWords& words, const Map& g, std::span<const Dart> hook_darts);
/// The rewrite of apply_scheme along a match from match_scheme on `g`.
SchemeDerivation rewrite_scheme(const Rule& core, const ArcWords& words, Map& g, const SchemeMatch& match);

/// Applies one scheme many times: what the application derives from the
/// rule alone (W's generators and their conjugates, each arc's generator,
/// L's arcs per node, the refusals that do not depend on the host) is
/// computed once, and the tables of an application (pattern positions,
/// shift tables, the match, the comatch) keep their memory for the next.
/// match + rewrite (or apply) give exactly what match_scheme +
/// rewrite_scheme give. The rule and words must outlive the rewriter.
class SchemeRewriter {
 public:
  SchemeRewriter(const Rule& core, const ArcWords& words);
  ~SchemeRewriter();
  SchemeRewriter(const SchemeRewriter&) = delete;
  SchemeRewriter& operator=(const SchemeRewriter&) = delete;

  /// match_scheme: `g` is not modified.
  Outcome<SchemeMatch> match(const Map& g, std::span<const Dart> hook_darts);
  /// rewrite_scheme along a match of this rewriter on `g`.
  SchemeDerivation rewrite(Map& g, const SchemeMatch& match);
  /// apply_scheme; the match's tables are kept for the next application.
  Outcome<SchemeDerivation> apply(Map& g, std::span<const Dart> hook_darts);
  /// Hand a match's or a derivation's tables back for the next application.
  void recycle(SchemeMatch&& m);
  void recycle(SchemeDerivation&& d);

 private:
  struct State;
  std::unique_ptr<State> s_;
};

/// Rewrites `g` at the hook darts, one per connected component of L (the
/// order of core.hooks()). With several hooks the pattern graphs of the
/// hook darts must be isomorphic, hook onto hook (002 Sec. 6.3); each
/// component of L is then instantiated on its own hook's pattern. Refuses,
/// leaving `g` unchanged, when a word has no path from a pattern node
/// (not-combinatorial), when the instantiated L does not match (no-match,
/// not-injective, or pattern graphs that differ), breaks the dangling
/// condition, or would give a dart two i-arcs (not-representable).
Outcome<SchemeDerivation> apply_scheme(const Rule& core, const ArcWords& words, Map& g, std::span<const Dart> hook_darts);

}  // namespace dartcheck
