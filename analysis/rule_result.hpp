// The result model: what dartcheck found about one rule of a catalog, from
// every stage a command ran (GUIDE, "The pipeline"). check, fuzz, prove and
// report build RuleResults through the functions below and differ only in
// the stages they run and the renderer they choose (reports/); so a verdict,
// the list of failing conditions and the comparison with the recorded
// verdict are computed in one place and read the same in every output.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "analysis/embedding_checks.hpp"
#include "analysis/fuzz.hpp"
#include "checkers/host_search.hpp"
#include "checkers/rule_conditions.hpp"
#include "io/catalog.hpp"
#include "proofs/rule_prover.hpp"
#include "analysis/potential_events.hpp"

namespace dartcheck::analysis {

/// Where the recorded verdict comes from: the catalog's `verdict:` keys or
/// a baseline side file (io/baseline.hpp).
enum class RecordSource { catalog, baseline };

struct RuleResult {
  const CatalogRule* entry = nullptr;  // location, rule, model, recorded verdict
  RecordSource record_source = RecordSource::catalog;

  // Static stage (002 Def. 11-16, 21-27; 003 Theorems 2 and 4).
  RuleVerdict verdict;
  std::vector<EmbeddingCheck> embedding;
  /// The failing conditions: topological in the checker's order, then the
  /// required embedding checks. The one list every output names.
  std::vector<std::string> failures;
  double static_ms = 0;

  // Model-level confirmation (check): a failing DPO rule on every small map
  // of its model that contains L; a scheme on small, catalog and random maps.
  std::optional<HostSearch> host_search;
  std::optional<FuzzReport> scheme_search;

  // Fuzz stage, with the command that replays its counterexample ("" when
  // there is none or nowhere to write it).
  std::optional<FuzzReport> fuzz;
  std::string fuzz_replay;
  std::string events_replay;  // replays the event contradiction, if any

  // Solver stage, with one replay command per constraint ("" when none);
  // a counterexample that replays dynamically as `proof_maps` (per constraint).
  std::optional<proofs::RuleProof> proof;
  std::vector<std::string> proof_replays;
  std::vector<std::optional<Counterexample>> proof_maps;
  // Per embedding answer of the proof (one entry each): the shell commands
  // that replay its counterexample files (apply, then validate-map), or "".
  std::vector<std::string> embedding_replays;
  // 004's potential events decided on hosts up to K (prove), and per
  // event the command that replays its witness (with --out), or empty.
  std::optional<PotentialEvents> potential_events;
  std::vector<std::string> potential_event_replays;

  /// How this run compares with the recorded verdict: one sentence per
  /// disagreement (empty: it matches). Filled by `compare_with_record`.
  std::vector<std::string> mismatches;
  /// Whether mismatches[0] is the static verdict against the recorded one
  /// (the other entries: a broken map, the solver, a soundness bug).
  bool verdict_differs = false;

  const std::string& name() const { return entry->rule.name(); }
  bool consistent() const { return failures.empty(); }
  bool topological_failure() const;
  /// A stage found a broken map that the static verdict says cannot exist
  /// (model-level confirmation or fuzz), or the solver contradicts a
  /// theorem: a defect of dartcheck, exit 3.
  bool unsound() const;
  /// fuzz found an application whose event logs contradict the static
  /// events (004): a defect of the event analysis, reported apart from
  /// the rule's verdict.
  bool events_contradicted() const { return fuzz && fuzz->event_contradiction; }
  /// Whether some stage broke a map of the model.
  bool broke_a_map() const;
  bool matches_record() const { return mismatches.empty(); }
  /// A failing rule for which nothing is recorded (a modeler's first run):
  /// a finding to record with --write-baseline, not a changed verdict.
  bool first_run_finding() const { return verdict_differs && !entry->expected_failures; }

  /// "consistent" or "fails I(1) C(0,2)".
  std::string verdict_text() const;
  /// "consistent", "fails I(1)" or "none recorded".
  std::string recorded_text() const;
  /// "catalog" or "baseline".
  std::string_view record_source_name() const;
  /// The model-level confirmation in one sentence ("" when none ran).
  std::string confirmation_text() const;
  /// The solver's refined verdict per embedding (prove, check --solver):
  /// "fails A(col) syntactically; Z3: no host up to 5 darts breaks col,
  /// for every interpretation of mix"; empty without a solver stage.
  std::vector<std::string> solver_lines() const;
  /// The solver's class per embedding as a baseline records it (io/
  /// baseline.hpp: holds, breaks, false alarm, other algebra, unknown);
  /// empty without a solver stage.
  std::vector<std::pair<std::string, std::string>> solver_classes() const;
  /// Fuzz broke an embedding on a host no larger than the K up to which
  /// the solver found none (in either reading): what contradicts, or empty.
  std::string solver_fuzz_contradiction() const;
};

/// The static stage of one rule: conditions, embedding checks and, with
/// `confirm_darts` > 0, the model-level confirmation (a failing DPO rule on
/// hosts of up to |L| + confirm_darts darts; every scheme through the
/// fuzzer with a small fixed budget, on `catalog_maps` too). Compares
/// with the record.
/// The budget of a scheme's model-level confirmation: the fuzzer with seed
/// 1, this many applications, random hosts up to this many darts, no event
/// checks (`dartcheck fuzz --seed 1 --runs 2000 --max-darts 64
/// --event-checks 0` finds the same hosts).
inline constexpr std::size_t scheme_confirmation_runs = 2000, scheme_confirmation_darts = 64;

RuleResult analyse_static(const Catalog& catalog, const CatalogRule& entry, std::size_t confirm_darts, const std::vector<Map>& catalog_maps = {},
                          RecordSource source = RecordSource::catalog);

/// Adds a fuzz report and compares again. Its replay commands: an
/// embedded rule's `fuzz --seed` line, or the files written under
/// `out_dir` (host, match, H; named after the rule plus `suffix`, and
/// ".events" for an event contradiction) and their `apply` or
/// `events --dynamic` line; none when there is nowhere to write.
void add_fuzz(RuleResult& r, FuzzReport report, std::uint64_t seed, const std::string& out_dir, const std::string& catalog_file,
              const std::string& suffix = "");

/// check --solver: the embedding queries alone (proofs/embedding_prover)
/// on hosts of up to |L| + 4 darts, as the rule's proof,
/// compared again; nothing for a rule without terms.
void run_embedding_solver(RuleResult& r, const std::function<bool()>& stop);

/// Adds a proof with its replays and dynamic counterexamples, and compares again.
void add_proof(RuleResult& r, proofs::RuleProof proof, std::vector<std::string> replays, std::vector<std::optional<Counterexample>> maps);

/// The solver stage: proves the rule, replays every counterexample on a map
/// of the model through the library's own derivation, writes those under
/// `out_dir` (when given; files named rule + suffix + "." + constraint)
/// and adds it all to `r`.
void run_proof(RuleResult& r, const proofs::ProveOptions& options, const std::string& out_dir, const std::string& catalog_file,
               const std::string& suffix = "");

/// Recomputes `mismatches`: the static failures against the recorded ones
/// (none recorded: every condition must hold), a broken map against a
/// recorded 'consistent', and a soundness bug of the checker.
void compare_with_record(RuleResult& r);

/// Counts over a run's results, for every summary line.
struct ResultCounts {
  std::size_t rules = 0, consistent = 0, failing = 0, mismatches = 0, unsound = 0, events_contradicted = 0;
  std::size_t first_run_findings = 0;  // of the mismatches: failing rules with no verdict recorded
};
ResultCounts count_results(const std::vector<RuleResult>& results);

}  // namespace dartcheck::analysis
