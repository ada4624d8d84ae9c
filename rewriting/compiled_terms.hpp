// The embedding part of compiled operations (issue 41): what the C++ that
// `dartcheck compile` generates for a rule with terms (003) calls at run
// time. The rule-dependent work is generated: each term as straight-line
// calls of rewriting/algebra.hpp, the classes of the instantiated sides as
// one union per arc and pattern position, the writes per node. What depends
// on the host is here, written once for the interpreter and the compiled
// code where it can be (a collect's multiset is collect_orbit_values, the
// evaluator's own), so a compiled rule writes the interpreter's values.
#pragma once

#include <algorithm>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "core/dart_table.hpp"
#include "core/disjoint_sets.hpp"
#include "core/orbit.hpp"
#include "rewriting/algebra.hpp"
#include "rewriting/embedded_map.hpp"

namespace dartcheck::compiled {

/// An unset entry of the compiled runtime's per-dart and per-instance tables.
inline constexpr std::uint32_t none = 0xffffffffU;

/// Where the value of a labeled instance (or class) of R is: a stored value
/// of G kept by the rule (an index into the embedding's pool) or one the
/// application evaluated (an index into TermWorkspace::evaluated).
struct Source {
  std::uint32_t index = Embedding::none;
  bool stored = false;
};

/// A collect pi<o'>(x) of a term, known when the code is generated: its
/// embedding's name and <o'>. Immutable (the generated code keeps it in a
/// function-local static, shared by every thread).
struct CollectSite {
  CollectSite(std::string embedding, std::vector<Dim> orbit);
  std::string name;
  std::vector<Dim> dims;
  std::vector<OrbitWord> outer;
};

/// An each(x in <o>(y): t) or each(x in <o>_<s>(y): t) of a term (Jerboa's
/// loop over an orbit's darts), known when the code is generated: the
/// generators of <o> and of <s> ∩ <o>, and the term's text and <s> for
/// the message of a sub-orbit whose darts give two values. Immutable.
struct EachSite {
  EachSite(std::vector<Dim> orbit, std::vector<Dim> sub_orbit, bool per_sub, std::string text);
  std::vector<OrbitWord> outer, sub;
  std::vector<Dim> sub_dims;
  bool per_sub;
  std::string text;
};

/// The tables of an application's terms, kept from one application to the
/// next (a member of compiled::Workspace).
struct TermWorkspace {
  /// One bag per collect of the function (a term may hold several, each
  /// lent to its call while the others are evaluated).
  std::vector<std::vector<Value>> bags;
  /// Per collect: the generators of <o> ∩ <o'>, which depend on the map's
  /// embedding pi : <o> (as in the evaluator), found at the first collect
  /// and kept while the site and the map's <o> stay the same (a workspace
  /// may serve several compiled functions, whose collects share numbers).
  struct Within {
    const CollectSite* for_site = nullptr;
    std::vector<Dim> for_orbit;
    std::vector<OrbitWord> inner;
  };
  std::vector<Within> within;
  /// class_of[u]: the classes of the instances of R for the u-th
  /// embedding the rule labels, numbered 0 .. class_count[u] - 1, at
  /// [group * np + p] where the generated code found groups of nodes (nodes
  /// joined by arcs of the orbit with the empty word: their instances in one
  /// copy p share a class), at [y * np + p] (a union-find root) otherwise.
  std::vector<std::vector<std::uint32_t>> class_of;
  std::vector<std::uint32_t> class_count;
  std::vector<std::uint32_t> stack;       // of the walks that number the classes
  std::vector<std::uint32_t> left_class;  // of L, for Lemma 3
  /// sources[u][c]: the value of class c (or of instance k * np + p when
  /// each instance has its own).
  std::vector<std::vector<Source>> sources;
  std::vector<Value> evaluated;
  std::vector<std::uint32_t> pooled;   // evaluated[i]'s pool index once stored
  std::vector<std::uint32_t> pool_of;  // per class: the pool index written
  /// The orbits of H written by walking (Def. 12): the writer of each dart.
  DartTable given;
  struct Writer {
    std::uint32_t value;
    Source from;
  };
  std::vector<Writer> writers;
  /// Orbits given two values (003 Def. 13: the propagation does not
  /// exist); H keeps both, as the interpreter's. Never for a rule the
  /// static checker calls consistent (Thm 4).
  std::size_t conflicts = 0;
  /// How often the kept-label shortcut of compiler/term_compiler.cpp
  /// (kept_groups) was taken and how often its check failed and the
  /// classes were walked: the differential test needs both.
  std::size_t shortcuts = 0, shortcut_fallbacks = 0;

  /// Sizes the per-application tables: `used` embeddings labeled, `sites`
  /// collects in the function.
  void prepare(std::size_t used, std::size_t sites);
  /// The union-find of one side's instances (`instances` = nodes * np).
  static void reset(std::vector<std::uint32_t>& up, std::size_t instances);
  static std::uint32_t find(std::vector<std::uint32_t>& up, std::uint32_t a) { return find_representative(up, a); }
  /// The smaller instance is the root (flatten relies on it).
  static void unite(std::vector<std::uint32_t>& up, std::uint32_t a, std::uint32_t b) { join_sets(up, a, b); }
  /// Every entry its root.
  static void flatten(std::vector<std::uint32_t>& up);

  /// The multiset of `site` from dart d (collect_orbit_values), in this
  /// site's bag. Throws EvaluationError when the map lacks the embedding.
  std::span<const Value> collect(std::size_t bag, const CollectSite& site, const Map& g, const Embedding* e, Dart d);
  /// collect(bag, site, g, e, p) in an everywhere function (positions are
  /// darts) when site's orbit is the class of p in a group whose classes
  /// alternating_classes numbered along the shifts `a` and `b` of site's
  /// two letters: the class is that orbit, walked on the shift tables with
  /// no involution to check (alternating_classes checked them).
  std::span<const Value> collect_class(std::size_t bag, const CollectSite& site, const Map& g, const Embedding* e, std::uint32_t p,
                                       const std::uint32_t* a, const std::uint32_t* b);
  /// The darts of d's <o>-orbit for `site`, in the evaluator's order (a
  /// copy: the body's collects walk while the loop runs).
  std::vector<Dart> each_orbit(const Map& g, Dart d, const EachSite& site);
  /// The each's multiset from its body's values on `orbit` (each_values,
  /// the evaluator's own): one per sub-orbit where the site says, sorted.
  void each_finish(std::vector<Value>& values, std::span<const Dart> orbit, const Map& g, const EachSite& site);
  /// The darts of d's orbit under `generators` in H (a walk).
  const std::vector<Dart>& orbit(const Map& g, Dart d, std::span<const OrbitWord> generators);

 private:
  void walkers_for(const Map& g);
  const std::vector<OrbitWord>& inner_of(std::size_t bag, const CollectSite& site, const Embedding& e);
  bool alternate(const Map& g, Dim a, Dim b, Dart d);
  bool pairs_within(const Map& g, const Embedding& e, const CollectSite& site, std::span<const OrbitWord> inner, std::vector<Value>& out);
  std::vector<Dart> cycle_;
  std::vector<const Value*> sorted_;  // pairs_within's multiset, sorted
  const Map* walked_ = nullptr;
  std::unique_ptr<OrbitWalker> outer_, inner_, writer_;
  std::vector<std::uint64_t> done_;
};

/// Room for `more` further elements of v, growing geometrically: one
/// reallocation instead of the doublings of a long run of push_back, and
/// none in a loop of small applications (a reserve of the exact size
/// would reallocate at each).
template <class T>
void reserve_more(std::vector<T>& v, std::size_t more) {
  if (v.size() + more > v.capacity()) v.reserve(std::max(v.size() + more, 2 * v.capacity()));
}

/// x.pi: the value of e at d, or EvaluationError naming `term` (the map
/// has no embedding pi, or d has no pi value).
const Value& read(const Embedding* e, Dart d, const char* embedding, const char* term);
/// x.alpha_i: d's i-neighbour, or EvaluationError naming `term`.
Dart neighbour(const Map& g, Dim i, Dart d, const char* term);

/// 003 Lemma 3 for one embedding pi : <o> (`generators` of <o>): instances
/// of L in different classes (`left_class`, by x * np + p) must match darts
/// in different pi-orbits of G. Returns why not, or an empty string.
/// `names` are L's nodes, `pattern` P_v's darts (empty for a DPO rule).
std::string overlap(TermWorkspace& tw, const Map& g, std::span<const OrbitWord> generators, std::span<const Dart> match, std::size_t np,
                    std::span<const char* const> names, std::span<const Dart> pattern, const char* embedding);

/// The label of a preserved node of L that R does not label is dropped
/// from its dart (`direct`) or its whole pi-orbit of H (`extended`).
void unlabel(TermWorkspace& tw, const Map& g, Embedding& e, std::span<const OrbitWord> generators, Dart d, bool extended);

/// The pool index of a source's value in e, storing an evaluated value on
/// its first write (once: later writes of it share the entry).
std::uint32_t pool_index(TermWorkspace& tw, Embedding& e, Source from);

/// Def. 12 where R is not closed under <o>: the value of `from` goes to the
/// whole pi-orbit of d in H, unless an earlier writer gave it one (equal:
/// nothing to do; different: a conflict, and d alone takes the second
/// value, as in the interpreter). `given` and `writers` are per embedding:
/// clear them (end_writes) before the next one.
void write_orbit(TermWorkspace& tw, const Map& g, Embedding& e, std::span<const OrbitWord> generators, Dart d, Source from);
void end_writes(TermWorkspace& tw);

/// The classes of one group of R's nodes whose loop words are two single
/// letters of non-oriented dimensions (a face <0,1>, an edge <0,2>, a
/// vertex <1,2> of a G-map): their shift tables `a` and `b` are
/// involutions of the positions, so a class is a path or a cycle of
/// alternating shifts, walked without a stack. `cls` is the group's row
/// (np entries, none where unnumbered); classes are numbered from `count`
/// in order of their smallest position, as the stack walk numbers them,
/// so the rows are equal. Returns false, with the row reset to none and
/// `count` unchanged, if a shift is not an involution there (a host that
/// is not a G-map); the caller then walks with the stack.
inline bool alternating_classes(std::uint32_t* cls, const std::uint32_t* a, const std::uint32_t* b, std::size_t np, std::uint32_t& count) {
  const std::uint32_t first = count;
  auto fail = [&] {
    std::fill(cls, cls + np, none);
    count = first;
    return false;
  };
  for (std::uint32_t p0 = 0; p0 < np; ++p0) {
    if (cls[p0] != none) continue;
    cls[p0] = count;
    bool cycle = false;
    for (int half = 0; half < 2 && !cycle; ++half) {
      // First half a, b, a, ...; second (a path only) b, a, b, ...
      const std::uint32_t* next = half == 0 ? a : b;
      const std::uint32_t* other = half == 0 ? b : a;
      std::uint32_t x = p0;
      for (std::size_t steps = 0;; ++steps) {
        const std::uint32_t r = next[x];
        if (r >= np || next[r] != x || steps > np) return fail();
        if (r == x) break;  // a fixed point: the end of a path
        if (r == p0) {
          if (half == 1) return fail();  // a path cannot close
          cycle = true;
          break;
        }
        if (cls[r] != none) return fail();
        cls[r] = count;
        x = r;
        std::swap(next, other);
      }
    }
    ++count;
  }
  return true;
}

}  // namespace dartcheck::compiled
