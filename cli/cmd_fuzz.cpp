// `dartcheck fuzz`: every rule of a catalog against random, enumerated and
// given maps (cli/fuzz.hpp), classified against its static verdict, with
// counterexample files that `dartcheck apply` replays.
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <random>

#include <cstdio>

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include "checkers/map_validity.hpp"
#include "cli/commands.hpp"
#include "analysis/interrupt.hpp"
#include "analysis/verdict_record.hpp"
#include "cli/options.hpp"
#include "analysis/embedded_fuzz.hpp"
#include "analysis/counterexample_files.hpp"
#include "analysis/fuzz.hpp"
#include "cli/report_text.hpp"
#include "analysis/map_sources.hpp"
#include "core/input_error.hpp"
#include "io/map_io.hpp"

namespace dartcheck::cli {

using namespace analysis;  // the engines the commands call
namespace {

// The user's maps, built once per model that the fuzzed rules rewrite.
std::vector<Map> given_maps(const std::vector<std::string>& targets, const std::vector<Model>& models,
                            const Catalog& catalog) {
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
    if (built == 0) throw InputError("<command line>", 0, 0, fmt::format("--maps {}: not built for any model of the rules ({})", t, fmt::join(why, "; ")));
    for (const auto& w : why) fmt::print(stderr, "note: --maps {} is not used for {}\n", t, w);
  }
  for (const Map& m : out) {
    const auto report = check_map(m);
    if (!report.valid())
      throw InputError("<command line>", 0, 0, fmt::format("--maps: a given {} of {} darts is not valid ({} violations): fuzzing needs valid hosts",
                                                           m.model().name, m.size(), report.violations.size()));
  }
  return out;
}

}  // namespace

int fuzz(const FuzzCommand& c) {
  // jsonl: one JSON object per rule on stdout as it finishes, then a summary.
  const bool jsonl = c.format == "jsonl";
  const Catalog catalog = read_command_catalog(c.catalog, c.rule, jsonl ? "json" : c.format);
  catch_interrupts();
  if (c.max_darts < 2) throw InputError("<command line>", 0, 0, "--max-darts: expected at least 2");

  FuzzOptions o;
  o.seed = c.seed ? *c.seed : std::random_device{}();
  o.max_darts = c.max_darts;
  std::optional<double> seconds;
  if (!c.time.empty()) seconds = parse_duration(c.time, "--time");
  o.runs = c.runs ? *c.runs : seconds ? SIZE_MAX : 10'000;
  o.event_checks = c.event_checks;

  std::vector<const Operation*> rules;
  std::vector<const CatalogRule*> entries;
  std::vector<Model> models;
  for (const auto& e : catalog.rules) {
    if (!c.rule.empty() && e.rule.name() != c.rule) continue;
    rules.push_back(&e);
    entries.push_back(&e);
    if (std::find(models.begin(), models.end(), e.rule.model()) == models.end()) models.push_back(e.rule.model());
  }
  std::vector<Map> seeds;
  for (const auto& s : catalog.maps)
    if (std::find(models.begin(), models.end(), s.model) != models.end()) seeds.push_back(build_source(s));
  for (auto& m : given_maps(c.maps, models, catalog)) seeds.push_back(std::move(m));

  fmt::print(stderr, "dartcheck fuzz: seed {} (replay with --seed {}), {} rule{}, {}\n", o.seed, o.seed, rules.size(),
             rules.size() == 1 ? "" : "s",
             seconds ? fmt::format("{} s{}", *seconds, c.runs ? fmt::format(" or {} applications per rule", *c.runs) : "")
                     : fmt::format("{} applications per rule", o.runs));
  const auto start = std::chrono::steady_clock::now();
  // Each rule's counterexample files (and, with jsonl, its result line) are
  // written as soon as the rule finishes: a run killed later keeps them.
  std::vector<std::string> replays(rules.size());
  auto rule_json = [&](std::size_t k, const FuzzReport& r) {
    std::string s = fmt::format("{{\"name\": \"{}\", \"model\": \"{}\", \"static_failures\": {}, \"class\": \"{}\", \"applications\": {}, "
                                "\"hosts\": {}, \"largest_host\": {}, \"exhaustive_darts\": {}, \"event_checks\": {}, \"seconds\": {:.4f}, "
                                "\"out_of_time\": {}, \"reason\": \"{}\"",
                                json_escape(r.rule), rules[k]->rule.model().name, json_strings(r.static_failures), fuzz_class_name(r.verdict),
                                r.applications, r.hosts, r.largest_host, r.exhaustive_darts, r.event_checks, r.seconds, r.out_of_time,
                                json_escape(r.reason));
    if (r.counterexample) {
      const auto& cx = *r.counterexample;
      s += fmt::format(", \"counterexample\": {{\"darts\": {}, \"hooks\": [{}], \"broken\": {}, \"minimal\": {}, \"origin\": \"{}\", "
                       "\"events\": {}, \"replay\": \"{}\"}}",
                       cx.host.size(), fmt::join(cx.hooks, ", "), json_strings(cx.broken()), cx.minimal, json_escape(cx.origin),
                       json_strings(cx.event_contradictions), json_escape(replays[k]));
    }
    return s + "}";
  };
  auto finished = [&](std::size_t k, const FuzzReport& r) {
    if (r.counterexample) {
      if (rules[k]->terms)
        replays[k] = embedded_replay(c.catalog, r, o.seed);
      else if (!c.out.empty())
        replays[k] = write_counterexample(c.out, file_stem(r.rule), c.catalog, r.rule,
                                          {{"seed", std::to_string(o.seed)}, {"class", std::string(fuzz_class_name(r.verdict))}}, r.static_failures,
                                          *r.counterexample);
    }
    if (c.format == "jsonl") {
      fmt::print("{}\n", rule_json(k, r));
      std::fflush(stdout);
    }
  };
  const std::vector<FuzzReport> reports = fuzz_rules(rules, seeds, o, seconds, isatty(fileno(stderr)) != 0, finished);
  const double total = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  auto count = [&](FuzzClass v) { return std::count_if(reports.begin(), reports.end(), [&](const FuzzReport& r) { return r.verdict == v; }); };
  std::size_t applications = 0;
  for (const auto& r : reports) applications += r.applications;
  const auto bugs = count(FuzzClass::soundness_bug);
  // A broken map contradicts a recorded 'consistent' (exit 1, as check).
  std::vector<std::string> contradictions;
  for (std::size_t k = 0; k < reports.size(); ++k)
    if (contradicts_record(*entries[k], reports[k].counterexample.has_value()))
      contradictions.push_back(contradiction_line(*entries[k], fmt::format("fuzz broke a map ({})", fuzz_class_name(reports[k].verdict))));
  for (const auto& line : contradictions) fmt::print(stderr, "MISMATCH: {}\n", line);
  int status = bugs ? soundness_bug : contradictions.empty() ? ok : violation;
  // Interrupted (SIGINT, SIGTERM): the finished rules' results are kept.
  if (interrupted()) {
    fmt::print(stderr, "interrupted: {} of {} rule{} finished; the results above are theirs\n", reports.size(), rules.size(), rules.size() == 1 ? "" : "s");
    if (status != soundness_bug) status = interrupted_exit;
  }

  if (c.format == "jsonl") {
    // The rules' lines are out already; the last line sums the run up.
    fmt::print("{{\"summary\": {{\"catalog\": \"{}\", \"seed\": {}, \"seconds\": {:.3f}, \"rules\": {}, \"finished\": {}, \"consistent\": {}, "
               "\"confirmed\": {}, \"unconfirmed\": {}, \"soundness_bugs\": {}, \"applications\": {}, \"interrupted\": {}}}}}\n",
               json_escape(c.catalog), o.seed, total, rules.size(), reports.size(), count(FuzzClass::consistent), count(FuzzClass::confirmed),
               count(FuzzClass::unconfirmed), bugs, applications, interrupted());
    return status;
  }
  if (c.format == "json") {
    fmt::print("{{\"catalog\": \"{}\", \"seed\": {}, \"seconds\": {:.3f}, \"rules\": [\n", json_escape(c.catalog), o.seed, total);
    for (std::size_t k = 0; k < reports.size(); ++k) fmt::print("  {}{}\n", rule_json(k, reports[k]), k + 1 < reports.size() ? "," : "");
    fmt::print("], \"consistent\": {}, \"confirmed\": {}, \"unconfirmed\": {}, \"soundness_bugs\": {}, \"applications\": {}}}\n",
               count(FuzzClass::consistent), count(FuzzClass::confirmed), count(FuzzClass::unconfirmed), bugs, applications);
    return status;
  }

  std::size_t width = 4;
  for (const auto& r : reports) width = std::max(width, r.rule.size());
  fmt::print("{:<{}}  {:<18} {}\n", "rule", width, "static", "dynamic");
  for (std::size_t k = 0; k < reports.size(); ++k) {
    const auto& r = reports[k];
    const std::string stat = r.static_failures.empty() ? "consistent" : fmt::format("fails {}", fmt::join(r.static_failures, " "));
    fmt::print("{:<{}}  {:<18} {}\n", r.rule, width, stat, outcome_text(r));
    if (r.counterexample) {
      const auto& cx = *r.counterexample;
      fmt::print("{:<{}}  found in {}\n", "", width, cx.origin);
      if (!cx.unrepresentable.empty()) fmt::print("{:<{}}  H has no dense form: {}\n", "", width, cx.unrepresentable);
      for (std::size_t e = 0; e < cx.embedding_failures.size() && e < 4; ++e) fmt::print("{:<{}}  H: {}\n", "", width, cx.embedding_failures[e]);
      if (cx.embedding_failures.size() > 4) fmt::print("{:<{}}  H: ... {} more\n", "", width, cx.embedding_failures.size() - 4);
      if (!replays[k].empty())
        fmt::print("{:<{}}  replay: {}\n", "", width, replays[k]);
      else if (!rules[k]->terms)
        fmt::print("{:<{}}  (--out DIR writes the host, the match and H, with a replay command)\n", "", width);
    }
  }
  fmt::print("\n{} rules: {} consistent, {} confirmed, {} unconfirmed, {} soundness bug{}; {} applications in {:.1f} s ({:.0f}/s); seed {}\n",
             reports.size(), count(FuzzClass::consistent), count(FuzzClass::confirmed), count(FuzzClass::unconfirmed), bugs, bugs == 1 ? "" : "s", applications, total, total > 0 ? double(applications) / total : 0.0, o.seed);
  if (!contradictions.empty())
    fmt::print("{}\n", contradiction_summary(contradictions.size()));
  return status;
}

}  // namespace dartcheck::cli
