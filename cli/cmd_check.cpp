// `dartcheck check`: the static stage of every rule (analysis::RuleResult),
// compared with the verdicts the catalog or a baseline records, rendered
// as a table, JSON, SARIF or JUnit (reports/).
#include <algorithm>
#include <sstream>

#include <fmt/format.h>

#include "analysis/interrupt.hpp"
#include "analysis/map_sources.hpp"
#include "analysis/rule_result.hpp"
#include "analysis/verdict_record.hpp"
#include "cli/commands.hpp"
#include "cli/options.hpp"
#include "core/input_error.hpp"
#include "core/output_file.hpp"
#include "io/baseline.hpp"
#include "io/catalog.hpp"
#include "reports/ci_formats.hpp"
#include "reports/rule_result_json.hpp"
#include "reports/rule_result_text.hpp"

namespace dartcheck::cli {

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
  // SARIF and JUnit are read like text (errors on stderr as usual).
  const bool ci_format = o.format == "sarif" || o.format == "junit";
  Catalog catalog = read_command_catalog(o.catalog, o.rule, ci_format ? "text" : o.format);
  if (!o.write_baseline.empty()) check_writable(o.write_baseline);  // before the work, not after it
  const auto baseline_mismatches = o.baseline.empty() ? std::vector<std::string>{} : apply_baseline(catalog, o.baseline);
  const RecordSource source = o.baseline.empty() ? RecordSource::catalog : RecordSource::baseline;
  const bool schemes = std::any_of(catalog.rules.begin(), catalog.rules.end(), [](const CatalogRule& e) { return e.words.scheme; });
  const std::vector<Map> maps = o.confirm_darts > 0 && schemes ? catalog_maps(catalog) : std::vector<Map>{};

  // Ctrl-C stops at the next rule: the finished ones are reported, exit 130.
  catch_interrupts();
  std::vector<RuleResult> results;
  std::size_t selected = 0;
  for (const auto& entry : catalog.rules) {
    if (!o.rule.empty() && entry.rule.name() != o.rule) continue;
    ++selected;
    if (!interrupted()) results.push_back(analyse_static(catalog, entry, o.confirm_darts, maps, source));
  }

  const int status = finish_run(results, baseline_mismatches, selected);
  if (!o.write_baseline.empty() && interrupted())
    fmt::print(stderr, "not written: {} (interrupted: a baseline records every rule)\n", o.write_baseline);
  else if (!o.write_baseline.empty())
    write_baseline_file(o.write_baseline, o.catalog, catalog, results);
  if (o.format == "sarif") {
    fmt::print("{}\n", reports::sarif_document(o.catalog, results, DARTCHECK_VERSION));
  } else if (o.format == "junit") {
    fmt::print("{}", reports::junit_document("check", o.catalog, results, baseline_mismatches));
  } else if (o.format == "json") {
    const auto doc = reports::results_document("check", o.catalog, catalog, results, baseline_mismatches);
    fmt::print("{}\n", reports::json_text(doc));
  } else {
    fmt::print("{}", reports::check_table(catalog, results, baseline_mismatches.size(), {o.explain, o.catalog}));
  }
  // Writing a baseline records the present verdicts: not a failure.
  return o.write_baseline.empty() || interrupted() ? status : ok;
}

}  // namespace dartcheck::cli
