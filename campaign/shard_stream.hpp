// The JSON lines a command writes with --format jsonl, and what merge
// reads back: a header (the command, the catalog and its digest, the
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

/// A header with the digests of the catalog and baseline files.
RunHeader make_header(std::string command, const std::string& catalog, const std::string& baseline, const std::string& rule, Shard shard,
                      reports::Json parameters);

/// Commands whose run reads one input (recombine, query): a campaign runs
/// one job per input; the header's `catalog` is the input, and merge
/// gathers the runs in the order of their inputs' paths.
bool per_input_command(std::string_view command);

/// Prints the run of a per-input command (recombine, query) as --format
/// asks: its text, its JSON document, or (jsonl) the one run of a campaign
/// over many inputs: a header naming the input and the options that
/// change results, the input's line, and a summary with the exit status.
void print_input_run(const std::string& format, const std::string& command, const std::string& input, reports::Json parameters,
                     reports::Json document, const std::string& text, int status);

/// Writes the lines on stdout, each flushed.
class ShardWriter {
 public:
  explicit ShardWriter(const RunHeader& header);
  void rule(const analysis::RuleResult& r);
  /// A per-input command's result: its JSON document and its text.
  void input(reports::Json document, const std::string& text);
  /// One rule's part of an output that is not a RuleResult (events): its
  /// JSON object (null when the JSON output has none) and its text.
  void fragment(const std::string& rule, reports::Json json, const std::string& text);
  void summary(reports::Json summary);

 private:
  void line(const char* type, reports::Json payload, std::optional<reports::Json> record = std::nullopt);
  std::string command_;
};

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
};

/// Reads a file written by --format jsonl. InputError with file:line on
/// malformed lines, a missing header, and a missing or interrupted summary
/// (a shard that did not finish cannot be merged as if it had).
ShardFile read_shard_file(const std::string& file);

/// Checks that `files` are the N shards of one run, each exactly once;
/// InputError naming the missing shard, the duplicated one (with both
/// files) or the option that differs. Returns them ordered by shard. For
/// a per-input command: runs with the same options, each input once,
/// ordered by the input's path.
std::vector<ShardFile> check_complete(std::vector<ShardFile> files);

}  // namespace dartcheck::campaign
