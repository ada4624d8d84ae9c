// Orbits <o>(d) (000 Def. 3.2) and cells.
//
// An orbit is the set of darts reachable from d along the generators of an
// orbit type. For G-maps the generators are single dimensions; for O-maps a
// vertex needs composed links (002 Sec. 3.3: "orbits in O-maps require
// considering paths"), so a generator is a word: the dart reached by the
// word's path. Forward reachability is the whole orbit here because every
// generator of a valid map is a permutation of a finite set.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "core/map.hpp"

namespace dartcheck {

/// An orbit word: a path of dimensions (O-map generators such as 21),
/// not a conjugate word (core/conjugate_words) nor 001's query word.
using OrbitWord = std::vector<Dim>;

/// Target of the w-path from d, or no_dart if an arc is missing.
inline Dart follow(const Map& map, Dart d, std::span<const Dim> w) {
  for (Dim i : w) {
    if (d == no_dart) break;
    d = map.link(i, d);
  }
  return d;
}

/// The generators of the orbit type of the k-cells of the map's model:
/// <D \ {k}> for G-maps and for k >= 1 in O-maps; {j1 : 2 <= j <= n} for the
/// vertices of O-maps (both letters keep the dart's origin vertex).
std::vector<OrbitWord> cell_generators(const Model& model, int k);
/// Generators of an orbit type given as a set of dimensions.
std::vector<OrbitWord> dims_generators(const std::vector<Dim>& dims);

/// Traverses orbits with a reusable visited mark: one bit per dart,
/// allocated once (and grown when the map grows); each traversal clears
/// only the darts it marked, so a call costs time proportional to the
/// orbit, not to the map.
class OrbitWalker {
 public:
  explicit OrbitWalker(const Map& map);

  /// The darts of the orbit of d under `generators`, in BFS order.
  const std::vector<Dart>& orbit(Dart d, std::span<const OrbitWord> generators);

  /// Number of distinct orbits of `generators` over the whole map.
  std::size_t count_orbits(std::span<const OrbitWord> generators);

 private:
  bool marked(Dart d) const { return (marks_[d >> 6] >> (d & 63)) & 1U; }
  void mark(Dart d) { marks_[d >> 6] |= std::uint64_t{1} << (d & 63); }
  void unmark(Dart d) { marks_[d >> 6] &= ~(std::uint64_t{1} << (d & 63)); }
  void traverse(Dart d, std::span<const OrbitWord> generators);
  // The map may have grown since the walker was made (a walker kept across
  // rule applications).
  void fit() {
    if (marks_.size() * 64 < map_.size()) marks_.resize((map_.size() + 63) / 64, 0);
  }

  const Map& map_;
  std::vector<std::uint64_t> marks_;
  std::vector<Dart> visited_;
};

/// One visit per class of darts: for each dart d of `candidates`, in order,
/// whose class no earlier visit covered, `visit(d, members)` with
/// `members = walk(d)`, every element of d's class, each then marked
/// covered. Elements are indices below `size` (darts, or positions in a
/// list of darts). The one "one dart per orbit" loop: orbits, faces
/// walked by hand, components, the sub-orbits of an orbit.
template <class Candidates, class Walk, class Visit>
void for_each_class(std::size_t size, const Candidates& candidates, Walk&& walk, Visit&& visit) {
  std::vector<bool> covered(size, false);
  for (const auto d : candidates) {
    if (covered[static_cast<std::size_t>(d)]) continue;
    const auto& members = walk(d);
    for (const auto x : members) covered[static_cast<std::size_t>(x)] = true;
    visit(d, members);
  }
}

/// The integers [0, n) as a range (for_each_class's candidates). Not
/// std::views::iota: clang 14, which builds the fuzz targets, cannot
/// compile libstdc++ 12's <ranges>.
template <class Index>
struct IndexRange {
  struct iterator {
    Index i;
    Index operator*() const { return i; }
    iterator& operator++() {
      ++i;
      return *this;
    }
    bool operator!=(const iterator& o) const { return i != o.i; }
  };
  Index n;
  iterator begin() const { return {Index{0}}; }
  iterator end() const { return {n}; }
};
inline IndexRange<Dart> all_darts(std::size_t n) { return {static_cast<Dart>(n)}; }

/// Every orbit of `generators` once, from its smallest dart, in increasing
/// order: `visit(d, orbit)` with the orbit's darts in `walker`'s BFS order
/// (valid until the walker walks again: `visit` uses another walker).
template <class Visit>
void for_each_orbit(OrbitWalker& walker, const Map& map, std::span<const OrbitWord> generators, Visit&& visit) {
  for_each_class(
      map.size(), all_darts(map.size()), [&](Dart d) -> const std::vector<Dart>& { return walker.orbit(d, generators); }, visit);
}

/// The orbits of `generators` over the whole map, numbered in the order of
/// their smallest darts: `of[d]` is the number of d's orbit and `first[k]`
/// the smallest dart of orbit k, one dart per orbit (CGAL's
/// one_dart_per_cell). One walk of the map, O(|darts| x |generators|).
struct OrbitPartition {
  std::vector<std::uint32_t> of;
  std::vector<Dart> first;
  std::size_t size() const { return first.size(); }
};
OrbitPartition partition_orbits(const Map& map, std::span<const OrbitWord> generators);

/// Cell counts of a map: cells[k] is the number of k-cells, k = 0..n;
/// components is the number of connected components.
struct CellCounts {
  std::vector<std::size_t> cells;
  std::size_t components = 0;
  /// Alternating sum of the cell counts (the Euler characteristic of a
  /// closed surface for n = 2).
  long long euler() const;
};

CellCounts count_cells(const Map& map);

/// The links of one dimension: arcs (darts with a partner) and loops.
struct LinkCount {
  Dim dim = 0;
  std::size_t arcs = 0, loops = 0;
};

std::vector<LinkCount> count_links(const Map& map);

}  // namespace dartcheck
