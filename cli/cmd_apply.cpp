// dartcheck apply: one rule at hook darts of a map; the run itself is
// reports/apply_output's.
#include <fmt/format.h>

#include "analysis/map_sources.hpp"
#include "cli/commands.hpp"
#include "cli/options.hpp"
#include "core/input_error.hpp"
#include "core/output_file.hpp"
#include "io/catalog.hpp"
#include "io/mesh_writer.hpp"

namespace dartcheck::cli {

int apply(const ApplyOptions& o) {
  // The writers are YAML, Jerboa .jba and polygon meshes: a result under
  // another extension would be a file that its readers reject.
  if (!o.output.empty() && !o.output.ends_with(".jba") && !is_polygon_mesh_output(o.output) && !o.output.ends_with(".yaml") && !o.output.ends_with(".yml"))
    throw UsageError(
        fmt::format("-o: '{}': dartcheck writes result maps as YAML (.yaml, .yml), Jerboa .jba, or meshes (.off, .obj, .vtu, .vtk, .msh)", o.output));
  check_distinct_outputs({{"-o", o.output}, {"--kappa-out", o.kappa_out}});
  for (const auto* out : {&o.output, &o.kappa_out})
    if (!out->empty()) check_writable(*out);  // before the work, not after it
  const Catalog catalog = read_catalog(o.catalog);
  const CatalogRule* rule = &analysis::require_rule(catalog, o.catalog, o.rule);
  Map map = analysis::resolve_map(o.map, rule->rule.model(), &catalog);
  if (!(map.model() == rule->rule.model()))
    throw UsageError(fmt::format("--map {} is a {} but rule '{}' rewrites {}", o.map, map.model().name, o.rule, rule->rule.model().name));
  check_hooks(*rule, o.hooks, map, o.map);
  fmt::print("rule: {} ({})\nhost: {}\n", o.rule, rule->rule.model().name, analysis::describe_target(o.map, map));
  return reports::apply_and_write(o, *rule, std::move(map));
}

}  // namespace dartcheck::cli
