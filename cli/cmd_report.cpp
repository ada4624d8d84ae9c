// `dartcheck report`: one self-contained HTML page for a catalog. A verdict
// table (rules x conditions, each failing cell linked to its witnesses),
// then a section per rule: its picture with the witnesses highlighted, the
// static verdict against the recorded one, and, when asked, what the fuzzer
// and the solver found, each counterexample drawn as G, H and the rule.
// The pictures are also written as SVG files beside the page, and each
// counterexample as the files `dartcheck apply` replays.
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <random>

#include <fmt/format.h>

#include "analysis/interrupt.hpp"
#include "analysis/run_stages.hpp"
#include "analysis/rule_result.hpp"
#include "analysis/verdict_record.hpp"
#include "cli/commands.hpp"
#include "campaign/jobs.hpp"
#include "campaign/rule_run.hpp"
#include "cli/options.hpp"
#include "analysis/map_sources.hpp"
#include "reports/run_output.hpp"
#include "core/terminal.hpp"
#include "core/wording.hpp"
#include "core/input_error.hpp"
#include "core/output_file.hpp"

namespace dartcheck::cli {

using reports::ReportStages;
using reports::write_report;

using namespace analysis;  // the engines the commands call
namespace fs = std::filesystem;

int report(const ReportOptions& o) {
  if (o.jobs > 1) {
    if (o.format == "jsonl") throw UsageError("--jobs: not with --format jsonl (run the shards, then merge)");
    const bool seed = !o.fuzz.empty() && !o.seed;  // every shard fuzzes with the same seed
    return campaign::run_jobs({o.jobs,
                               o.shard,
                               {.format = reports::OutputFormat::html, .output = o.output, .engine = o.engine},
                               seed ? std::optional<std::uint64_t>(std::random_device{}()) : std::nullopt,
                               o.fuzz.empty() ? std::nullopt : std::optional(parse_duration(o.fuzz, "--fuzz"))});
  }
  campaign::RuleRun run("report", {o.catalog, o.rule, o.shard, o.baseline, o.format == "jsonl"});
  ReportStages stages;
  stages.baseline = !o.baseline.empty();
  if (!o.fuzz.empty()) stages.fuzz_seconds = parse_duration(o.fuzz, "--fuzz");
  if (o.prove_darts > 256) throw UsageError("--prove: expected 0 (no proof) to 256 darts");
  stages.seed = o.seed ? *o.seed : std::random_device{}();
  stages.prove_darts = o.prove_darts;
  stages.scheme_darts = std::min<std::size_t>(proofs::ProveOptions{}.scheme_darts, o.prove_darts);
  ensure_directory(o.output);  // before the work, not after it
  const std::string cx_dir = (fs::path(o.output) / "counterexamples").string();
  std::vector<RuleResult> rows;
  // The model-level confirmation as check runs it (--confirm-darts).
  const std::vector<Map> maps = confirmation_maps(run.catalog(), o.confirm_darts);
  for (const CatalogRule* e : run.rules()) rows.push_back(analyse_static(run.catalog(), *e, o.confirm_darts, maps, run.source()));
  const std::size_t selected = rows.size();
  if (stages.fuzz_seconds) {
    if (!terminal().quiet)
      fmt::print(stderr, "dartcheck report: fuzzing {} for {} s, seed {}\n", counted(rows.size(), "rule"), *stages.fuzz_seconds, stages.seed);
    fuzz_all(rows, run.catalog(), o.rule, o.shard_budget ? *o.shard_budget : *stages.fuzz_seconds, stages.seed, cx_dir, o.catalog, isatty(fileno(stderr)) != 0 && !terminal().quiet);
  }
  if (stages.prove_darts > 0) {
    if (!terminal().quiet)
      fmt::print(stderr, "dartcheck report: proving {} up to {} darts (schemes {})\n", counted(rows.size(), "rule"), stages.prove_darts,
                 stages.scheme_darts);
    prove_all(rows, stages.prove_darts, stages.scheme_darts, cx_dir, o.catalog, isatty(fileno(stderr)) != 0 && !terminal().quiet);
  }
  // A shard's lines come after every stage (the fuzz budget is shared by the rules).
  run.open_lines({{"fuzz", o.fuzz},
                  {"seed", stages.fuzz_seconds ? std::optional(stages.seed) : std::nullopt},  // drawn only to fuzz
                  {"prove_darts", stages.prove_darts},
                  {"scheme_darts", stages.scheme_darts}});
  for (const auto& r : rows) run.finished(r);
  if (!run.writes_lines()) write_report(o.output, o.engine, o.catalog, run.catalog(), rows, run.baseline_mismatches(), stages);
  return run.finish(rows, selected);
}

}  // namespace dartcheck::cli
