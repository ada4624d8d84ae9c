// The direct derivation G =>(r,m) H on a dense map (002 Def. 4): delete
// m(L \ K), add R \ K, glue along K.
#pragma once

#include <span>
#include <vector>

#include "rewriting/match.hpp"

namespace dartcheck {

struct Derivation {
  Match match;                // L -> G, in G's dart numbering
  std::vector<Dart> comatch;  // R -> H, in H's dart numbering
  /// Darts of G that H renumbered to fill the slots of deleted darts
  /// (H keeps its darts dense): (old, new).
  std::vector<std::pair<Dart, Dart>> moved;
};

/// Rewrites `g` into H in place. Costs O((|L| + |R|) * |D|) plus O(|D|)
/// per renumbered dart: independent of the size of `g`. On refusal (no
/// match, dangling condition, or an H that would give a dart two i-arcs)
/// `g` is left unchanged and the outcome says why.
Outcome<Derivation> apply_rule(const Rule& rule, Map& g, std::span<const Dart> hook_darts);

/// Keeps a map dense after deleting darts: the `holes` (darts with no arc
/// left) are filled with the last darts, which are renumbered, and the map
/// is truncated. Returns the renumberings (old, new).
/// `sources` are the darts a rule gave new arcs (in g's numbering before
/// the call): a rule that breaks O may leave a non-oriented arc without its
/// reverse, which Map::relocate cannot find, so their arcs into moved darts
/// are redirected here.
std::vector<std::pair<Dart, Dart>> compact(Map& g, std::vector<Dart> holes, std::span<const Dart> sources = {});

}  // namespace dartcheck
