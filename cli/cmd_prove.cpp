// `dartcheck prove`: the solver's answer for every rule and constraint, set
// against the static verdict (proofs/rule_prover.hpp). Counterexamples on
// maps of the model are also replayed by the dynamic checker (apply_rule
// plus check_map), the third opinion, and written as the same files that
// `dartcheck fuzz` writes.
#include <chrono>

#include <fmt/format.h>

#include "cli/commands.hpp"
#include "analysis/interrupt.hpp"
#include "analysis/verdict_record.hpp"
#include "campaign/shard_stream.hpp"
#include "cli/jobs.hpp"
#include "cli/options.hpp"
#include "reports/run_output.hpp"
#include "analysis/rule_result.hpp"
#include "reports/rule_result_json.hpp"
#include "reports/rule_result_text.hpp"
#include "core/input_error.hpp"
#include "core/output_file.hpp"
#include "proofs/rule_prover.hpp"

namespace dartcheck::cli {

using reports::finish_run;

using reports::print_prove;

using namespace analysis;  // the engines the commands call

int prove(const ProveCommand& c) {
  if (c.jobs > 1) {
    if (c.format == "jsonl") throw InputError("<command line>", 0, 0, "--jobs: not with --format jsonl (run the shards, then merge)");
    return run_jobs({c.jobs, c.shard, {.format = c.format, .explain = c.explain}, std::nullopt});
  }
  Catalog catalog = read_command_catalog(c.catalog, c.rule, c.format == "json" ? "json" : "text");
  const campaign::Shard shard = command_shard(c.shard);
  const auto baseline_mismatches = c.baseline.empty() ? std::vector<std::string>{} : apply_baseline(catalog, c.baseline);
  campaign::keep_shard(catalog, shard);
  const RecordSource source = c.baseline.empty() ? RecordSource::catalog : RecordSource::baseline;
  if (!c.out.empty()) ensure_directory(c.out);  // before the work, not after it
  catch_interrupts();
  if (c.max_darts < 1 || c.max_darts > 256) throw InputError("<command line>", 0, 0, "--max-darts: expected 1 to 256");
  if (c.scheme_darts < 1 || c.scheme_darts > 256) throw InputError("<command line>", 0, 0, "--scheme-darts: expected 1 to 256");
  proofs::ProveOptions o;
  o.max_darts = c.max_darts;
  o.scheme_darts = c.scheme_darts;
  o.rlimit = c.rlimit;
  o.timeout_ms = static_cast<unsigned>(c.timeout * 1000);
  o.stop = [] { return interrupted(); };  // Ctrl-C interrupts the running Z3 query too

  std::optional<campaign::ShardWriter> lines;
  if (c.format == "jsonl")
    lines.emplace(campaign::make_header(
        "prove", c.catalog, c.baseline, c.rule, shard,
        reports::Json{{"max_darts", o.max_darts}, {"scheme_darts", o.scheme_darts}, {"rlimit", o.rlimit}, {"timeout", c.timeout}}));
  const auto start = std::chrono::steady_clock::now();
  std::vector<RuleResult> results;
  std::size_t selected = 0;
  for (const auto& e : catalog.rules) {
    if (!c.rule.empty() && e.rule.name() != c.rule) continue;
    ++selected;
    if (interrupted()) continue;  // a rule's queries finish; the next ones do not start
    results.push_back(analyse_static(catalog, e, 0, {}, source));
    run_proof(results.back(), o, c.out, c.catalog);
    if (lines) lines->rule(results.back());
  }
  if (!results.empty() && results.back().proof && results.back().proof->interrupted)
    fmt::print(stderr, "interrupted during the solver queries of {}: the queries it did not finish say 'interrupted'\n",
               results.back().entry->rule.name());
  const double total = seconds_since(start);
  const int status = finish_run(results, baseline_mismatches, selected);
  const reports::ProveRun run{c.catalog, o.max_darts, o.rlimit, total, c.explain, baseline_mismatches};
  if (lines)
    lines->summary(campaign::run_summary(results, selected, interrupted(), total, baseline_mismatches));
  else
    print_prove(c.format, run, results);
  return status;
}

}  // namespace dartcheck::cli
