// `dartcheck merge`: the shards of one run (check, fuzz, prove or report
// with --shard K/N --format jsonl; events, recombine and query on many
// inputs) back into one result, rendered by the commands' own renderers
// (reports/run_output.hpp), so that a merged run prints what the unsharded
// run prints. The static stage is recomputed from the catalog, whose
// digest must be the shards'; the costly stages come from the records
// (campaign/result_record.hpp).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "reports/output_format.hpp"

namespace dartcheck::campaign {

struct MergeRequest {
  std::vector<std::string> shards = {};  // files written by --format jsonl
  reports::OutputFormat format = reports::OutputFormat::text;
  std::string output = {}, catalog = {}, engine = "dot";
  bool explain = false;
  /// Merge what there is: interrupted or killed shards, missing shards and
  /// empty shard files; the result says how many rules are missing and the
  /// exit status is 130 (interrupted) unless a soundness bug makes it 3.
  bool incomplete = false;
  /// --jobs: the run's wall-clock seconds, printed as its time (the
  /// shards' seconds summed are the work done, which a merge of shards
  /// from many hosts prints instead).
  std::optional<double> wall_seconds = std::nullopt;
};

/// Reads, checks (complete, one run, the same catalog) and merges the
/// shards, prints the merged output and returns the run's exit status
/// (analysis/exit_status.hpp). Throws InputError on shards that do not
/// make one run.
int merge_shards(const MergeRequest& request);

}  // namespace dartcheck::campaign
