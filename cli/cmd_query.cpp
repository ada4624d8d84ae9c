// dartcheck query: query words (001 Sec. 5) on any map: the queries are
// maps themselves (map files, catalog maps, meshes, tetrahedral meshes,
// and the 322 hex patterns with --hex), read from a start dart with a
// boundary condition on their free links; every match, or a selection
// without overlap (greedy or global).
#include <fmt/format.h>

#include <chrono>
#include <optional>

#include "analysis/query_sources.hpp"
#include "campaign/input_run.hpp"
#include "cli/commands.hpp"
#include "cli/options.hpp"
#include "reports/querymodify_report.hpp"
#include "querymodify/tet_input.hpp"
#include "core/input_error.hpp"
#include "io/catalog.hpp"
#include "querymodify/hex_queries.hpp"
#include "querymodify/overlap.hpp"

namespace dartcheck::cli {

using querymodify::load_tet_input;

using namespace querymodify;

int query(const QueryOptions& o) {
  const querymodify::BoundaryCondition free_links = analysis::parse_boundary_condition(o.free);
  if (o.queries.empty() && !o.hex) throw InputError("<command line>", 0, 0, "no query: give --query (repeatable) or --hex");
  const Model model = command_model(o.model);
  const std::optional<Catalog> catalog = optional_catalog(o.catalog);
  const Catalog* cat = catalog ? &*catalog : nullptr;
  const Map input = analysis::load_query_map(o.map, model, cat);
  const auto queries = analysis::named_queries(o.queries, o.hex, o.start, input, model, cat, free_links);
  const analysis::QuerySearch found = analysis::search_queries(input, queries, o.strategy);
  reports::QueryRun run{o.map,        input.model().name, o.free,           o.strategy, o.queries.empty() ? "" : boundary_symbol(free_links),
                        input.size(), found.trie.nodes(), o.queries.size(), o.hex,      {},
                        {},           &found.all,         &found.shown,     o.limit,    found.seconds};
  for (const auto& q : queries) run.names.push_back(q.name), run.query_darts.push_back(q.word.darts);
  const int status = found.all.distinct.empty() ? violation : ok;
  // jsonl: one run of a campaign over many maps (docs/scale.md), which merge gathers.
  campaign::print_input_run(o.format, o.map,
                            {{"queries", o.queries},
                             {"hex", o.hex},
                             {"model", o.model},
                             {"catalog", o.catalog},
                             {"free", o.free},
                             {"strategy", o.strategy},
                             {"start", o.start},
                             {"limit", o.limit}},
                            run, status);
  return status;
}

}  // namespace dartcheck::cli
