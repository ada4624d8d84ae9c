// Topological words and query words (001 Sec. 3.3 and 5.1): a map read as
// the sequence of its darts' neighbours under a breadth-first labeling.
//
// 001 defines them on 3-maps (β1, β2, β3 with β3 possibly free); here the
// letters are the dimensions of any dartcheck model in ascending order, so
// the same code reads n-O-maps and n-G-maps. A link is free (001's ε) when
// it is missing (a partial dimension) or a fixed point of an involution (a
// G-map's loop); a fixed point of the permutation β1 is a 1-gon, not free.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "core/map.hpp"

namespace dartcheck::querymodify {

/// True if the i-link of d is free (see above).
bool is_free(const Map& m, Dim i, Dart d);

/// A BFS labeling (001 Def. 3): darts[k - 1] is the dart labeled k, from
/// `start` (label 1), neighbours taken by increasing dimension, labels in
/// prefix order. Covers the connected component of `start`.
struct Labeling {
  std::vector<Dart> darts;
  /// label[d]: the label of dart d, 0 if d is not in the component.
  std::vector<std::uint32_t> label;
};
Labeling bfs_labeling(const Map& m, Dart start);

/// The word of (M, l) (001 Def. 4): for each label k and each dimension i
/// of the model in ascending order, the label of the i-neighbour of d_k,
/// 0 when it is free. Length |dims| * |D|. Two connected maps are
/// isomorphic iff they have labelings giving the same word.
std::vector<std::uint32_t> word(const Map& m, const Labeling& l);

/// Boundary conditions on a free link of a query dart (001 Sec. 5.1.2),
/// not the map constraints a rule must preserve (checkers/violation.hpp).
enum class BoundaryCondition : std::uint32_t {
  any = 0xFFFFFFFF,            // '*': matches any input dart, free or not
  boundary = 0xFFFFFFFE,       // 'ε': the input link must be free
  interior = 0xFFFFFFFD,       // 'ε̄': the input link must not be free
  no_connection = 0xFFFFFFFC,  // '↔': must not reach another matched dart
};
/// True for the four special letters.
constexpr bool is_boundary_condition(std::uint32_t letter) { return letter >= static_cast<std::uint32_t>(BoundaryCondition::no_connection); }
const char* boundary_symbol(BoundaryCondition c);

/// A query word (001 Def. 5): the word of a query map whose free links
/// carry boundary conditions instead of 0.
struct QueryWord {
  std::vector<Dim> dims;               // the letters' dimensions, ascending
  std::vector<std::uint32_t> letters;  // |dims| * darts entries
  std::size_t darts = 0;
  std::uint32_t at(std::uint32_t label, std::size_t letter) const { return letters[(label - 1) * dims.size() + letter]; }
};

/// The query word of `query` labeled from `start`; every free link gets
/// `free_links`, except those listed in `overrides` (query dart, dimension,
/// condition). Throws ValueError if the query is not connected
/// (001 Sec. 5: queries are connected) or an override names a link that is
/// not free.
struct BoundaryOverride {
  Dart dart;
  Dim dim;
  BoundaryCondition condition;
};
QueryWord query_word(const Map& query, Dart start, BoundaryCondition free_links = BoundaryCondition::any,
                     const std::vector<BoundaryOverride>& overrides = {});

/// "1 2 ε | 3 1 * | ..." for messages and tests.
std::string word_text(const QueryWord& w);

}  // namespace dartcheck::querymodify
