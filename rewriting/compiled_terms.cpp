#include "rewriting/compiled_terms.hpp"

#include <algorithm>
#include <numeric>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "rewriting/term_eval.hpp"

namespace dartcheck::compiled {

CollectSite::CollectSite(std::string embedding, std::vector<Dim> orbit)
    : name(std::move(embedding)), dims(std::move(orbit)), outer(dims_generators(dims)) {}

EachSite::EachSite(std::vector<Dim> orbit, std::vector<Dim> sub_orbit, bool per, std::string term)
    : outer(dims_generators(orbit)), sub_dims(std::move(sub_orbit)), per_sub(per), text(std::move(term)) {
  std::vector<Dim> within;  // <s> ∩ <o>: the sub-orbits inside the orbit, as the evaluator's
  for (Dim i : sub_dims)
    if (std::find(orbit.begin(), orbit.end(), i) != orbit.end()) within.push_back(i);
  sub = dims_generators(within);
}

void TermWorkspace::prepare(std::size_t used, std::size_t sites) {
  if (bags.size() < sites) bags.resize(sites);
  if (within.size() < sites) within.resize(sites);
  class_of.resize(used);
  class_count.resize(used);
  sources.resize(used);
  evaluated.clear();
  pooled.clear();
  conflicts = 0;
}

void TermWorkspace::reset(std::vector<std::uint32_t>& up, std::size_t instances) { make_singletons(up, instances); }

void TermWorkspace::flatten(std::vector<std::uint32_t>& up) {
  // Roots are the smallest instances of their classes, so one pass in
  // order finds every root already final.
  for (std::uint32_t& a : up) a = up[a];
}

void TermWorkspace::walkers_for(const Map& g) {
  if (walked_ == &g && outer_) return;
  walked_ = &g;
  outer_ = std::make_unique<OrbitWalker>(g);
  inner_ = std::make_unique<OrbitWalker>(g);
  writer_ = std::make_unique<OrbitWalker>(g);
}

const std::vector<OrbitWord>& TermWorkspace::inner_of(std::size_t bag, const CollectSite& site, const Embedding& e) {
  Within& w = within[bag];
  if (w.for_site != &site || w.for_orbit != e.signature.orbit) {
    std::vector<Dim> common;  // <o> ∩ <o'>, in <o>'s order as the evaluator's
    for (Dim i : e.signature.orbit)
      if (std::find(site.dims.begin(), site.dims.end(), i) != site.dims.end()) common.push_back(i);
    w.inner = dims_generators(common);
    w.for_orbit = e.signature.orbit;
    w.for_site = &site;
  }
  return w.inner;
}

std::span<const Value> TermWorkspace::collect(std::size_t bag, const CollectSite& site, const Map& g, const Embedding* e, Dart d) {
  if (!e) throw EvaluationError(fmt::format("the map has no embedding '{}'", site.name));
  const std::vector<OrbitWord>& inner = inner_of(bag, site, *e);
  walkers_for(g);
  std::vector<Value>& out = bags[bag];
  out.clear();
  const bool two_letters = site.outer.size() == 2 && site.outer[0].size() == 1 && site.outer[1].size() == 1;
  if (two_letters && alternate(g, site.outer[0][0], site.outer[1][0], d)) {
    if (!pairs_within(g, *e, site, inner, out)) collect_orbit_values(g, *e, cycle_, inner, *inner_, done_, out, site.name, site.dims);
  } else {
    collect_orbit_values(g, *e, outer_->orbit(d, site.outer), inner, *inner_, done_, out, site.name, site.dims);
  }
  return out;
}

std::span<const Value> TermWorkspace::collect_class(std::size_t bag, const CollectSite& site, const Map& g, const Embedding* e, std::uint32_t p,
                                                    const std::uint32_t* a, const std::uint32_t* b) {
  if (!e) throw EvaluationError(fmt::format("the map has no embedding '{}'", site.name));
  const std::vector<OrbitWord>& inner = inner_of(bag, site, *e);
  walkers_for(g);
  std::vector<Value>& out = bags[bag];
  out.clear();
  // The class of p is a path or a cycle of alternating shifts: walked as
  // `alternate` walks links, a first, then (a path) b first from p.
  cycle_.assign(1, p);
  bool closed = false;
  for (int half = 0; half < 2 && !closed; ++half) {
    const std::uint32_t* next = half == 0 ? a : b;
    const std::uint32_t* other = half == 0 ? b : a;
    for (std::uint32_t x = p;;) {
      const std::uint32_t r = next[x];
      if (r == x) break;
      if (r == p) {
        closed = true;
        break;
      }
      cycle_.push_back(r);
      x = r;
      std::swap(next, other);
    }
  }
  if (!pairs_within(g, *e, site, inner, out)) collect_orbit_values(g, *e, cycle_, inner, *inner_, done_, out, site.name, site.dims);
  return out;
}

// collect_orbit_values on the alternating walk's orbit (cycle_) when <o> ∩
// <o'> is empty or one of the walk's two letters: a pi-orbit is then a dart
// alone or a pair {x, alpha_i(x)}, both in the orbit because the walk
// checked that each of its letters is an involution there. Each pair is
// taken at its smaller dart, with no marks to set and clear; its value is
// that of its smallest labeled dart, and the multiset is sorted as there,
// so the values are the same bit for bit.
bool TermWorkspace::pairs_within(const Map& g, const Embedding& e, const CollectSite& site, std::span<const OrbitWord> inner,
                                 std::vector<Value>& out) {
  const bool alone = inner.empty();
  if (!alone && (inner.size() != 1 || inner[0].size() != 1 || (inner[0][0] != site.outer[0][0] && inner[0][0] != site.outer[1][0]))) return false;
  const Dim i = alone ? 0 : inner[0][0];
  // Pointers are sorted, not the 40-byte values: std::sort makes the same
  // comparisons and so the same permutation, and each value is copied
  // once, in order.
  sorted_.clear();
  for (const Dart x : cycle_) {
    const Dart y = alone ? x : g.link(i, x);
    if (y < x) continue;  // taken at y
    const Value* v = e.value(x);
    if (!v && y != x) v = e.value(y);
    if (!v) throw EvaluationError(fmt::format("{}<{}>: the {}-orbit of dart {} has no value", site.name, fmt::join(site.dims, ","), site.name, x));
    sorted_.push_back(v);
  }
  std::sort(sorted_.begin(), sorted_.end(), [](const Value* a, const Value* b) { return value_less(*a, *b); });
  for (const Value* v : sorted_) out.push_back(*v);
  return true;
}

// An orbit of two involutions a, b (a face <0,1> of a 2-G-map, an edge
// <0,2>) is a cycle or a path of alternating links: walked without marks,
// a then b from d until the walk is back at d or at a fixed point, then b
// then a from d. Any link that is not an involution (an invalid host) gives
// up, and the caller walks the orbit with marks; so does a walk longer
// than the map.
bool TermWorkspace::alternate(const Map& g, Dim a, Dim b, Dart d) {
  cycle_.assign(1, d);
  auto step = [&](Dim i, Dart x, Dart& next) {
    next = g.link(i, x);
    return next != no_dart && g.link(i, next) == x;
  };
  Dart x = d;
  Dim i = a;
  for (;;) {
    Dart y;
    if (!step(i, x, y)) return false;
    if (y == x) break;        // a fixed point: the orbit is a path
    if (y == d) return true;  // back at d: a cycle
    if (cycle_.size() > g.size()) return false;
    cycle_.push_back(y);
    x = y;
    i = i == a ? b : a;
  }
  x = d;  // the path's other half, from d along b first
  i = b;
  for (;;) {
    Dart y;
    if (!step(i, x, y)) return false;
    if (y == x) return true;
    if (y == d || cycle_.size() > g.size()) return false;  // a path cannot close
    cycle_.push_back(y);
    x = y;
    i = i == a ? b : a;
  }
}

const std::vector<Dart>& TermWorkspace::orbit(const Map& g, Dart d, std::span<const OrbitWord> generators) {
  walkers_for(g);
  return writer_->orbit(d, generators);
}

std::vector<Dart> TermWorkspace::each_orbit(const Map& g, Dart d, const EachSite& site) {
  walkers_for(g);
  const std::vector<Dart>& o = outer_->orbit(d, site.outer);
  return {o.begin(), o.end()};
}

void TermWorkspace::each_finish(std::vector<Value>& values, std::span<const Dart> orbit, const Map& g, const EachSite& site) {
  walkers_for(g);
  each_values(values, orbit, site.per_sub, site.sub, *inner_, site.text, site.sub_dims);
}

const Value& read(const Embedding* e, Dart d, const char* embedding, const char* term) {
  if (!e) throw EvaluationError(fmt::format("the map has no embedding '{}'", embedding));
  const Value* v = e->value(d);
  if (!v) throw EvaluationError(fmt::format("{}: dart {} has no {} value", term, d, embedding));
  return *v;
}

Dart neighbour(const Map& g, Dim i, Dart d, const char* term) {
  if (!g.model().contains(i)) throw EvaluationError(fmt::format("alpha{} is not a dimension of the map", i));
  const Dart n = g.link(i, d);
  if (n == no_dart) throw EvaluationError(fmt::format("{}: dart {} has no {}-arc", term, d, i));
  return n;
}

// As the interpreter's check: the matched darts are marked with their
// instance; each pi-orbit of G holding one is walked once, from the first
// met, and every matched dart in it must be in that instance's class.
std::string overlap(TermWorkspace& tw, const Map& g, std::span<const OrbitWord> generators, std::span<const Dart> match, std::size_t np,
                    std::span<const char* const> names, std::span<const Dart> pattern, const char* embedding) {
  constexpr std::uint32_t covered = DartTable::none - 1;
  DartTable& orbit_of = tw.given;
  const DartTable::ClearOnExit emptied{orbit_of};
  for (std::size_t k = 0; k < match.size(); ++k) orbit_of.set(match[k], static_cast<std::uint32_t>(k));
  auto name = [&](std::size_t k) {
    const std::string node = names[k / np];
    return pattern.empty() ? node : fmt::format("{}@{}", node, pattern[k % np]);
  };
  // The interpreter visits instances node by node, pattern copy by copy:
  // k = x * np + p is that order.
  for (std::size_t k = 0; k < match.size(); ++k) {
    const Dart d = match[k];
    if (orbit_of.get(d) == covered) continue;
    const std::uint32_t cls = tw.left_class[k];
    for (Dart y : tw.orbit(g, d, generators)) {
      const std::uint32_t i = orbit_of.get(y);
      if (i == DartTable::none || i == covered) continue;
      if (tw.left_class[i] != cls)
        return fmt::format(
            "nodes {} and {} are in different {}-orbits of L, but their darts {} and {} share one {}-orbit of the map (003 Lemma 3, "
            "non-overlap): the extended rule would give that orbit the labels of both",
            name(k), name(i), embedding, d, y, embedding);
      orbit_of.set(y, covered);
    }
  }
  return {};
}

void unlabel(TermWorkspace& tw, const Map& g, Embedding& e, std::span<const OrbitWord> generators, Dart d, bool extended) {
  if (!extended) {
    e.set_index(d, Embedding::none);
    return;
  }
  for (Dart x : tw.orbit(g, d, generators)) e.set_index(x, Embedding::none);
}

std::uint32_t pool_index(TermWorkspace& tw, Embedding& e, Source from) {
  if (from.stored) return from.index;
  if (tw.pooled.size() < tw.evaluated.size()) tw.pooled.resize(tw.evaluated.size(), Embedding::none);
  std::uint32_t& at = tw.pooled[from.index];
  if (at == Embedding::none) at = e.store(tw.evaluated[from.index]);
  return at;
}

void write_orbit(TermWorkspace& tw, const Map& g, Embedding& e, std::span<const OrbitWord> generators, Dart d, Source from) {
  if (const std::uint32_t w = tw.given.get(d); w != DartTable::none) {
    const TermWorkspace::Writer& first = tw.writers[w];
    const bool same = (from.index == first.from.index && from.stored == first.from.stored) || (from.stored && first.value == from.index) ||
                      e.pool[first.value] == (from.stored ? e.pool[from.index] : tw.evaluated[from.index]);
    if (same) return;
    ++tw.conflicts;
    e.set_index(d, pool_index(tw, e, from));
    return;
  }
  const std::uint32_t idx = pool_index(tw, e, from);
  const auto w = static_cast<std::uint32_t>(tw.writers.size());
  tw.writers.push_back({idx, from});
  for (Dart x : tw.orbit(g, d, generators)) {
    e.set_index(x, idx);
    tw.given.set(x, w);
  }
}

void end_writes(TermWorkspace& tw) {
  tw.given.clear();
  tw.writers.clear();
}

}  // namespace dartcheck::compiled
