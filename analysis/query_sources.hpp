// The maps `dartcheck query` reads: the map searched and the query maps,
// each read as a query word (001 Sec. 5) from a start dart with a
// boundary condition on its free links, and the 322 hex patterns.
#pragma once

#include <string>
#include <vector>

#include "io/catalog.hpp"
#include "querymodify/overlap.hpp"
#include "querymodify/query_word.hpp"

namespace dartcheck::analysis {

/// A map as resolve_map names it, or a tetrahedral mesh (.node, .ele,
/// .mesh) as an open 3-O-map.
Map load_query_map(const std::string& target, const Model& model, const Catalog* catalog);

/// --free: any, boundary, interior or no-link; InputError otherwise.
querymodify::BoundaryCondition parse_boundary_condition(const std::string& text);

struct NamedQuery {
  std::string name;  // the target, or hex-K
  querymodify::QueryWord word;
};

/// The query maps `targets` read as words from `start` (each a map of
/// `input`'s model with that dart), then with `hex` the hex patterns
/// (on an open 3-O-map only). InputError naming the query otherwise.
std::vector<NamedQuery> named_queries(const std::vector<std::string>& targets, bool hex, Dart start, const Map& input, const Model& model,
                                      const Catalog* catalog, querymodify::BoundaryCondition free_links);

/// The queries' prefix tree, every distinct match on `input`, and those
/// `strategy` shows: all, or a selection without overlap, greedy or
/// global (largest first); with the search's seconds.
struct QuerySearch {
  querymodify::QueryTrie trie;
  querymodify::AllMatches all;
  std::vector<querymodify::QueryMatch> shown;
  double seconds = 0;
};
QuerySearch search_queries(const Map& input, const std::vector<NamedQuery>& queries, const std::string& strategy);

}  // namespace dartcheck::analysis
