// The JSON lines a command writes with --format jsonl (campaign/shard_writer),
// and what merge reads back: a header (the command, the catalog and its digest, the
// options that change results, the shard), one line per finished rule
// (the rule's JSON, as --format json gives it, and its record,
// campaign/result_record.hpp), and a summary line when the run ends. Each
// line is flushed as it is written, so a shard killed halfway keeps its
// finished rules, and merge can tell it from a finished shard.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "analysis/rule_result.hpp"
#include "campaign/shard.hpp"
#include "campaign/shard_writer.hpp"
#include "reports/json_document.hpp"

namespace dartcheck::campaign {

/// What identifies a run: shards merge only when everything but the
/// shard index is equal.
struct RunHeader {
  std::string command;  // check, fuzz, prove or report
  std::string catalog;  // the path given on the command line
  std::string catalog_digest;
  std::string baseline, baseline_digest;  // "" when the catalog's verdicts are used
  std::string rule;                       // --rule ("" for every rule)
  Shard shard;
  /// The options that change results: seed, --runs, --max-darts...
  reports::Json parameters = reports::Json::object();
};

/// Commands whose run reads one input (recombine, query): a campaign runs
/// one job per input; the header's `catalog` is the input, and merge
/// gathers the runs in the order of their inputs' paths.
bool per_input_command(std::string_view command);

/// The summary line of check, prove and report: rules selected and
/// finished, whether a signal stopped the run, its seconds, the counts.
reports::Json run_summary(const std::vector<analysis::RuleResult>& results, std::size_t selected, bool interrupted, double seconds,
                          const std::vector<std::string>& baseline_mismatches);

/// One rule line as read back: its name, the JSON and the record, and
/// the line it was on.
struct ShardRule {
  std::string name;
  reports::Json record;
  int line = 0;
};

/// One shard file as read back.
struct ShardFile {
  std::string file;
  RunHeader header;
  std::vector<ShardRule> rules;
  reports::Json input;                   // a per-input command's {"document", "text"}
  std::vector<reports::Json> fragments;  // events: {"rule", "json", "text"} per rule
  reports::Json summary;
  /// False for a shard a signal stopped (its summary says so) or that
  /// ended without a summary (killed): read only with `incomplete`.
  bool finished = true;
};

/// Reads a file written by --format jsonl. InputError with file:line on
/// malformed lines, a line of another format version, a missing header,
/// and a missing or interrupted summary: a shard that did not finish
/// cannot be merged as if it had. With `incomplete`, such a shard is read
/// with `finished` false (merge --incomplete: a result marked incomplete).
ShardFile read_shard_file(const std::string& file, bool incomplete = false);

/// Checks that `files` are the N shards of one run, each exactly once;
/// InputError naming the missing shard, the duplicated one (with both
/// files) or the option that differs. Returns them ordered by shard. For
/// a per-input command: runs with the same options, each input once,
/// ordered by the input's path. With `incomplete`, missing shards are
/// allowed (the caller marks the result incomplete).
std::vector<ShardFile> check_complete(std::vector<ShardFile> files, bool incomplete = false);

}  // namespace dartcheck::campaign
