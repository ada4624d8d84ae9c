// The outputs of check, fuzz, prove and report, shared by each command and
// by `merge`, which renders the results of a sharded run through the same
// functions: a merged run prints what the unsharded run prints.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "analysis/rule_result.hpp"
#include "io/catalog.hpp"
#include "reports/output_format.hpp"
#include "reports/rule_result_text.hpp"

namespace dartcheck::reports {

using Results = std::vector<analysis::RuleResult>;

/// check's output in `format`: text (the table), json, sarif or junit.
void print_check(OutputFormat format, const std::string& catalog_file, const Catalog& catalog, const Results& results,
                 const std::vector<std::string>& baseline_mismatches, bool explain);

/// SARIF or JUnit of any command's results.
void print_ci_format(OutputFormat format, const std::string& command, const std::string& catalog_file, const Results& results,
                     const std::vector<std::string>& baseline_mismatches);

/// fuzz's output: text or json.
void print_fuzz(OutputFormat format, const FuzzRun& run, const Results& results);

/// prove's output: text or json.
void print_prove(OutputFormat format, const ProveRun& run, const Results& results);

/// What report's page says about the stages that ran.
struct ReportStages {
  std::optional<double> fuzz_seconds;  // --fuzz
  std::uint64_t seed = 0;
  std::size_t prove_darts = 0, scheme_darts = 0;  // --prove (0: none)
  bool baseline = false;                          // verdicts recorded by a baseline, not the catalog
};

/// report's page: DIR/index.html with its SVG pictures and DIR/results.json.
void write_report(const std::string& dir, const std::string& engine, const std::string& catalog_file, const Catalog& catalog, const Results& rows,
                  const std::vector<std::string>& baseline_mismatches, const ReportStages& stages);

/// The end of a run of check, fuzz, prove or report: prints the baseline's
/// disagreements and every mismatch line on stderr, says how many of
/// `selected` rules finished if the run was `interrupted` (a signal, or a
/// merge of unfinished shards), and returns the exit status (3 a soundness
/// bug, 130 interrupted, 1 a mismatch, 0). A first run's findings get a
/// hint (first_run_hint); `recording` (--write-baseline) prints neither
/// them nor the verdicts that differ: the baseline records them.
int finish_run(const std::vector<analysis::RuleResult>& results, const std::vector<std::string>& baseline_mismatches, std::size_t selected,
               bool interrupted, bool recording = false);

}  // namespace dartcheck::reports
