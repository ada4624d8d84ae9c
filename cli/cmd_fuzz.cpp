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
#include "campaign/shard_stream.hpp"
#include "cli/jobs.hpp"
#include "cli/options.hpp"
#include "reports/run_output.hpp"
#include "analysis/embedded_fuzz.hpp"
#include "analysis/counterexample_files.hpp"
#include "analysis/fuzz.hpp"
#include "analysis/rule_result.hpp"
#include "reports/rule_result_json.hpp"
#include "reports/rule_result_text.hpp"
#include "analysis/map_sources.hpp"
#include "core/input_error.hpp"
#include "core/output_file.hpp"
#include "io/map_io.hpp"

namespace dartcheck::cli {

using reports::finish_run;

using reports::print_fuzz;

using namespace analysis;  // the engines the commands call
namespace {

// The user's maps, built once per model that the fuzzed rules rewrite.
std::vector<Map> given_maps(const std::vector<std::string>& targets, const std::vector<Model>& models, const Catalog& catalog) {
  std::vector<Map> out;
  if (models.empty()) return out;  // a catalog without rules: nothing to fuzz
  for (const auto& t : targets) {
    const auto ext = std::filesystem::path(t).extension().string();
    if (ext == ".yaml" || ext == ".yml" || ext == ".jba") {
      out.push_back(resolve_map(t, models.front(), &catalog));  // the file names its model (a .jba its dimension)
      continue;
    }
    std::vector<std::string> why;
    std::size_t built = 0;
    for (const Model& m : models) {
      try {
        out.push_back(resolve_map(t, m, &catalog));
        ++built;
      } catch (const InputError& e) {
        why.push_back(fmt::format("{}: {}", m.name, e.what()));
      }
    }
    if (built == 0)
      throw InputError("<command line>", 0, 0, fmt::format("--maps {}: not built for any model of the rules ({})", t, fmt::join(why, "; ")));
    for (const auto& w : why) fmt::print(stderr, "note: --maps {} is not used for {}\n", t, w);
  }
  for (const Map& m : out) {
    const auto report = check_map(m);
    if (!report.valid())
      throw InputError("<command line>", 0, 0,
                       fmt::format("--maps: a given {} of {} darts is not valid ({} violations): fuzzing needs valid hosts", m.model().name, m.size(),
                                   report.violations.size()));
  }
  return out;
}

// The rules to fuzz and the hosts they start from: the catalog's maps of
// their models and the user's --maps.
struct Targets {
  std::vector<const Operation*> rules;
  std::vector<const CatalogRule*> entries;
  std::vector<Map> seeds;
};

Targets select_targets(const FuzzCommand& c, const Catalog& catalog) {
  Targets t;
  std::vector<Model> models;
  for (const auto& e : catalog.rules) {
    if (!c.rule.empty() && e.rule.name() != c.rule) continue;
    t.rules.push_back(&e);
    t.entries.push_back(&e);
    if (std::find(models.begin(), models.end(), e.rule.model()) == models.end()) models.push_back(e.rule.model());
  }
  for (const auto& s : catalog.maps)
    if (std::find(models.begin(), models.end(), s.model) != models.end()) t.seeds.push_back(build_source(s));
  for (auto& m : given_maps(c.maps, models, catalog)) t.seeds.push_back(std::move(m));
  return t;
}

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
    if (c.format == "jsonl") throw InputError("<command line>", 0, 0, "--jobs: not with --format jsonl (run the shards, then merge)");
    // Every shard fuzzes with the same seed: drawn here unless given.
    return run_jobs({c.jobs, c.shard, {.format = c.format}, c.seed ? std::nullopt : std::optional<std::uint64_t>(std::random_device{}())});
  }
  // jsonl: one JSON object per rule on stdout as it finishes, then a summary.
  const bool jsonl = c.format == "jsonl";
  Catalog catalog = read_command_catalog(c.catalog, c.rule, jsonl ? "json" : c.format);
  const campaign::Shard shard = command_shard(c.shard);
  const auto baseline_mismatches = c.baseline.empty() ? std::vector<std::string>{} : apply_baseline(catalog, c.baseline);
  campaign::keep_shard(catalog, shard);
  const RecordSource source = c.baseline.empty() ? RecordSource::catalog : RecordSource::baseline;
  if (!c.out.empty()) ensure_directory(c.out);  // before the work, not after it
  catch_interrupts();
  if (c.max_darts < 2) throw InputError("<command line>", 0, 0, "--max-darts: expected at least 2");

  std::optional<double> seconds;
  if (!c.time.empty()) seconds = parse_duration(c.time, "--time");
  const FuzzOptions o = fuzz_options(c, seconds);

  const Targets targets = select_targets(c, catalog);
  const auto& rules = targets.rules;
  const auto& entries = targets.entries;
  const auto& seeds = targets.seeds;

  fmt::print(stderr, "dartcheck fuzz: seed {} (replay with --seed {}), {} rule{}, {}\n", o.seed, o.seed, rules.size(), rules.size() == 1 ? "" : "s",
             seconds ? fmt::format("{} s{}", *seconds, c.runs ? fmt::format(" or {} applications per rule", *c.runs) : "")
                     : fmt::format("{} applications per rule", o.runs));
  // The options that change results go in the header: shards merge only
  // when they agree (a --time run merges, but is not deterministic).
  std::optional<campaign::ShardWriter> lines;
  if (jsonl)
    lines.emplace(campaign::make_header("fuzz", c.catalog, c.baseline, c.rule, shard,
                                        reports::Json{{"seed", o.seed},
                                                      {"runs", c.runs ? reports::Json(*c.runs) : reports::Json(nullptr)},
                                                      {"time", c.time},
                                                      {"max_darts", o.max_darts},
                                                      {"event_checks", o.event_checks},
                                                      {"maps", c.maps}}));
  const auto start = std::chrono::steady_clock::now();
  // Each rule's result (its counterexample files and, with jsonl, its line)
  // is written as soon as the rule finishes: a run killed later keeps them.
  std::vector<RuleResult> results;
  auto finished = [&](std::size_t k, const FuzzReport& r) {
    results.push_back(analyse_static(catalog, *entries[k], 0, {}, source));
    add_fuzz(results.back(), r, o.seed, c.out, c.catalog);
    if (lines) lines->rule(results.back());
  };
  fuzz_rules(rules, seeds, o, seconds, isatty(fileno(stderr)) != 0, finished);
  const double total = seconds_since(start);

  const int status = finish_run(results, baseline_mismatches, rules.size());
  const reports::FuzzRun run{c.catalog, o.seed, total, rules.size(), interrupted(), baseline_mismatches};
  if (lines)
    lines->summary(reports::fuzz_summary_json(run, results));  // the rules' lines are out already
  else
    print_fuzz(c.format, run, results);
  return status;
}

}  // namespace dartcheck::cli
