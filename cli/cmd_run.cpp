// `dartcheck run`: builds every map of a catalog, applies every rule to its
// worked examples and compares each outcome with the recorded expectation.
#include <algorithm>
#include <cstdio>

#include <fmt/format.h>

#include "core/input_error.hpp"
#include "core/terminal.hpp"
#include "core/wording.hpp"
#include "checkers/map_validity.hpp"
#include "analysis/interrupt.hpp"
#include "cli/commands.hpp"
#include "analysis/catalog_examples.hpp"
#include "analysis/map_sources.hpp"
#include "io/catalog.hpp"

namespace dartcheck::cli {

using namespace analysis;  // the engines the commands call

int run(const RunOptions& o) {
  const Catalog catalog = read_catalog(o.catalog);
  // -q: only the failing examples, one diagnostic line each on stderr.
  const bool quiet = terminal().quiet;
  const auto say = [quiet](const std::string& text) {
    if (!quiet) fmt::print("{}", text);
  };
  say(fmt::format("catalog {}: {}, {}\n\nmaps\n", o.catalog, counted(catalog.maps.size(), "map"), counted(catalog.rules.size(), "rule")));
  std::vector<Map> built;
  std::size_t name = 4, model = 5;  // columns as wide as their cells
  for (const auto& s : catalog.maps) name = std::max(name, columns(s.name)), model = std::max(model, columns(s.model.name));
  for (const auto& s : catalog.maps) {
    built.push_back(build_source(s));
    const auto report = check_map(built.back());
    say(fmt::format("  {:<{}} {:<{}} {:>8} darts  {}\n", s.name, name, s.model.name, model, built.back().size(),
                    report.valid() ? "valid" : fmt::format("INVALID ({} violations)", report.violations.size())));
  }
  int failures = 0, examples = 0;
  say("\nrules (example: expected -> got)\n");
  std::fflush(stdout);
  analysis::catch_interrupts();  // Ctrl-C: the examples run so far, their summary, exit 130
  for (const auto& r : catalog.rules) {
    if (analysis::interrupted()) break;
    say(hanging("  ",
                fmt::format("{} ({}): L {} / {}, R {} / {}", r.rule.name(), r.rule.model().name, counted(r.rule.left().node_count(), "node"),
                            counted(r.rule.left().arc_count(), "arc"), counted(r.rule.right().node_count(), "node"),
                            counted(r.rule.right().arc_count(), "arc")),
                2));
    for (const auto& e : r.examples) {
      if (analysis::interrupted()) break;  // a rule may have many examples on large maps
      ++examples;
      const ExampleOutcome got = run_example(catalog, built, r, e);
      const bool pass = got.got == e.expect;
      failures += !pass;
      // The detail goes under the row when the row would pass the width.
      const std::string row = fmt::format("    {} {} at {}: {} -> {}", pass ? "ok  " : "FAIL", e.map, fmt::join(e.hooks, ","), e.expect, got.got);
      const std::string detail = fmt::format("({}){}", got.detail, pass ? "" : "  at " + e.location.str());
      say(columns(row) + 2 + columns(detail) <= terminal().width ? row + "  " + detail + "\n" : row + "\n" + hanging("", detail, 9));
      if (quiet && !pass)
        fmt::print(stderr, "{}: error: {}: example on {} at {}: expected {}, got {} ({})\n", e.location.str(), printable(r.rule.name()), e.map,
                   fmt::join(e.hooks, ","), e.expect, got.got, got.detail);
      std::fflush(stdout);  // a run ended by a signal inside the next example keeps this row
    }
  }
  say(fmt::format("\n{}, {} passed, {} failed\n", counted(static_cast<std::size_t>(examples), "example"), examples - failures, failures));
  if (analysis::interrupted()) {
    fmt::print(stderr, "interrupted: the examples above are those that ran\n");
    return analysis::interrupted_exit;
  }
  return failures ? violation : ok;
}

}  // namespace dartcheck::cli
