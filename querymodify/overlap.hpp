// Choosing among overlapping matches (001 Sec. 5.2.2).
//
// Two matches conflict when they share a matched dart: a dart annotated
// with a label by both. Darts annotated ∅ (a '↔' neighbour) and darts a
// '*' or 'ε̄' letter only looked at are not matched and do not conflict;
// neither do two matches of the same darts found from different start
// darts by the same query (they are one match: `distinct_matches`).
#pragma once

#include <functional>
#include <vector>

#include "querymodify/annotation.hpp"

namespace dartcheck::querymodify {

/// Greedy (Sec. 5.2.2 (1)): start darts in increasing order; from each dart
/// not yet matched, the first match the tree finds is selected and its
/// darts are blocked (annotated ∅) for the following searches.
/// `accept` (optional) filters the candidates: the first accepted match is
/// taken.
std::vector<QueryMatch> greedy_matches(const Map& input, const QueryTrie& trie, const ClassBound* bound = nullptr,
                                       const std::function<bool(const QueryMatch&)>& accept = {});

/// Every match from every start dart, overlapping ones included, and how
/// many were found before removing those with the same query and darts.
struct AllMatches {
  std::size_t raw = 0;
  std::vector<QueryMatch> distinct;
};
/// The start darts are split between `threads` threads (0: one per core),
/// each with its own scratch; the result does not depend on the split.
AllMatches all_matches(const Map& input, const QueryTrie& trie, const ClassBound* bound = nullptr, unsigned threads = 0);

/// Global (Sec. 5.2.2 (2)): the distinct matches sorted by decreasing
/// score (ties: the order found), each selected unless it conflicts with
/// one selected before.
std::vector<QueryMatch> global_matches(const Map& input, const QueryTrie& trie, const std::function<double(const QueryMatch&)>& score);
/// The same on matches already found (`all` from all_matches on a map of
/// `darts` darts).
std::vector<QueryMatch> global_matches(const AllMatches& all, std::size_t darts, const std::function<double(const QueryMatch&)>& score);
/// The same with the score of each of all.distinct given.
std::vector<QueryMatch> global_matches(const AllMatches& all, std::size_t darts, const std::vector<double>& scores);

/// True if the two matches share a matched dart.
bool conflict(const QueryMatch& a, const QueryMatch& b);

}  // namespace dartcheck::querymodify
