// Matching query words on a map (001 Sec. 5): Algorithm 1, the
// annotation of the input from a start dart with the boundary-condition
// table of Sec. 5.1.2, for one query word and for a prefix tree of many
// (Sec. 5.2.1).
//
// The constraint table, for the letter c of (label k, dimension i) and
// d_i the i-neighbour of the dart labeled k:
//
//   d_i                  | label c      | *  | ε  | ε̄  | ↔
//   free                 | no           | ok | ok | no | ok
//   not annotated        | annotate c   | ok | no | ok | annotate ∅
//   annotated with a     | a = c        | ok | no | ok | no
//   label                |              |    |    |    |
//   annotated ∅          | no           | ok | no | ok | ok
//
// "annotate c" also needs label c unused. The word is read strictly left
// to right: label by label, dimension by dimension.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "core/error.hpp"
#include "core/map.hpp"
#include "querymodify/query_word.hpp"

namespace dartcheck::querymodify {

/// One match: the query and the input dart of each of its labels
/// (darts[k - 1] for label k).
struct QueryMatch {
  int query = 0;
  std::vector<Dart> darts;
};

/// m_QM of a match (001's mapping from query darts to input darts): the
/// input dart of each dart of query map `q`, whose word was labeled from
/// `start`.
std::vector<Dart> query_to_input(const Map& q, Dart start, const QueryMatch& m);

/// Algorithm 1 for one query word, as 001 writes it (a queue of annotated
/// darts). `blocked` (optional, one flag per dart) are darts annotated ∅
/// beforehand: the greedy strategy's already matched darts.
std::optional<QueryMatch> annotate(const Map& input, const QueryWord& w, Dart start, const std::vector<bool>* blocked = nullptr);

/// A pruning bound for the prefix-tree search: input darts fall into
/// classes (e.g. the mesh vertex a dart starts from), and no match of any
/// query spans more than `most` classes, so a partial match that already
/// spans more is abandoned. Sound for vertices and hex patterns: a
/// query's darts at one vertex are joined by a path inside the query,
/// whose image joins their images, so a match spans at most the query's 8
/// vertices.
struct ClassBound {
  const std::vector<std::uint32_t>* class_of = nullptr;  // per input dart
  std::uint32_t most = 0;
  std::vector<std::uint32_t>* count = nullptr;  // per class, zero between calls (scratch)
};

/// Many query words in a prefix tree: words sharing a prefix are read
/// together, and several queries may share one word (a terminal holds a
/// list). All words must have the same letters (dimensions).
class QueryTrie {
 public:
  /// Adds the word of query `id`. The word must number its labels in
  /// order of first use, as query_word() does (throws
  /// ValueError otherwise): the search then knows that the only
  /// new label allowed at any position is the next one.
  void add(const QueryWord& w, int id);
  std::size_t queries() const { return count_; }
  std::size_t nodes() const { return nodes_.size(); }

  /// Every match of every query from `start` (in the order the tree's
  /// depth-first search finds them). `blocked` as for annotate().
  /// `scratch`, kept by a caller that matches from many darts, is one word
  /// per input dart, all zero between calls: the search undoes what it
  /// writes, so a call costs the size of the search, not of the map.
  std::vector<QueryMatch> match(const Map& input, Dart start, const std::vector<bool>* blocked = nullptr,
                                std::vector<std::uint32_t>* scratch = nullptr, const ClassBound* bound = nullptr) const;

 private:
  struct Node {
    /// (letter, node) sorted by letter: the input allows at most four
    /// letters at a position, found by binary search.
    std::vector<std::pair<std::uint32_t, std::uint32_t>> children;
    std::vector<int> terminal;  // queries whose word ends here
  };
  std::vector<Node> nodes_{Node{}};
  std::vector<Dim> dims_;
  std::size_t count_ = 0;
};

}  // namespace dartcheck::querymodify
