// Internal to rewriting/ (the Applier, rewriting/application.hpp, is the
// one way in): the direct derivation G =>(r,m) H of a DPO rule on a dense
// map (002 Def. 4): delete m(L \ K), add R \ K, glue along K.
#pragma once

#include <span>
#include <vector>

#include "rewriting/compaction.hpp"
#include "rewriting/match.hpp"

namespace dartcheck {

struct Derivation {
  Match match;                // L -> G, in G's dart numbering
  std::vector<Dart> comatch;  // R -> H, in H's dart numbering
  /// Darts of G that H renumbered to fill the slots of deleted darts
  /// (H keeps its darts dense): (old, new).
  std::vector<std::pair<Dart, Dart>> moved;
};

/// Rewrites `g` into H in place along a match from match_from_hooks.
/// Costs O((|L| + |R|) * |D|) plus O(|D|) per renumbered dart: independent
/// of the size of `g`. On refusal (the dangling condition, or an H that
/// would give a dart two i-arcs) `g` is left unchanged and the outcome
/// says why.
Outcome<Derivation> rewrite_rule(const Rule& rule, Map& g, Match match);

/// match_from_hooks, then rewrite_rule (a refusal of either).
Outcome<Derivation> apply_rule(const Rule& rule, Map& g, std::span<const Dart> hook_darts);

}  // namespace dartcheck
