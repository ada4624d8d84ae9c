// What the C++ that `dartcheck compile` generates relies on (issue 41): the
// dense Map, the refusals of the interpreter, the compaction of a derivation
// and the tables below. Generated code includes this header and nothing
// else of dartcheck, so the header set it depends on is: core/map.hpp,
// core/model.hpp, rewriting/match.hpp (Refusal), rewriting/derivation.hpp
// (compact) and this file; a rule with embedding terms adds
// rewriting/compiled_terms.hpp with rewriting/embedded_map.hpp (the map and
// its embeddings), rewriting/value.hpp, rewriting/algebra.hpp (the
// built-in functions) and core/orbit.hpp.
//
// A compiled rule is a function
//     Refusal NAME(Map& g, std::span<const Dart> hooks, compiled::Workspace& ws);
// (EmbeddedMap& instead of Map& for a rule with embedding terms)
// that applies the rule or rule scheme at the hook darts exactly as
// dartcheck::apply does (same match, same refusals before any write, same
// darts created and renumbered), writing the match, comatch and renumbering
// into `ws` instead of allocating them. On refusal `g` is unchanged and
// ws.why says why.
#pragma once

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "core/map.hpp"
#include "rewriting/compiled_terms.hpp"
#include "rewriting/pattern_walk.hpp"
#include "rewriting/compaction.hpp"
#include "rewriting/match.hpp"

namespace dartcheck::compiled {

/// The tables of one application, kept from one application to the next
/// so that a loop of small applications on a large map costs the darts
/// each one touches (as SchemeRewriter does for the interpreter).
struct Workspace {
  /// |P_v|: the darts of the hook's pattern graph (1 for a DPO rule).
  std::size_t np = 0;
  /// pattern[p]: the p-th dart of P_v in BFS order (pattern[0] the hook).
  std::vector<Dart> pattern;
  /// shift[k][p]: the position of p·w_k, w_k the k-th generator of W.
  std::vector<std::vector<std::uint32_t>> shift;
  /// match[x * np + p]: the dart of G matched by product node (p, x).
  std::vector<Dart> match;
  /// comatch[y * np + p]: the dart of H of product node (p, y).
  std::vector<Dart> comatch;
  /// Darts of G renumbered to keep H dense: (old, new).
  std::vector<std::pair<Dart, Dart>> moved;
  /// Why the last application was refused.
  std::string why;
  /// The tables of a rule with embedding terms (rewriting/compiled_terms.hpp).
  TermWorkspace terms;

  // Per-dart marks (none between applications) and the walk's queue.
  std::vector<std::uint32_t> position;
  std::vector<Dart> queue;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> work;  // (p, x) to propagate
  std::vector<Dart> holes;

  Refusal refuse(Refusal r, std::string sentence) {
    why = std::move(sentence);
    return r;
  }
  /// Sizes the per-dart tables for a map of `darts` darts and W's
  /// `generators` generators.
  void prepare(std::size_t darts, std::size_t generators) {
    if (position.size() < darts) position.resize(darts, none);
    if (queue.size() < darts + 1) queue.resize(darts + 1);
    prepare_tables(generators);
  }
  /// prepare without the per-dart marks and queue (whole_map_patterns
  /// walks nothing).
  void prepare_tables(std::size_t generators) {
    shift.resize(generators);
    for (auto& s : shift) s.clear();
    moved.clear();
    why.clear();
  }
  /// A DPO rule: one instance (np = 1), no pattern to walk.
  void prepare_dpo(std::size_t darts, std::size_t left_nodes) {
    prepare(darts, 0);
    np = 1;
    pattern.clear();
    match.assign(left_nodes, no_dart);
  }
};

/// P_v for every hook dart (002 Def. 20), by BFS along W's generators;
/// `follow(k, d)` is the dart reached from d along the k-th generator
/// (no_dart when there is no such path), a lambda the generated code
/// writes with the generator's links spelt out. Every hook's walk must give
/// the first one's shift tables (002 Sec. 6.3: one pattern for every
/// component of L). The walk is the interpreter's (pattern_walk.hpp), so
/// the positions are the interpreter's.
template <std::size_t Generators, class Follow>
Refusal walk_patterns(const Map& g, std::span<const Dart> hooks, Workspace& ws, Follow follow, const char* const* generator_names) {
  ws.prepare(g.size(), Generators);
  if (hooks.empty()) {  // L is empty (a rule that creates): one instance
    ws.pattern.clear();
    ws.np = 1;
    return Refusal::none;
  }
  const PatternWalkStop stop =
      walk_pattern_graphs(hooks, Generators, follow, ws.position, ws.queue, ws.shift, [&](std::size_t h, std::span<const Dart> darts) {
        if (h == 0) ws.pattern.assign(darts.begin(), darts.end());
      });
  if (stop.kind == PatternWalkStop::no_path)
    return ws.refuse(Refusal::not_combinatorial,
                     "dart " + std::to_string(stop.at) + " has no " + generator_names[stop.generator] + "-path: the host is not combinatorial");
  if (stop.kind == PatternWalkStop::not_isomorphic)
    return ws.refuse(Refusal::no_match, "the pattern graphs of hook darts " + std::to_string(hooks[0]) + " and " + std::to_string(hooks[stop.hook]) +
                                            " are not isomorphic (Sec. 6.3 needs one pattern for every component of L)");
  ws.np = ws.pattern.size();
  return Refusal::none;
}

/// The match of a generated everywhere function (whole_map_patterns):
/// product node (p, hook) is dart p, so match[p] is p, known to the
/// compiler as a type rather than read from a table.
struct IdentityMatch {
  constexpr Dart operator[](std::size_t p) const { return static_cast<Dart>(p); }
};

/// P for a scheme applied at every connected component at once (the
/// generated NAME_everywhere functions): when W's single-letter generators
/// name every dimension of the model, the P_v of any dart is its connected
/// component, so P over all components is the whole map. Position p is dart
/// p and shift[k][p] = follow(k, p): no walk and no dart -> position table.
/// The instantiation over this P is the disjoint union of the instantiations
/// at one hook per component, so applying it is applying the scheme at each
/// component (in any order: their darts are disjoint and no term reads
/// beyond a component); the new darts are numbered in dart order, not in a
/// BFS order from a hook, so the result is isomorphic to the sequential
/// applications', not equal. Refused when some dart has no path along a
/// generator, as walk_patterns refuses at the first such dart of P_v.
template <std::size_t Generators, class Follow>
Refusal whole_map_patterns(const Map& g, Workspace& ws, Follow follow, const char* const* generator_names) {
  ws.prepare_tables(Generators);
  const auto n = static_cast<Dart>(g.size());
  // L is the hook with a loop per letter of W (everywhere_applies): the
  // match is the identity, product node (p, hook) being dart p.
  ws.pattern.clear();
  ws.match.resize(n);
  std::iota(ws.match.begin(), ws.match.end(), Dart{0});
  // One loop per generator with its index a constant, so that follow's
  // switch folds away, writing through a raw pointer (a push_back's end
  // pointer may alias the map's link array, which forced a reload of it
  // per dart). The refusal is the one of the first generator, in W's
  // order, with a dart that has no path, at its first such dart.
  std::size_t failed = Generators;
  const auto fill = [&](auto w) {
    std::vector<std::uint32_t>& shift = ws.shift[w];
    shift.resize(n);
    std::uint32_t* const out = shift.data();
    bool complete = true;
    for (Dart d = 0; d < n; ++d) {
      const Dart t = follow(w, d);
      out[d] = t;
      complete &= t != no_dart;
    }
    if (!complete) failed = w;
    return complete;
  };
  [&]<std::size_t... W>(std::index_sequence<W...>) { (void)(fill(std::integral_constant<std::size_t, W>{}) && ...); }(std::make_index_sequence<Generators>{});
  if (failed < Generators) {
    const std::vector<std::uint32_t>& shift = ws.shift[failed];
    const auto d = static_cast<std::size_t>(std::find(shift.begin(), shift.end(), no_dart) - shift.begin());
    return ws.refuse(Refusal::not_combinatorial,
                     "dart " + std::to_string(d) + " has no " + generator_names[failed] + "-path: the host is not combinatorial");
  }
  ws.np = n;
  return Refusal::none;
}

/// The match's propagation along one instantiated arc of L: product node
/// (q, x) is dart `there`. False when it is already another dart (the
/// instantiated L would send one node to two darts).
inline bool propagate(Workspace& ws, std::uint32_t q, std::uint32_t x, Dart there) {
  Dart& slot = ws.match[x * ws.np + q];
  if (slot == no_dart) {
    slot = there;
    ws.work.emplace_back(q, x);
    return true;
  }
  return slot == there;
}

/// Every product node of the instantiated L matched (ι(L, P_v) connected)
/// and no two on one dart: the interpreter's checks, in its order.
/// `node_names` are L's node names.
inline Refusal check_match(Workspace& ws, std::size_t left_nodes, const char* const* node_names) {
  std::size_t marked = 0;
  auto unmark = [&] {
    for (std::size_t k = 0; k < marked; ++k) ws.position[ws.match[k]] = none;
  };
  // match is [x * np + p], so "the first `marked` entries" are those marked.
  for (std::size_t k = 0; k < left_nodes * ws.np; ++k) {
    const Dart d = ws.match[k];
    if (d == no_dart) {
      unmark();
      return ws.refuse(Refusal::disconnected, "node (" + std::to_string(ws.pattern[k % ws.np]) + ", " + node_names[k / ws.np] +
                                                  ") of the instantiated L is unreachable from the hooks: ι(L, P_v) is not connected, so "
                                                  "the hooks do not fix the match (002 Sec. 6.3)");
    }
    if (ws.position[d] != none) {
      unmark();
      return ws.refuse(Refusal::not_injective, "two nodes of the instantiated L match dart " + std::to_string(d));
    }
    ws.position[d] = 0;
    ++marked;
  }
  unmark();
  return Refusal::none;
}

/// After the added arcs are written: when fewer darts were added than
/// deleted, the last darts of the map fill the holes left (compact), and
/// the comatch follows their renumbering.
inline void fill_holes(Map& g, Workspace& ws, std::size_t reused) {
  if (ws.holes.size() <= reused) return;
  ws.holes.erase(ws.holes.begin(), ws.holes.begin() + static_cast<std::ptrdiff_t>(reused));
  ws.moved = compact(g, ws.holes, ws.comatch);
  // The marks (sized for G, which is larger than H here) index the moves.
  for (std::size_t k = 0; k < ws.moved.size(); ++k) ws.position[ws.moved[k].first] = static_cast<std::uint32_t>(k);
  for (Dart& d : ws.comatch)
    if (d < ws.position.size() && ws.position[d] != none) d = ws.moved[ws.position[d]].second;
  for (const auto& move : ws.moved) ws.position[move.first] = none;
}

}  // namespace dartcheck::compiled
