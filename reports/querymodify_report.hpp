// The renderers of `dartcheck recombine` and `dartcheck query` (001): a
// few lines per phase as text, or a JSON document (docs/schema/recombine,
// docs/schema/query).
#pragma once

#include <string>
#include <vector>

#include "querymodify/overlap.hpp"
#include "querymodify/recombined_mesh.hpp"
#include "reports/json_fwd.hpp"

namespace dartcheck::reports {

using querymodify::RecombineRun;

std::string recombine_text(const RecombineRun& run);
Json recombine_document(const RecombineRun& run);

/// One query run: the queries (named), every distinct match, the ones
/// shown (all, or a selection without overlap), at most `limit` listed.
struct QueryRun {
  std::string map, model, free, strategy;
  std::string free_symbol;                                   // the --query maps' boundary condition, or empty with --hex alone
  std::size_t darts = 0, trie_nodes = 0, named_queries = 0;  // the --query maps come first
  bool hex = false;
  std::vector<std::string> names;
  std::vector<std::size_t> query_darts;
  const querymodify::AllMatches* all = nullptr;
  const std::vector<querymodify::QueryMatch>* shown = nullptr;
  std::size_t limit = 0;
  double seconds = 0;
};

std::string query_text(const QueryRun& run);
Json query_document(const QueryRun& run);

}  // namespace dartcheck::reports
