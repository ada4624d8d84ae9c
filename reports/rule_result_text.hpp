// analysis::RuleResult as text: the lines every command prints on stderr
// for a rule that disagrees with its record, and check's verdict table.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "analysis/rule_result.hpp"

namespace dartcheck::reports {

/// One line per mismatch, as compilers and CI annotators read them:
/// "catalog.yaml:12:3: error: rule-name: MISMATCH: the static verdict is ...";
/// a failing rule with nothing recorded (a first run) is not a MISMATCH:
/// "...: error: rule-name: fails A(pos), and the catalog records no verdict
/// for it". `recording` (--write-baseline) leaves out the verdicts it records.
std::vector<std::string> mismatch_lines(const std::vector<analysis::RuleResult>& results, bool recording = false);

/// The rules whose verdict differs from a recorded one (not the first
/// run's findings, which have none).
std::size_t changed_verdicts(const std::vector<analysis::RuleResult>& results);

/// "2 verdicts differ from the baseline; 3 rules fail with no verdict
/// recorded" ("" when every result matches its record).
std::string mismatch_summary(const std::vector<analysis::RuleResult>& results);

/// The hint after a first run's findings: how to record them as a
/// baseline and compare with it ("" when there are none).
std::string first_run_hint(const std::vector<analysis::RuleResult>& results);

struct TableOptions {
  bool explain = false;  // every witness under its rule
  std::string catalog;   // for the Jerboa header line
};

/// check's table: rules x conditions, the verdict, each rule's caveats,
/// its model-level confirmation and, with `explain`, every witness; then
/// the rules not checked and the summary line.
std::string check_table(const Catalog& catalog, const std::vector<analysis::RuleResult>& results, std::size_t baseline_mismatches,
                        const TableOptions& options);

/// A D-graph's arcs, "a -1-> b, b -1-> a" (hosts and results of witnesses).
std::string arcs_text(const TopoGraph& g);

/// A prove run as its renderers see it.
struct ProveRun {
  std::string catalog;
  std::size_t max_darts = 0;
  unsigned rlimit = 0;
  double seconds = 0;
  bool explain = false;  // the theorem-class hosts and their H
  std::vector<std::string> baseline_mismatches;
};

/// prove's text: per rule and constraint, the static verdict, the theorem
/// class's and the model's answers and their agreement, then the totals.
std::string prove_text(const ProveRun& run, const std::vector<analysis::RuleResult>& results);
/// One rule's part of prove's text, and the totals that end it: `prove`
/// prints each rule's part as it finishes (prove_text is their sum).
std::string prove_rule_text(const ProveRun& run, const analysis::RuleResult& result);
std::string prove_totals_text(const ProveRun& run, const std::vector<analysis::RuleResult>& results);

/// A fuzz run as its renderers see it.
struct FuzzRun {
  std::string catalog;
  std::uint64_t seed = 0;
  double seconds = 0;     // by the wall clock, unless `shard_seconds` is all a merge knows
  std::size_t rules = 0;  // selected; the results hold the finished ones
  bool interrupted = false;
  std::vector<std::string> baseline_mismatches;
  /// A merge's shards' summed times (the work done, CPU-like); `seconds`
  /// is then the wall clock of a --jobs run, or this sum for a bare merge.
  std::optional<double> shard_seconds = std::nullopt;
  bool wall_clock = true;  // false: `seconds` is the shards' sum, no wall clock is known
  /// The options besides the seed that decide which host a rule's search
  /// finds (fuzz_search_options), for the hints' commands.
  std::string search_options = {};
};

/// " --runs 200 --max-darts 64 --maps a.off" (shell-quoted): the options
/// of a fuzz run that differ from the defaults and change its hosts, so
/// that a printed command finds the same counterexample.
std::string fuzz_search_options(std::optional<std::size_t> runs, std::size_t max_darts, std::size_t event_checks, const std::vector<std::string>& maps);

/// fuzz's table: each rule's static verdict and fuzz outcome, where its
/// counterexample was found and how to replay it, then the summary line.
std::string fuzz_table(const FuzzRun& run, const std::vector<analysis::RuleResult>& results);

/// The conditions of one kind, as a table cell: "ok", "fails 1,2",
/// "skipped" or "-" (the model has none of that kind).
std::string condition_cell(const RuleVerdict& v, RuleCondition kind);

}  // namespace dartcheck::reports
