// --jobs J: one machine's cores for check, fuzz, prove and report. The
// command runs itself as 4J shards, J processes at a time (--shard k/4J
// --format jsonl, one process each: no engine state is shared between rules, and processes
// could not race on it if some ever were) and merges them (`merge`), so
// the output is the one-job output by construction for a fixed --runs.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

#include "campaign/merge.hpp"

namespace dartcheck::campaign {

/// The process's arguments, for running it again as shards (set by main).
void set_command_line(int argc, char** argv);

struct JobsRun {
  std::size_t jobs = 1;
  std::string shard;  // the command's --shard: refused with --jobs
  /// How to render the merge (the command's --format; a report's page in `merge.output`).
  MergeRequest merge;
  /// fuzz and report: the seed every shard must share (drawn here when not given).
  std::optional<std::uint64_t> seed;
  /// fuzz --time and report --fuzz: the whole run's budget. Each shard is
  /// started with what is left of it divided by the waves of shards still
  /// to come (--shard-budget), so that the run takes the budget, not 4x it.
  std::optional<double> budget_seconds;
};

/// Runs the saved command line as `jobs` shard processes and merges them.
/// Returns the merged run's exit status, or the first failing shard's
/// (with its error output). SIGINT or SIGTERM: no shard is started any
/// more, the running ones are sent SIGTERM and reaped, and what finished
/// is merged (merge --incomplete), exit 130; a second signal a second
/// later kills the shards and returns 130 at once. The shards' directory
/// is removed in every case.
int run_jobs(const JobsRun& run);

}  // namespace dartcheck::campaign
