// `dartcheck run`: builds every map of a catalog, applies every rule to its
// worked examples and compares each outcome with the recorded expectation.
#include <fmt/format.h>

#include "checkers/map_validity.hpp"
#include "cli/commands.hpp"
#include "rewriting/application.hpp"
#include "analysis/map_sources.hpp"
#include "io/catalog.hpp"
#include "rewriting/derivation.hpp"
#include "core/isomorphism.hpp"
#include "core/orbit.hpp"
#include "rewriting/scheme_application.hpp"

namespace dartcheck::cli {

using namespace analysis;  // the engines the commands call

int run(const RunOptions& o) {
  const Catalog catalog = read_catalog(o.catalog);
  fmt::print("catalog {}: {} maps, {} rules\n\nmaps\n", o.catalog, catalog.maps.size(), catalog.rules.size());
  std::vector<Map> built;
  for (const auto& s : catalog.maps) {
    built.push_back(build_source(s));
    const auto report = check_map(built.back());
    fmt::print("  {:<24} {:<14} {:>8} darts  {}\n", s.name, s.model.name, built.back().size(),
               report.valid() ? "valid" : fmt::format("INVALID ({} violations)", report.violations.size()));
  }
  int failures = 0, examples = 0;
  fmt::print("\nrules (example: expected -> got)\n");
  for (const auto& r : catalog.rules) {
    fmt::print("  {} ({}): L {} nodes / {} arcs, R {} nodes / {} arcs\n", r.rule.name(), r.rule.model().name, r.rule.left().node_count(),
               r.rule.left().arc_count(), r.rule.right().node_count(), r.rule.right().arc_count());
    for (const auto& e : r.examples) {
      ++examples;
      std::size_t index = 0;
      while (catalog.maps[index].name != e.map) ++index;
      Map host = built[index];
      // A scheme is instantiated at the hook (002 Sec. 6.3), a DPO rule
      // matched from it.
      const auto result = dartcheck::apply(r, host, e.hooks);
      const Refusal refusal = result.refusal;
      const std::string& why = result.why;
      std::string got, detail;
      if (refusal != Refusal::none) {
        got = std::string(refusal_name(refusal));
        detail = why;
      } else {
        const auto report = check_map(host);
        got = report.valid() ? "valid" : "invalid";
        detail = report.valid() ? fmt::format("{} darts", host.size())
                                : fmt::format("{} violations, first: dart {} {}", report.violations.size(), report.violations[0].element,
                                              constraint_name(report.violations[0]));
        if (e.cells && report.valid()) {
          const auto cells = count_cells(host).cells;
          if (cells != *e.cells) {
            got = "wrong cells";
            detail = fmt::format("cells {} expected {}", fmt::join(cells, ","), fmt::join(*e.cells, ","));
          }
        }
        if (!e.isomorphic_to.empty() && got == "valid") {
          std::size_t target = 0;
          while (catalog.maps[target].name != e.isomorphic_to) ++target;
          if (!isomorphic(host, built[target])) {
            got = "not isomorphic";
            detail = fmt::format("H is not isomorphic to map {} ({} darts)", e.isomorphic_to, built[target].size());
          } else {
            detail += fmt::format(", isomorphic to {}", e.isomorphic_to);
          }
        }
      }
      const bool pass = got == e.expect;
      failures += !pass;
      fmt::print("    {} {} at {}: {} -> {}  ({}){}\n", pass ? "ok  " : "FAIL", e.map, fmt::join(e.hooks, ","), e.expect, got, detail,
                 pass ? "" : "  at " + e.location.str());
    }
  }
  fmt::print("\n{} examples, {} passed, {} failed\n", examples, examples - failures, failures);
  return failures ? violation : ok;
}

}  // namespace dartcheck::cli
