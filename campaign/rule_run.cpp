#include "campaign/rule_run.hpp"

#include <fmt/format.h>

#include "analysis/interrupt.hpp"
#include "analysis/map_sources.hpp"
#include "analysis/verdict_record.hpp"
#include "core/input_error.hpp"
#include "campaign/detail/shard_stream.hpp"
#include "reports/rule_result_json.hpp"
#include "reports/run_output.hpp"

namespace dartcheck::campaign {

RuleRun::RuleRun(std::string command, const RuleRunOptions& options) : command_(std::move(command)), options_(options) {
  catalog_ = analysis::read_rule_catalog(options.catalog, options.rule);
  shard_ = shard_option(options.shard);
  // The baseline names every rule of the catalog: applied before the shard keeps its part.
  if (!options.baseline.empty()) baseline_mismatches_ = analysis::apply_baseline(catalog_, options.baseline);
  keep_shard(catalog_, shard_);
  analysis::catch_interrupts();  // Ctrl-C stops at the next rule: the finished ones are reported, exit 130
}

std::vector<const CatalogRule*> RuleRun::rules() const {
  std::vector<const CatalogRule*> out;
  for (const auto& e : catalog_.rules)
    if (options_.rule.empty() || e.rule.name() == options_.rule) out.push_back(&e);
  return out;
}

double RuleRun::seconds() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count(); }

void RuleRun::open_lines(const Parameters& parameters) {
  if (options_.jsonl) lines_.emplace(make_header(command_, options_.catalog, options_.baseline, options_.rule, shard_, parameters));
}

void RuleRun::finished(const analysis::RuleResult& r) {
  if (lines_) lines_->rule(r);
}

int RuleRun::finish(const std::vector<analysis::RuleResult>& results, std::size_t selected, const reports::FuzzRun* fuzz, bool recording) {
  const int status = reports::finish_run(results, baseline_mismatches_, selected, analysis::interrupted(), recording);
  if (lines_)
    lines_->summary(fuzz ? reports::fuzz_summary_json(*fuzz, results)
                         : run_summary(results, selected, analysis::interrupted(), seconds(), baseline_mismatches_));
  return status;
}

}  // namespace dartcheck::campaign
