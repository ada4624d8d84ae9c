// `dartcheck merge`: the shards of one run (check, fuzz, prove or report
// with --shard K/N --format jsonl) back into one result, rendered by the
// command's own renderers (reports/run_output.hpp). The static stage is
// recomputed from the catalog, whose digest must be the shards'; the
// costly stages come from the records (campaign/result_record.hpp).
#include <algorithm>
#include <array>
#include <filesystem>
#include <limits>
#include <map>

#include <fmt/format.h>

#include "analysis/verdict_record.hpp"
#include "analysis/exit_status.hpp"
#include "analysis/interrupt.hpp"
#include "campaign/events_output.hpp"
#include "campaign/merge.hpp"
#include "campaign/detail/result_record.hpp"
#include "campaign/detail/shard_stream.hpp"
#include "core/number_text.hpp"
#include "core/wording.hpp"
#include "reports/run_output.hpp"
#include "core/input_error.hpp"
#include "core/output_file.hpp"
#include "reports/rule_result_json.hpp"

namespace dartcheck::campaign {

using namespace exit_status;
using namespace reports;

using namespace analysis;

namespace {

// A number of the header's parameters, as the command wrote it.
template <class T>
T parameter(const RunHeader& h, const char* key) {
  const auto it = h.parameters.find(key);
  if (it == h.parameters.end() || !it->is_number_unsigned() || it->get<std::uint64_t>() > std::numeric_limits<T>::max())
    throw InputError("<shards>", 0, 0, fmt::format("the header has no count \"{}\" for {}", key, h.command));
  return it->get<T>();
}

// A string of the header's parameters ("" when absent).
std::string text_parameter(const RunHeader& h, const char* key) {
  const auto it = h.parameters.find(key);
  if (it == h.parameters.end()) return {};
  if (!it->is_string()) throw InputError("<shards>", 0, 0, fmt::format("the header's \"{}\" is not a string", key));
  return it->get<std::string>();
}

// The catalog the shards ran on, unchanged since (its digest), with the
// baseline they read.
Catalog merged_catalog(const RunHeader& h, const std::string& override_path, std::vector<std::string>& baseline_mismatches) {
  const std::string path = override_path.empty() ? h.catalog : override_path;
  if (file_digest(path) != h.catalog_digest)
    throw InputError(path, 0, 0, fmt::format("not the catalog the shards ran on (its digest is {}, theirs {})", file_digest(path), h.catalog_digest));
  Catalog catalog = read_catalog(path);
  if (!h.baseline.empty()) {
    if (file_digest(h.baseline) != h.baseline_digest) throw InputError(h.baseline, 0, 0, "not the baseline the shards ran with (its digest changed)");
    baseline_mismatches = apply_baseline(catalog, h.baseline);
  }
  return catalog;
}

// Every selected rule of the catalog from the shard its name belongs to,
// in catalog order; an error for a rule that is left over, or missing
// unless the merge is incomplete (then `selected` counts it).
Results merged_results(const Catalog& catalog, const std::vector<ShardFile>& shards, bool incomplete, std::size_t& selected) {
  const auto& h = shards.front().header;
  const RecordSource source = h.baseline.empty() ? RecordSource::catalog : RecordSource::baseline;
  std::map<std::size_t, std::map<std::string, const ShardRule*>> by_name;  // by shard index
  std::map<std::size_t, const ShardFile*> by_index;
  for (const auto& f : shards) {
    by_index[f.header.shard.index] = &f;
    auto& names = by_name[f.header.shard.index];
    for (const auto& r : f.rules)
      if (!names.emplace(r.name, &r).second) throw InputError(f.file, r.line, 1, fmt::format("rule '{}' twice", printable(r.name)));
  }
  Results results;
  selected = 0;
  for (const auto& e : catalog.rules) {
    if (!h.rule.empty() && e.rule.name() != h.rule) continue;
    ++selected;
    const std::size_t k = stable_hash(e.rule.name()) % h.shard.count;
    auto& names = by_name[k];
    const auto it = names.find(reports::replace_invalid_utf8(e.rule.name()));
    if (it == names.end()) {
      if (incomplete) continue;
      throw InputError(by_index.at(k)->file, 0, 0,
                       fmt::format("rule '{}' ({}) belongs to shard {}/{}, which has no line for it", printable(e.rule.name()), e.location.str(), k,
                                   h.shard.count));
    }
    results.push_back(analyse_static(catalog, e, 0, {}, source));
    try {
      restore_record(results.back(), it->second->record);
    } catch (const RecordError& err) {
      throw InputError(by_index.at(k)->file, it->second->line, 1, err.what());
    }
    names.erase(it);
  }
  for (const auto& [k, names] : by_name)
    if (!names.empty()) {
      const auto* left = names.begin()->second;
      throw InputError(by_index.at(k)->file, left->line, 1,
                       fmt::format("rule '{}' is not a rule of shard {} of {} in the catalog", printable(left->name), k, h.catalog));
    }
  return results;
}

// The worse of two runs' exit statuses: a soundness bug, then a violation.
int worse(int a, int b) { return a == soundness_bug || b == soundness_bug ? soundness_bug : a == violation || b == violation ? violation : ok; }

// recombine and query on many inputs, one run each: their documents in
// one JSON document, or their texts one after the other, in the order of
// the inputs' paths; the worst exit status (3, then 1, then 0).
int merge_inputs(const std::vector<ShardFile>& files, OutputFormat format) {
  const std::string& command = files.front().header.command;
  if (format != OutputFormat::text && format != OutputFormat::json) throw UsageError(fmt::format("--format: {} runs merge as text or json", command));
  int status = ok;
  Json runs = Json::array();
  std::string text;
  bool incomplete = false;
  for (const auto& f : files) {
    incomplete = incomplete || !f.finished;
    if (f.input.is_null()) continue;  // killed before its result (merge --incomplete)
    if (f.summary.is_object()) status = worse(status, f.summary.value("status", 0));
    runs.push_back(f.input["document"]);
    text += f.input["text"].get<std::string>();
  }
  fmt::print(stderr, "dartcheck merge: {} runs of {}\n", files.size(), command);
  if (format == OutputFormat::json) {
    Json doc = reports::json_document(command + "-campaign");
    doc["inputs"] = files.size();
    doc["runs"] = std::move(runs);
    fmt::print("{}\n", reports::json_text(std::move(doc)));
  } else {
    fmt::print("{}", printable(text));  // a shard file is input: no escape sequence reaches the terminal
  }
  if (incomplete) {
    fmt::print(stderr, "incomplete: {} of {} runs finished; the results above are theirs and those of the runs a signal stopped\n",
               std::count_if(files.begin(), files.end(), [](const ShardFile& f) { return f.finished; }), files.size());
    if (status != soundness_bug) return analysis::interrupted_exit;
  }
  return status;
}

// events: every shard's rule fragments in catalog order, each from the
// shard its name belongs to; the worst exit status.
int merge_events(const Catalog& catalog, const std::vector<ShardFile>& shards, OutputFormat format) {
  if (format != OutputFormat::text && format != OutputFormat::json) throw UsageError("--format: events shards merge as text or json");
  const auto& h = shards.front().header;
  std::map<std::string, std::size_t> order;
  for (std::size_t k = 0; k < catalog.rules.size(); ++k) order.emplace(reports::replace_invalid_utf8(catalog.rules[k].rule.name()), k);
  std::map<std::size_t, const Json*> fragments;
  int status = ok;
  bool incomplete = shards.size() < h.shard.count;
  for (const auto& shard : shards) {
    const std::size_t k = shard.header.shard.index;
    incomplete = incomplete || !shard.finished;
    if (shard.summary.is_object()) status = worse(status, shard.summary.value("status", 0));
    for (const Json& f : shard.fragments) {
      const std::string name = f["rule"].get<std::string>();
      const auto at = order.find(name);
      if (at == order.end() || stable_hash(catalog.rules[at->second].rule.name()) % h.shard.count != k)
        throw InputError(shard.file, 0, 0, fmt::format("rule '{}' is not a rule of shard {} of {} in the catalog", printable(name), k, h.catalog));
      if (!fragments.emplace(at->second, &f).second) throw InputError(shard.file, 0, 0, fmt::format("rule '{}' twice", printable(name)));
    }
  }
  fmt::print(stderr, "dartcheck merge: {} shards of events {}, {} rules\n", shards.size(), h.catalog, fragments.size());
  if (format == OutputFormat::json) {
    Json doc = reports::json_document("events");
    doc["catalog"] = h.catalog;
    doc["rules"] = Json::array();
    for (const auto& [k, f] : fragments)
      if (!(*f)["json"].is_null()) doc["rules"].push_back((*f)["json"]);
    fmt::print("{}\n", reports::json_text(std::move(doc)));
  } else {
    for (const auto& [k, f] : fragments) fmt::print("{}", printable((*f)["text"].get<std::string>()));
    std::size_t counts[3] = {0, 0, 0};  // analysed, not analysed, skipped: the shards' summaries
    for (const auto& shard : shards)
      if (shard.summary.is_object())
        for (int c = 0; c < 3; ++c) counts[c] += shard.summary.value(std::array{"analysed", "not_analysed", "skipped"}[c], std::size_t{0});
    fmt::print("{}", events_counts_line(counts[0], counts[1], counts[2]));
  }
  if (incomplete) {
    fmt::print(stderr, "incomplete: {} of {} shards finished; the rules above are theirs\n",
               std::count_if(shards.begin(), shards.end(), [](const ShardFile& f) { return f.finished; }), h.shard.count);
    if (status != soundness_bug) return analysis::interrupted_exit;
  }
  return status;
}

}  // namespace

int merge_shards(const MergeRequest& o) {
  std::vector<ShardFile> files;
  for (const auto& f : o.shards) {
    // A shard killed before its header (--jobs stopped by a signal) has nothing to give.
    std::error_code ec;
    if (o.incomplete && std::filesystem::is_regular_file(f, ec) && std::filesystem::file_size(f, ec) == 0) continue;
    files.push_back(read_shard_file(f, o.incomplete));
  }
  if (files.empty() && o.incomplete) throw UsageError("merge --incomplete: every shard file is empty (no shard started)");
  files = check_complete(std::move(files), o.incomplete);
  const RunHeader& h = files.front().header;
  if (per_input_command(h.command)) return merge_inputs(files, o.format);
  if (o.format == OutputFormat::html && o.output.empty()) throw UsageError("--format html: give -o DIR for the page");
  if (h.command == "report" && o.format == OutputFormat::text) throw UsageError("--format: a report merges as html, json, sarif or junit");
  if (o.format == OutputFormat::html) ensure_directory(o.output);

  std::vector<std::string> baseline_mismatches;
  const Catalog catalog = merged_catalog(h, o.catalog, baseline_mismatches);
  if (h.command == "events") return merge_events(catalog, files, o.format);
  std::size_t selected = 0;
  const Results results = merged_results(catalog, files, o.incomplete, selected);
  // Incomplete: a shard stopped, killed or missing, so some rules may have no result.
  const bool incomplete = files.size() < h.shard.count || std::any_of(files.begin(), files.end(), [](const ShardFile& f) { return !f.finished; });
  // The run's seconds: a --jobs run's wall clock, else the shards' summed
  // time (the work done), which the text says it is.
  double shard_seconds = 0;
  for (const auto& f : files)
    if (f.summary.is_object()) shard_seconds += f.summary.value("seconds", 0.0);
  const double seconds = o.wall_seconds.value_or(shard_seconds);
  fmt::print(stderr, "dartcheck merge: {} of {} {}, {}\n", counted(files.size(), "shard"), h.command, h.catalog, counted(results.size(), "rule"));

  if (o.format == OutputFormat::sarif || o.format == OutputFormat::junit) {
    print_ci_format(o.format, h.command, h.catalog, results, baseline_mismatches);
  } else if (o.format == OutputFormat::html) {
    ReportStages stages;
    stages.baseline = !h.baseline.empty();
    if (h.command == "report" || h.command == "fuzz") {
      const std::string budget = text_parameter(h, h.command == "report" ? "fuzz" : "time");
      if (h.command == "fuzz" || !budget.empty()) {
        stages.fuzz_seconds = budget.empty() ? seconds : parse_duration(budget, "fuzz");
        stages.seed = parameter<std::uint64_t>(h, "seed");
      }
    }
    if (h.command == "report" || h.command == "prove") {
      stages.prove_darts = parameter<std::size_t>(h, h.command == "report" ? "prove_darts" : "max_darts");
      stages.scheme_darts = parameter<std::size_t>(h, "scheme_darts");
    }
    write_report(o.output, o.engine, h.catalog, catalog, results, baseline_mismatches, stages);
  } else if (h.command == "check") {
    print_check(o.format, h.catalog, catalog, results, baseline_mismatches, o.explain);
  } else if (h.command == "fuzz") {
    // The hints' commands carry the options that decide the hosts.
    const auto runs = h.parameters.find("runs");
    std::vector<std::string> maps;
    if (const auto m = h.parameters.find("maps"); m != h.parameters.end() && m->is_array())
      for (const auto& x : *m)
        if (x.is_string()) maps.push_back(x.get<std::string>());
    const std::string search = reports::fuzz_search_options(
        runs != h.parameters.end() && runs->is_number_unsigned() ? std::optional(runs->get<std::size_t>()) : std::nullopt,
        parameter<std::size_t>(h, "max_darts"), parameter<std::size_t>(h, "event_checks"), maps);
    print_fuzz(o.format,
               {h.catalog, parameter<std::uint64_t>(h, "seed"), seconds, selected, incomplete, baseline_mismatches, shard_seconds,
                o.wall_seconds.has_value(), search},
               results);
  } else if (h.command == "prove") {
    print_prove(o.format,
                {h.catalog, parameter<std::size_t>(h, "max_darts"), parameter<unsigned>(h, "rlimit"), seconds, o.explain, baseline_mismatches},
                results);
  } else {  // report, json (text refused above)
    fmt::print("{}\n", reports::json_text(reports::results_document("report", h.catalog, catalog, results, baseline_mismatches)));
  }
  return finish_run(results, baseline_mismatches, selected, incomplete || analysis::interrupted());
}

}  // namespace dartcheck::campaign
