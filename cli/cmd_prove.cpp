// `dartcheck prove`: the solver's answer for every rule and constraint, set
// against the static verdict (proofs/rule_prover.hpp). Counterexamples on
// maps of the model are also replayed by the dynamic checker (apply_rule
// plus check_map), the third opinion, and written as the same files that
// `dartcheck fuzz` writes.
#include <chrono>
#include <cstdio>

#include <unistd.h>

#include <fmt/format.h>

#include "cli/commands.hpp"
#include "analysis/interrupt.hpp"
#include "analysis/stage_progress.hpp"
#include "analysis/verdict_record.hpp"
#include "campaign/jobs.hpp"
#include "campaign/rule_run.hpp"
#include "cli/options.hpp"
#include "reports/run_output.hpp"
#include "analysis/rule_result.hpp"
#include "reports/rule_result_text.hpp"
#include "core/terminal.hpp"
#include "core/input_error.hpp"
#include "core/output_file.hpp"
#include "proofs/rule_prover.hpp"

namespace dartcheck::cli {

using reports::print_prove;

using namespace analysis;  // the engines the commands call

int prove(const ProveCommand& c) {
  if (c.jobs > 1) {
    if (c.format == "jsonl") throw UsageError("--jobs: not with --format jsonl (run the shards, then merge)");
    return campaign::run_jobs({c.jobs, c.shard, {.format = reports::output_format(c.format), .explain = c.explain}, std::nullopt, std::nullopt});
  }
  campaign::RuleRun run("prove", {c.catalog, c.rule, c.shard, c.baseline, c.format == "jsonl"});
  if (!c.out.empty()) ensure_directory(c.out);  // before the work, not after it
  if (c.max_darts < 1 || c.max_darts > 256) throw UsageError("--max-darts: expected 1 to 256");
  if (c.scheme_darts < 1 || c.scheme_darts > 256) throw UsageError("--scheme-darts: expected 1 to 256");
  proofs::ProveOptions o;
  o.max_darts = c.max_darts;
  o.scheme_darts = c.scheme_darts;
  o.rlimit = c.rlimit;
  o.embedding_darts = c.embedding_darts;
  o.timeout_ms = static_cast<unsigned>(c.timeout * 1000);
  o.stop = [] { return interrupted(); };  // Ctrl-C interrupts the running Z3 query too
  run.open_lines({{"max_darts", o.max_darts}, {"scheme_darts", o.scheme_darts}, {"embedding_darts", o.embedding_darts}, {"rlimit", o.rlimit}, {"timeout", c.timeout}});
  std::vector<RuleResult> results;
  const auto rules = run.rules();
  StageProgress progress(rules.size(), isatty(fileno(stderr)) != 0 && !terminal().quiet);
  // The text streams: each rule's part as it finishes, the totals at the end.
  const bool stream = c.format == "text" && !run.writes_lines() && !terminal().quiet;
  const reports::ProveRun layout{c.catalog, o.max_darts, o.rlimit, 0, c.explain, {}};
  for (std::size_t k = 0; k < rules.size() && !interrupted(); ++k) {  // a rule's queries finish; the next ones do not start
    progress.start(
        k, fmt::format("{}: asking Z3 for a host up to {} darts", rules[k]->rule.name(), rules[k]->is_scheme() ? o.scheme_darts : o.max_darts));
    results.push_back(analyse_static(run.catalog(), *rules[k], 0, {}, run.source()));
    run_proof(results.back(), o, c.out, c.catalog);
    if (results.back().proof) {
      progress.finished(k, proof_line(*results.back().proof));
      if (stream) {
        progress.clear();
        fmt::print("{}", reports::prove_rule_text(layout, results.back()));
        std::fflush(stdout);
      }
    }
    run.finished(results.back());
  }
  progress.clear();
  if (!results.empty() && results.back().proof && results.back().proof->interrupted)
    fmt::print(stderr, "interrupted during the solver queries of {}: the queries it did not finish say 'interrupted'\n",
               results.back().entry->rule.name());
  const int status = run.finish(results, rules.size());
  const reports::ProveRun done{c.catalog, o.max_darts, o.rlimit, run.seconds(), c.explain, run.baseline_mismatches()};
  if (stream)
    fmt::print("{}", reports::prove_totals_text(done, results));
  else if (!run.writes_lines())
    print_prove(reports::output_format(c.format), done, results);
  return status;
}

}  // namespace dartcheck::cli
