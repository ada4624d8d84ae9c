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
#include "querymodify/selection_cells.hpp"
#include "io/volume_mesh_writer.hpp"
#include "core/output_file.hpp"
#include "core/terminal.hpp"

namespace dartcheck::cli {

using querymodify::load_tet_input;

using namespace querymodify;

int query(const QueryOptions& o) {
  const querymodify::BoundaryCondition free_links = analysis::parse_boundary_condition(o.free);
  if (o.queries.empty() && !o.hex) throw UsageError("no query: give --query (repeatable) or --hex");
  const Model model = command_model(o.model);
  const std::optional<Catalog> catalog = optional_catalog(o.catalog);
  const Catalog* cat = catalog ? &*catalog : nullptr;
  // -o: the selection as cell data of the tetrahedral mesh searched,
  // checked before the work.
  std::optional<TetInput> tets;
  if (!o.output.empty()) {
    if (!is_volume_mesh_output(o.output) || o.output.ends_with(".mesh"))
      throw UsageError(fmt::format("-o: expected a .vtu, .vtk or .msh file (medit .mesh carries no cell data), got '{}'", o.output));
    if (!is_tet_mesh_path(o.map))
      throw UsageError(
          fmt::format("-o: the selection is written as cell data of a tetrahedral mesh (.node, .ele, .mesh, .msh); '{}' is not one", o.map));
    check_writable(o.output);
    tets = load_tet_input(o.map);
  }
  const Map input = tets ? tets->map.map : analysis::load_query_map(o.map, model, cat);
  const auto queries = analysis::named_queries(o.queries, o.hex, o.start, input, model, cat, free_links);
  const analysis::QuerySearch found = analysis::search_queries(input, queries, o.strategy);
  reports::QueryRun run{o.map,        input.model().name, o.free,           o.strategy, o.queries.empty() ? "" : boundary_symbol(free_links),
                        input.size(), found.trie.nodes(), o.queries.size(), o.hex,      {},
                        {},           &found.all,         &found.shown,     o.limit,    found.seconds};
  for (const auto& q : queries) run.names.push_back(q.name), run.query_darts.push_back(q.word.darts);
  const int status = found.all.distinct.empty() ? violation : ok;
  // jsonl: one run of a campaign over many maps (docs/scale.md), which merge gathers.
  campaign::print_input_run(reports::output_format(o.format), o.map,
                            {{"queries", o.queries},
                             {"hex", o.hex},
                             {"model", o.model},
                             {"catalog", o.catalog},
                             {"free", o.free},
                             {"strategy", o.strategy},
                             {"start", o.start},
                             {"limit", o.limit}},
                            run, status);
  if (tets) {
    // The tetrahedra as the map has them (oriented, in the file's order),
    // without the file's other cells: one value per tetrahedron.
    TetMesh mesh;
    mesh.points = tets->mesh.points;
    mesh.tets = tets->map.tets;
    write_file(o.output, volume_mesh_text(mesh, o.output, selection_fields(mesh.tets.size(), found.shown)));
    if (!terminal().quiet && o.format == "text")
      fmt::print("written: {} ({} tetrahedra; cell data match, query, matches)\n", o.output, mesh.tets.size());
  }
  return status;
}

}  // namespace dartcheck::cli
