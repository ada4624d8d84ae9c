// `dartcheck check`: the static stage of every rule (analysis::RuleResult),
// compared with the verdicts the catalog or a baseline records, rendered
// as a table, JSON, SARIF or JUnit (reports/).
#include <algorithm>
#include <chrono>
#include <sstream>

#include <fmt/format.h>

#include "analysis/interrupt.hpp"
#include "analysis/map_sources.hpp"
#include "analysis/rule_result.hpp"
#include "analysis/verdict_record.hpp"
#include "cli/commands.hpp"
#include "core/terminal.hpp"
#include "campaign/jobs.hpp"
#include "campaign/rule_run.hpp"
#include "cli/options.hpp"
#include "reports/run_output.hpp"
#include "core/input_error.hpp"
#include "core/output_file.hpp"
#include "io/baseline.hpp"
#include "io/catalog.hpp"

namespace dartcheck::cli {

using reports::print_check;

using namespace analysis;

namespace {

void write_baseline_file(const std::string& path, const std::string& catalog_file, const Catalog& catalog, const std::vector<RuleResult>& results) {
  std::vector<BaselineEntry> entries;
  for (const auto& r : results) {
    entries.push_back({r.name(), r.failures, {}, std::nullopt, {}});
    if (r.proof && r.proof->embedding) entries.back().solver = r.solver_classes();
  }
  for (const auto& s : catalog.skipped) entries.push_back({s.name, std::nullopt, {}, std::nullopt, {}});
  std::ostringstream text;
  write_baseline(text, catalog_file, entries);
  write_file(path, text.str());
  if (!terminal().quiet) fmt::print(stderr, "wrote {} ({} verdicts, {} not checked)\n", path, results.size(), catalog.skipped.size());
}

}  // namespace

int check(const CheckOptions& o) {
  if (o.jobs > 1) {
    if (o.format == "jsonl" || !o.write_baseline.empty())
      throw UsageError("--jobs: not with --format jsonl or --write-baseline (run the shards, then merge)");
    return campaign::run_jobs({o.jobs, o.shard, {.format = reports::output_format(o.format), .explain = o.explain}, std::nullopt, std::nullopt});
  }
  const std::string not_written = fmt::format("not written: {} (interrupted: a baseline records every rule)", o.write_baseline);
  if (!o.write_baseline.empty()) say_on_early_interrupt(not_written);  // Ctrl-C while the catalog is read
  campaign::RuleRun run("check", {o.catalog, o.rule, o.shard, o.baseline, o.format == "jsonl"});
  if (!o.write_baseline.empty()) check_writable(o.write_baseline);  // before the work, not after it
  if (!o.write_baseline.empty() && !run.shard().whole()) throw UsageError("--write-baseline: a baseline records every rule, not a shard's");
  run.open_lines({{"confirm_darts", o.confirm_darts}, {"solver", o.solver}});
  const Catalog& catalog = run.catalog();
  const std::vector<Map> maps = confirmation_maps(catalog, o.confirm_darts);
  std::vector<RuleResult> results;
  const auto rules = run.rules();
  for (const CatalogRule* entry : rules) {
    if (interrupted()) break;
    results.push_back(analyse_static(catalog, *entry, o.confirm_darts, maps, run.source()));
    if (o.solver) run_embedding_solver(results.back(), [] { return interrupted(); });
    run.finished(results.back());
  }
  const int status = run.finish(results, rules.size(), nullptr, !o.write_baseline.empty());
  if (!o.write_baseline.empty() && interrupted())
    fmt::print(stderr, "{}\n", not_written);
  else if (!o.write_baseline.empty())
    write_baseline_file(o.write_baseline, o.catalog, catalog, results);
  if (!run.writes_lines()) print_check(reports::output_format(o.format), o.catalog, catalog, results, run.baseline_mismatches(), o.explain);
  // Writing a baseline records the present verdicts: not a failure.
  return o.write_baseline.empty() || interrupted() ? status : ok;
}

}  // namespace dartcheck::cli
