// analysis::RuleResult as JSON: one object per rule, the same in `check`,
// `fuzz`, `prove` and `report` (docs/schema/rule-result.schema.json), and
// the documents those commands print around them.
#pragma once

#include <string>
#include <vector>

#include "analysis/rule_result.hpp"
#include "reports/json_fwd.hpp"
#include "reports/rule_result_text.hpp"

namespace dartcheck::reports {

/// How much of a result the JSON holds: what the report shows, or also
/// what the report leaves out or shows as text (maps, D-graphs, solver
/// hosts, every count), so that a campaign's shard record reads back
/// without loss (campaign/detail/result_record.hpp). One writer for both:
/// a field added to the report is in the record.
enum class JsonDetail { report, record };

/// One rule: location, model, static conditions with witnesses, embedding
/// checks, the recorded verdict and how this run compares with it, and
/// each stage that ran (confirmation, fuzz, solver, potential events).
Json rule_result_json(const analysis::RuleResult& r, JsonDetail detail = JsonDetail::report);

/// The rules a catalog names but dartcheck does not check, with why.
Json skipped_json(const std::vector<SkippedRule>& skipped);

/// check's document, also report's results.json: every rule's result, the
/// rules not checked, the baseline's own disagreements and the counts.
Json results_document(std::string_view command, const std::string& catalog_file, const Catalog& catalog,
                      const std::vector<analysis::RuleResult>& results, const std::vector<std::string>& baseline_mismatches);

/// fuzz's summary object (json's "summary", jsonl's last line).
Json fuzz_summary_json(const FuzzRun& run, const std::vector<analysis::RuleResult>& results);

/// prove's document: every rule's result with its proof, and the totals.
Json prove_document(const ProveRun& run, const std::vector<analysis::RuleResult>& results);

/// The counts every document ends with.
Json counts_json(const analysis::ResultCounts& c);

}  // namespace dartcheck::reports
