// Disjoint sets of the integers 0..n-1 (union-find): the one
// implementation that groups nodes into orbits, darts into classes and
// instances into cells, in the checkers, the event analysis, the readers,
// the rewriting engines and the compiled operations.
//
// A set is named by its representative; a table `up` holds each element's
// parent (up[x] == x: x represents its set). Two ways to join, because the
// representative is read by callers (as a class number, a bucket, an
// order): `join` keeps the smaller representative, so that a set's
// representative is its smallest element whatever the order of the joins;
// `attach` puts one set under the other's representative.
//
// The free functions work on a table the caller owns (scratch memory kept
// between applications, or the compiled operations' workspace); the class
// owns its table.
#pragma once

#include <cstddef>
#include <cstdint>
#include <numeric>
#include <vector>

namespace dartcheck {

/// `up` becomes n singletons (its memory kept for the next use).
template <class Index>
void make_singletons(std::vector<Index>& up, std::size_t n) {
  up.resize(n);
  std::iota(up.begin(), up.end(), Index{0});
}

// The table: a std::vector, or a std::array in a hot loop that must not
// allocate.

/// The representative of x's set; halves the path on the way.
template <class Table>
typename Table::value_type find_representative(Table& up, typename Table::value_type x) {
  while (up[static_cast<std::size_t>(x)] != x) x = up[static_cast<std::size_t>(x)] = up[static_cast<std::size_t>(up[static_cast<std::size_t>(x)])];
  return x;
}

/// Joins the sets of a and b; the union is represented by the smaller of
/// their two representatives.
template <class Table>
void join_sets(Table& up, typename Table::value_type a, typename Table::value_type b) {
  a = find_representative(up, a);
  b = find_representative(up, b);
  if (a != b) up[static_cast<std::size_t>(a < b ? b : a)] = a < b ? a : b;
}

/// Joins a's set into b's: the union is represented by b's representative.
template <class Table>
void attach_set(Table& up, typename Table::value_type a, typename Table::value_type b) {
  a = find_representative(up, a);
  up[static_cast<std::size_t>(a)] = find_representative(up, b);
}

/// Every entry its representative (callers that read them in bulk).
template <class Table>
void flatten_sets(Table& up) {
  for (std::size_t x = 0; x < up.size(); ++x) up[x] = find_representative(up, static_cast<typename Table::value_type>(x));
}

/// The same over a table of its own.
template <class Index = std::uint32_t>
class DisjointSets {
 public:
  DisjointSets() = default;
  explicit DisjointSets(std::size_t n) { reset(n); }

  /// n singletons.
  void reset(std::size_t n) { make_singletons(up_, n); }
  std::size_t size() const { return up_.size(); }

  Index find(Index x) { return find_representative(up_, x); }
  void join(Index a, Index b) { join_sets(up_, a, b); }
  void attach(Index a, Index b) { attach_set(up_, a, b); }
  /// Every element's representative.
  const std::vector<Index>& representatives() {
    flatten_sets(up_);
    return up_;
  }

 private:
  std::vector<Index> up_;
};

}  // namespace dartcheck
