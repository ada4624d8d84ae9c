#include "analysis/query_sources.hpp"

#include <chrono>

#include <fmt/format.h>

#include "core/error.hpp"
#include "analysis/map_sources.hpp"
#include "core/input_error.hpp"
#include "querymodify/hex_queries.hpp"
#include "querymodify/tet_input.hpp"

namespace dartcheck::analysis {

using namespace querymodify;

Map load_query_map(const std::string& target, const Model& model, const Catalog* catalog) {
  if (is_tet_mesh_path(target)) return load_tet_input(target).map.map;
  return resolve_map(target, model, catalog);
}

querymodify::BoundaryCondition parse_boundary_condition(const std::string& s) {
  if (s == "any") return querymodify::BoundaryCondition::any;
  if (s == "boundary") return querymodify::BoundaryCondition::boundary;
  if (s == "interior") return querymodify::BoundaryCondition::interior;
  if (s == "no-link") return querymodify::BoundaryCondition::no_connection;
  throw UsageError(fmt::format("--free: expected any, boundary, interior or no-link, got '{}'", s));
}

// The --query maps read as words from --start, then the hex patterns.
std::vector<NamedQuery> named_queries(const std::vector<std::string>& targets, bool hex, Dart start, const Map& input, const Model& model,
                                      const Catalog* cat, querymodify::BoundaryCondition free_links) {
  std::vector<NamedQuery> queries;
  for (const auto& target : targets) {
    const Map q = load_query_map(target, model, cat);
    if (!(q.model() == input.model()))
      throw InputError(
          "<command line>", 0, 0,
          fmt::format("--query {}: a {} query on a {} map (a query's letters are the map's dimensions)", target, q.model().name, input.model().name));
    if (start >= q.size()) throw UsageError(fmt::format("--start {}: the query {} has {} darts", start, target, q.size()));
    try {
      queries.push_back({target, query_word(q, start, free_links)});
    } catch (const ValueError& e) {
      throw InputError(target, 0, 0, e.what());
    }
  }
  if (hex) {
    if (!(input.model() == Model::open_omap(3)))
      throw UsageError(fmt::format("--hex: the hex patterns are tetrahedral 3-maps; the map is a {}", input.model().name));
    const auto& patterns = hex_queries();
    for (std::size_t k = 0; k < patterns.size(); ++k) queries.push_back({fmt::format("hex-{}", k), patterns[k].word});
  }
  return queries;
}

QuerySearch search_queries(const Map& input, const std::vector<NamedQuery>& queries, const std::string& strategy) {
  QuerySearch out;
  for (std::size_t k = 0; k < queries.size(); ++k) out.trie.add(queries[k].word, static_cast<int>(k));
  const auto t0 = std::chrono::steady_clock::now();
  out.all = all_matches(input, out.trie);
  if (strategy == "all")
    out.shown = out.all.distinct;
  else if (strategy == "greedy")
    out.shown = greedy_matches(input, out.trie);
  else
    out.shown = global_matches(out.all, input.size(), [](const QueryMatch& m) { return static_cast<double>(m.darts.size()); });
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace dartcheck::analysis
