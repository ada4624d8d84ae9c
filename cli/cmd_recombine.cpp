// dartcheck recombine: tetrahedra -> hexahedra by query-modify (001 Sec.
// 7.1), the run querymodify/recombined_mesh does, rendered by reports/.
#include <filesystem>

#include <fmt/format.h>

#include "campaign/input_run.hpp"
#include "cli/commands.hpp"
#include "core/input_error.hpp"
#include "core/output_file.hpp"
#include "querymodify/recombined_mesh.hpp"
#include "reports/querymodify_report.hpp"

namespace dartcheck::cli {

int recombine(const RecombineOptions& o) {
  // Before the work, as the output file.
  querymodify::check_contacts(querymodify::parse_strategy(o.strategy), querymodify::parse_search(o.search), o.conforming);
  querymodify::parse_cells(o.cells);
  if (!o.output.empty() && std::filesystem::path(o.output).extension() != ".mesh")
    throw InputError("<command line>", 0, 0, fmt::format("-o: expected a medit .mesh file, got '{}'", o.output));
  if (!o.output.empty()) check_writable(o.output);
  const auto run = querymodify::recombine_mesh(o.mesh, o.strategy, o.min_quality, o.output, o.search, o.conforming, o.cells);
  if (!run.input_valid) {
    fmt::print(stderr, "BUG: the map of {} is not a valid open 3-O-map\n", o.mesh);
    return soundness_bug;
  }
  const int status = run.sound() ? ok : soundness_bug;
  // jsonl: one run of a campaign over many meshes (docs/scale.md), which merge gathers.
  campaign::print_input_run(o.format, o.mesh,
                            {{"strategy", o.strategy}, {"search", run.search}, {"min_quality", o.min_quality}, {"conforming", o.conforming}, {"cells", o.cells}}, run,
                            status);
  if (status != ok)
    fmt::print(stderr, "BUG: the recombined map is {} ({} darts, {} expected)\n", run.valid ? "valid" : "invalid", run.darts, run.expected_darts);
  return status;
}

}  // namespace dartcheck::cli
