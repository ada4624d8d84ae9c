// `dartcheck fuzz`: every rule of a catalog against random, enumerated and
// given maps (cli/fuzz.hpp), classified against its static verdict, with
// counterexample files that `dartcheck apply` replays.
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>

#include <cstdio>

#include <fmt/format.h>

#include "checkers/map_validity.hpp"
#include "cli/commands.hpp"
#include "analysis/interrupt.hpp"
#include "analysis/verdict_record.hpp"
#include "campaign/jobs.hpp"
#include "campaign/rule_run.hpp"
#include "core/terminal.hpp"
#include "core/wording.hpp"
#include "cli/options.hpp"
#include "reports/run_output.hpp"
#include "analysis/embedded_fuzz.hpp"
#include "analysis/counterexample_files.hpp"
#include "analysis/fuzz.hpp"
#include "analysis/fuzz_targets.hpp"
#include "analysis/rule_result.hpp"
#include "reports/rule_result_text.hpp"
#include "analysis/map_sources.hpp"
#include "core/input_error.hpp"
#include "core/output_file.hpp"
#include "io/map_io.hpp"

namespace dartcheck::cli {

using reports::print_fuzz;

using namespace analysis;  // the engines the commands call
namespace {

// The engine's options from the command's: a drawn seed unless given; with
// --time and no --runs, as many applications as the time allows.
FuzzOptions fuzz_options(const FuzzCommand& c, std::optional<double> seconds) {
  FuzzOptions o;
  o.seed = c.seed ? *c.seed : std::random_device{}();
  o.max_darts = c.max_darts;
  o.runs = c.runs ? *c.runs : seconds ? SIZE_MAX : 10'000;
  o.event_checks = c.event_checks;
  return o;
}

}  // namespace

int fuzz(const FuzzCommand& c) {
  if (c.jobs > 1) {
    if (c.format == "jsonl") throw UsageError("--jobs: not with --format jsonl (run the shards, then merge)");
    // Every shard fuzzes with the same seed: drawn here unless given.
    return campaign::run_jobs({c.jobs,
                               c.shard,
                               {.format = reports::output_format(c.format)},
                               c.seed ? std::nullopt : std::optional<std::uint64_t>(std::random_device{}()),
                               c.time.empty() ? std::nullopt : std::optional(parse_duration(c.time, "--time"))});
  }
  // jsonl: one JSON object per rule on stdout as it finishes, then a summary.
  campaign::RuleRun run("fuzz", {c.catalog, c.rule, c.shard, c.baseline, c.format == "jsonl"});
  if (!c.out.empty()) ensure_directory(c.out);  // before the work, not after it
  if (c.max_darts < 2) throw UsageError("--max-darts: expected at least 2");
  std::optional<double> seconds;
  if (!c.time.empty()) seconds = parse_duration(c.time, "--time");
  if (seconds && c.shard_budget) seconds = *c.shard_budget;  // this shard's part of a --jobs run's budget
  const FuzzOptions o = fuzz_options(c, seconds);
  const FuzzTargets targets = fuzz_targets(run.catalog(), c.rule, c.maps);
  const std::size_t selected = targets.rules.size();
  if (!terminal().quiet)
    fmt::print(stderr, "dartcheck fuzz: seed {} (replay with --seed {}), {}, {}\n", o.seed, o.seed, counted(selected, "rule"),
               seconds ? fmt::format("{} s{}", *seconds, c.runs ? fmt::format(" or {} applications per rule", *c.runs) : "")
                       : fmt::format("{} applications per rule", o.runs));
  // The options that change results go in the header: shards merge only
  // when they agree (a --time run merges, but is not deterministic).
  run.open_lines(
      {{"seed", o.seed}, {"runs", c.runs}, {"time", c.time}, {"max_darts", o.max_darts}, {"event_checks", o.event_checks}, {"maps", c.maps}});
  // Each rule's result (its counterexample files and, with jsonl, its line)
  // is written as soon as the rule finishes: a run killed later keeps them.
  std::vector<RuleResult> results;
  auto finished = [&](std::size_t k, const FuzzReport& r) {
    results.push_back(analyse_static(run.catalog(), *targets.entries[k], 0, {}, run.source()));
    add_fuzz(results.back(), r, o.seed, c.out, c.catalog);
    run.finished(results.back());
  };
  fuzz_rules(targets.rules, targets.seeds, o, seconds, isatty(fileno(stderr)) != 0 && !terminal().quiet, finished);
  const reports::FuzzRun fuzz_run{c.catalog,          o.seed,       run.seconds(), selected, interrupted(), run.baseline_mismatches(), std::nullopt,
                                  true,               reports::fuzz_search_options(c.runs, o.max_darts, o.event_checks, c.maps)};
  const int status = run.finish(results, selected, &fuzz_run);
  if (!run.writes_lines()) print_fuzz(reports::output_format(c.format), fuzz_run, results);
  return status;
}

}  // namespace dartcheck::cli
