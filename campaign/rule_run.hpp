// The frame of a run over a catalog's rules, which check, fuzz, prove and
// report share: the catalog read (--rule must name one of its rules), a
// baseline's recorded verdicts applied, the shard's rules kept, the JSON
// lines of a shard opened, Ctrl-C caught; and at the end the exit status
// and the summary line. What differs between the commands is the stages
// each rule goes through and the renderer, which they keep.
#pragma once

#include <chrono>
#include <optional>
#include <string>
#include <vector>

#include "analysis/rule_result.hpp"
#include "campaign/run_parameters.hpp"
#include "campaign/shard_writer.hpp"
#include "io/catalog.hpp"
#include "reports/rule_result_text.hpp"

namespace dartcheck::campaign {

/// The options every rule run takes.
struct RuleRunOptions {
  std::string catalog, rule, shard, baseline;
  bool jsonl = false;  // --format jsonl: a shard's lines on stdout
};

class RuleRun {
 public:
  /// Reads the catalog and everything the run needs before its first rule;
  /// InputError for a --rule, --shard or baseline that does not fit.
  RuleRun(std::string command, const RuleRunOptions& options);

  const Catalog& catalog() const { return catalog_; }
  const Shard& shard() const { return shard_; }
  const std::vector<std::string>& baseline_mismatches() const { return baseline_mismatches_; }
  analysis::RecordSource source() const { return options_.baseline.empty() ? analysis::RecordSource::catalog : analysis::RecordSource::baseline; }
  /// The shard's rules that --rule selects, in catalog order.
  std::vector<const CatalogRule*> rules() const;
  /// Seconds since the run started.
  double seconds() const;

  /// With --format jsonl, writes the header: the options that change
  /// results are `parameters` (shards merge only when they agree).
  void open_lines(const Parameters& parameters);
  bool writes_lines() const { return lines_.has_value(); }
  /// A finished rule: its line now, so that a run killed later keeps it.
  void finished(const analysis::RuleResult& r);

  /// The exit status (reports::finish_run) of `results` out of `selected`
  /// rules; with --format jsonl, the summary line (fuzz's when `fuzz` is
  /// given, or the counts of check, prove and report).
  int finish(const std::vector<analysis::RuleResult>& results, std::size_t selected, const reports::FuzzRun* fuzz = nullptr, bool recording = false);

 private:
  std::string command_;
  RuleRunOptions options_;
  Catalog catalog_;
  Shard shard_;
  std::vector<std::string> baseline_mismatches_;
  std::optional<ShardWriter> lines_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

}  // namespace dartcheck::campaign
