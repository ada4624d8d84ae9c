// The output of `dartcheck events` as --format asks: each rule's part (its
// JSON object, none for a rule that --orbit skips, and its text) printed
// as it comes, gathered into one document (json), or written as a shard's
// lines (jsonl), so that a run killed later keeps the rules it finished.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "analysis/rule_events.hpp"
#include "campaign/run_parameters.hpp"
#include "campaign/shard_writer.hpp"
#include "io/catalog.hpp"
#include "reports/output_format.hpp"

namespace dartcheck::campaign {

class EventsOutput {
 public:
  /// `parameters`: the options that change the events (--orbit, --map...).
  EventsOutput(reports::OutputFormat format, std::string catalog, const std::string& rule, const Shard& shard, const Parameters& parameters);
  ~EventsOutput();

  /// A rule whose events were found.
  void analysed(const analysis::RuleEvents& r);
  /// A rule that could not be analysed, and why (in the JSON output too).
  void not_analysed(const CatalogRule& rule, const std::string& why);
  /// A rule that --orbit does not fit: a line of text, nothing in JSON.
  void skipped(const CatalogRule& rule, const std::string& why);
  /// The end of the run: the document (json), the summary line (jsonl),
  /// or the line of counts (text, events_counts_line).
  void finish(int status, std::size_t analysed, bool interrupted);

 private:
  struct Rules;  // the rules' JSON objects, for the json document
  void rule(const CatalogRule& rule, const reports::Json* json, const std::string& text);
  reports::OutputFormat format_;
  std::string catalog_;
  std::optional<ShardWriter> lines_;
  std::unique_ptr<Rules> rules_;
  std::size_t not_analysed_ = 0, skipped_ = 0;
};

/// The last line of events' text: how many rules were analysed, could not
/// be, and were skipped by --orbit (a merge of shards prints the same).
std::string events_counts_line(std::size_t analysed, std::size_t not_analysed, std::size_t skipped);

}  // namespace dartcheck::campaign
