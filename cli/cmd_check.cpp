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
#include "campaign/shard_stream.hpp"
#include "cli/jobs.hpp"
#include "cli/options.hpp"
#include "reports/run_output.hpp"
#include "core/input_error.hpp"
#include "core/output_file.hpp"
#include "io/baseline.hpp"
#include "io/catalog.hpp"

namespace dartcheck::cli {

using reports::finish_run;

using reports::print_check;

using namespace analysis;

namespace {

// The catalog's maps of the rules' models: a scheme's confirmation runs on them.
std::vector<Map> catalog_maps(const Catalog& catalog) {
  std::vector<Map> maps;
  for (const auto& source : catalog.maps) maps.push_back(build_source(source));
  return maps;
}

void write_baseline_file(const std::string& path, const std::string& catalog_file, const Catalog& catalog, const std::vector<RuleResult>& results) {
  std::vector<BaselineEntry> entries;
  for (const auto& r : results) entries.push_back({r.name(), r.failures, {}});
  for (const auto& s : catalog.skipped) entries.push_back({s.name, std::nullopt, {}});
  std::ostringstream text;
  write_baseline(text, catalog_file, entries);
  write_file(path, text.str());
  fmt::print(stderr, "wrote {} ({} verdicts, {} not checked)\n", path, results.size(), catalog.skipped.size());
}

}  // namespace

int check(const CheckOptions& o) {
  if (o.jobs > 1) {
    if (o.format == "jsonl" || !o.write_baseline.empty())
      throw InputError("<command line>", 0, 0, "--jobs: not with --format jsonl or --write-baseline (run the shards, then merge)");
    return run_jobs({o.jobs, o.shard, {.format = o.format, .explain = o.explain}, std::nullopt});
  }
  // SARIF, JUnit and JSON lines are read like text (errors on stderr as usual).
  const bool json = o.format == "json";
  Catalog catalog = read_command_catalog(o.catalog, o.rule, json ? "json" : "text");
  const campaign::Shard shard = command_shard(o.shard);
  if (!o.write_baseline.empty()) check_writable(o.write_baseline);  // before the work, not after it
  if (!o.write_baseline.empty() && !shard.whole())
    throw InputError("<command line>", 0, 0, "--write-baseline: a baseline records every rule, not a shard's");
  const auto baseline_mismatches = o.baseline.empty() ? std::vector<std::string>{} : apply_baseline(catalog, o.baseline);
  campaign::keep_shard(catalog, shard);
  std::optional<campaign::ShardWriter> lines;
  if (o.format == "jsonl")
    lines.emplace(campaign::make_header("check", o.catalog, o.baseline, o.rule, shard, reports::Json{{"confirm_darts", o.confirm_darts}}));
  const RecordSource source = o.baseline.empty() ? RecordSource::catalog : RecordSource::baseline;
  const bool schemes = std::any_of(catalog.rules.begin(), catalog.rules.end(), [](const CatalogRule& e) { return e.words.scheme; });
  const std::vector<Map> maps = o.confirm_darts > 0 && schemes ? catalog_maps(catalog) : std::vector<Map>{};

  // Ctrl-C stops at the next rule: the finished ones are reported, exit 130.
  catch_interrupts();
  const auto start = std::chrono::steady_clock::now();
  std::vector<RuleResult> results;
  std::size_t selected = 0;
  for (const auto& entry : catalog.rules) {
    if (!o.rule.empty() && entry.rule.name() != o.rule) continue;
    ++selected;
    if (interrupted()) continue;
    results.push_back(analyse_static(catalog, entry, o.confirm_darts, maps, source));
    if (lines) lines->rule(results.back());
  }

  const int status = finish_run(results, baseline_mismatches, selected);
  if (!o.write_baseline.empty() && interrupted())
    fmt::print(stderr, "not written: {} (interrupted: a baseline records every rule)\n", o.write_baseline);
  else if (!o.write_baseline.empty())
    write_baseline_file(o.write_baseline, o.catalog, catalog, results);
  if (lines)
    lines->summary(campaign::run_summary(results, selected, interrupted(), seconds_since(start), baseline_mismatches));
  else
    print_check(o.format, o.catalog, catalog, results, baseline_mismatches, o.explain);
  // Writing a baseline records the present verdicts: not a failure.
  return o.write_baseline.empty() || interrupted() ? status : ok;
}

}  // namespace dartcheck::cli
