// dartcheck query: query words (001 Sec. 5) on any map: the queries are
// maps themselves (map files, catalog maps, meshes, tetrahedral meshes,
// and the 322 hex patterns with --hex), read from a start dart with a
// boundary condition on their free links; every match, or a selection
// without overlap (greedy or global).
#include <fmt/format.h>

#include <chrono>
#include <optional>

#include "analysis/map_sources.hpp"
#include "campaign/shard_stream.hpp"
#include "cli/commands.hpp"
#include "reports/querymodify_report.hpp"
#include "querymodify/tet_input.hpp"
#include "core/input_error.hpp"
#include "io/catalog.hpp"
#include "querymodify/hex_queries.hpp"
#include "querymodify/overlap.hpp"

namespace dartcheck::cli {

using querymodify::load_tet_input;

using namespace querymodify;

namespace {

InputError command_line(const std::string& what) { return InputError("<command line>", 0, 0, what); }

Map load(const std::string& target, const Model& model, const Catalog* catalog) {
  if (is_tet_mesh_path(target)) return load_tet_input(target).map.map;
  return analysis::resolve_map(target, model, catalog);
}

querymodify::BoundaryCondition parse_free(const std::string& s) {
  if (s == "any") return querymodify::BoundaryCondition::any;
  if (s == "boundary") return querymodify::BoundaryCondition::boundary;
  if (s == "interior") return querymodify::BoundaryCondition::interior;
  if (s == "no-link") return querymodify::BoundaryCondition::no_connection;
  throw command_line(fmt::format("--free: expected any, boundary, interior or no-link, got '{}'", s));
}

struct NamedQuery {
  std::string name;
  QueryWord word;
};

// The --query maps read as words from --start, then the hex patterns.
std::vector<NamedQuery> named_queries(const QueryOptions& o, const Map& input, const Model& model, const Catalog* cat,
                                      querymodify::BoundaryCondition free_links) {
  std::vector<NamedQuery> queries;
  for (const auto& target : o.queries) {
    const Map q = load(target, model, cat);
    if (!(q.model() == input.model()))
      throw command_line(
          fmt::format("--query {}: a {} query on a {} map (a query's letters are the map's dimensions)", target, q.model().name, input.model().name));
    if (o.start >= q.size()) throw command_line(fmt::format("--start {}: the query {} has {} darts", o.start, target, q.size()));
    try {
      queries.push_back({target, query_word(q, o.start, free_links)});
    } catch (const std::invalid_argument& e) {
      throw InputError(target, 0, 0, e.what());
    }
  }
  if (o.hex) {
    if (!(input.model() == Model::open_omap(3)))
      throw command_line(fmt::format("--hex: the hex patterns are tetrahedral 3-maps; the map is a {}", input.model().name));
    const auto& hex = hex_queries();
    for (std::size_t k = 0; k < hex.size(); ++k) queries.push_back({fmt::format("hex-{}", k), hex[k].word});
  }
  return queries;
}

}  // namespace

int query(const QueryOptions& o) {
  if (o.format != "text" && o.format != "json" && o.format != "jsonl")
    throw command_line(fmt::format("--format: expected text, json or jsonl, got '{}'", o.format));
  if (o.strategy != "all" && o.strategy != "greedy" && o.strategy != "global")
    throw command_line(fmt::format("--strategy: expected all, greedy or global, got '{}'", o.strategy));
  const querymodify::BoundaryCondition free_links = parse_free(o.free);
  if (o.queries.empty() && !o.hex) throw command_line("no query: give --query (repeatable) or --hex");
  const auto model = Model::by_name(o.model);
  if (!model) throw command_line(fmt::format("--model: unknown model '{}' (expected {})", o.model, Model::known_names()));
  std::optional<Catalog> catalog;
  if (!o.catalog.empty()) catalog = read_catalog(o.catalog);
  const Catalog* cat = catalog ? &*catalog : nullptr;
  const Map input = load(o.map, *model, cat);
  const std::vector<NamedQuery> queries = named_queries(o, input, *model, cat, free_links);
  QueryTrie trie;
  for (std::size_t k = 0; k < queries.size(); ++k) trie.add(queries[k].word, static_cast<int>(k));
  const auto t0 = std::chrono::steady_clock::now();
  const AllMatches all = all_matches(input, trie);
  std::vector<QueryMatch> shown;
  if (o.strategy == "all")
    shown = all.distinct;
  else if (o.strategy == "greedy")
    shown = greedy_matches(input, trie);
  else
    shown = global_matches(all, input.size(), [](const QueryMatch& m) { return static_cast<double>(m.darts.size()); });
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  reports::QueryRun run{o.map,
                        input.model().name,
                        o.free,
                        o.strategy,
                        o.queries.empty() ? "" : boundary_symbol(free_links),
                        input.size(),
                        trie.nodes(),
                        o.queries.size(),
                        o.hex,
                        {},
                        {},
                        &all,
                        &shown,
                        o.limit,
                        seconds};
  for (const auto& q : queries) run.names.push_back(q.name), run.query_darts.push_back(q.word.darts);
  const int status = all.distinct.empty() ? violation : ok;
  if (o.format == "jsonl") {
    // One run of a campaign over many maps (docs/scale.md): merge gathers them.
    campaign::ShardWriter lines(campaign::make_header("query", o.map, "", "", {},
                                                      reports::Json{{"queries", o.queries},
                                                                    {"hex", o.hex},
                                                                    {"model", o.model},
                                                                    {"catalog", o.catalog},
                                                                    {"free", o.free},
                                                                    {"strategy", o.strategy},
                                                                    {"start", o.start},
                                                                    {"limit", o.limit}}));
    lines.input(reports::query_document(run), reports::query_text(run));
    lines.summary(reports::Json{{"status", status}});
  } else if (o.format == "json") {
    fmt::print("{}\n", reports::json_text(reports::query_document(run)));
  } else {
    fmt::print("{}", reports::query_text(run));
  }
  return status;
}

}  // namespace dartcheck::cli
