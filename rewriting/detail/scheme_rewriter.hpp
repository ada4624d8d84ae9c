// Internal to rewriting/ (the Applier, rewriting/application.hpp, is the
// one way in): application of a rule scheme to a dense map (002 Sec. 6.3): the pattern
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
#include "rewriting/detail/derivation.hpp"
#include "rewriting/pattern_graphs.hpp"

namespace dartcheck {

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
