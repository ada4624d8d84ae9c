#include <fmt/format.h>
#include <fstream>

#include "checkers/map_validity.hpp"
#include "cli/commands.hpp"
#include "cli/report_text.hpp"
#include "cli/resolve.hpp"
#include "core/catalog.hpp"
#include "core/derivation.hpp"
#include "core/scheme_application.hpp"
#include "core/input_error.hpp"
#include "core/map_io.hpp"

namespace dartcheck::cli {

int apply(const ApplyOptions& o) {
  const Catalog catalog = read_catalog(o.catalog);
  const CatalogRule* rule = catalog.find_rule(o.rule);
  if (!rule) throw InputError(o.catalog, 0, 0, fmt::format("no rule named '{}'", o.rule));
  Map map = resolve_map(o.map, rule->rule.model(), &catalog);
  if (!(map.model() == rule->rule.model()))
    throw InputError("<command line>", 0, 0,
                     fmt::format("--map {} is a {} but rule '{}' rewrites {}", o.map, map.model().name, o.rule, rule->rule.model().name));
  fmt::print("rule: {} ({})\nhost: {}\n", o.rule, rule->rule.model().name, describe_target(o.map, map));
  if (rule->words.scheme) {
    // A rule scheme: instantiated on the pattern graph of the hook dart.
    auto result = apply_scheme(rule->rule, rule->words, map, o.hooks);
    if (!result.ok()) {
      fmt::print("not applied ({}): {}\n", refusal_name(result.refusal), result.why);
      return violation;
    }
    fmt::print("applied scheme: pattern graph of {} darts, {} darts matched, {} added; result has {} darts\n",
               result.value->pattern_nodes, result.value->matched_darts, result.value->added_darts, map.size());
  } else {
    auto result = apply_rule(rule->rule, map, o.hooks);
    if (!result.ok()) {
      fmt::print("not applied ({}): {}\n", refusal_name(result.refusal), result.why);
      return violation;
    }
    const Derivation& d = *result.value;
    std::string comatch;
    for (NodeId v = 0; v < rule->rule.right().node_count(); ++v)
      comatch += fmt::format("{}{}={}", v ? " " : "", rule->rule.right().name(v), d.comatch[v]);
    fmt::print("applied: result has {} darts; comatch {}\n", map.size(), comatch);
  }
  const auto report = check_map(map);
  print_validity(stdout, map, report, o.limit);
  if (!o.output.empty()) {
    std::ofstream out(o.output);
    if (!out) throw InputError(o.output, 0, 0, "cannot write the result map");
    write_map(out, map);
    fmt::print("written: {}\n", o.output);
  }
  return report.valid() ? ok : violation;
}

}  // namespace dartcheck::cli
