// The writer of a run's JSON lines (--format jsonl, campaign/shard_stream.hpp
// reads them back): a header, one line per finished rule or input, a
// summary. Each line is flushed as it is written, so a shard killed halfway
// keeps its finished rules. Declares reports::Json only (json_fwd), so that
// the commands that hold a writer do not compile the JSON library.
#pragma once

#include <optional>
#include <string>

#include "analysis/rule_result.hpp"
#include "campaign/run_parameters.hpp"
#include "campaign/shard.hpp"
#include "reports/json_fwd.hpp"

namespace dartcheck::campaign {

struct RunHeader;

/// A header with the digests of the catalog and baseline files.
RunHeader make_header(std::string command, const std::string& catalog, const std::string& baseline, const std::string& rule, Shard shard,
                      const Parameters& parameters);

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
  void line(const char* type, reports::Json payload, std::optional<reports::Json> record);
  std::string command_;
};

}  // namespace dartcheck::campaign
