// Differential testing of one rule or rule scheme: apply it at many matches
// on valid maps of its model, check every result dynamically, and set the
// outcome against the static verdict (002 Theorems 1-6).
//
// Hosts come in three phases, smallest first, so the first failure found
// is a small one:
//  1. every map of the model on n darts, n growing, that contains L at the
//     identity (DPO rules: darts 0..|L|-1 are L's nodes) or, for schemes,
//     every map on n darts with every dart as hook; a failure found here
//     is minimal when every smaller n was enumerated completely;
//  2. the catalog's maps of the model and the maps given by the user;
//  3. random valid maps from recipes (1-3-G-maps, 2-3-O-maps), whose
//     recipe is shrunk greedily on failure while the failure persists.
// Everything is deterministic for a seed; only --time can cut a phase
// short, and the report says so.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "checkers/rule_conditions.hpp"
#include "checkers/violation.hpp"
#include "core/formatting.hpp"
#include "rewriting/application.hpp"
#include "rewriting/operation.hpp"
#include "rewriting/match.hpp"

namespace dartcheck::analysis {

/// How the static and dynamic verdicts combine.
enum class FuzzClass {
  consistent,     // static holds, no failure found
  confirmed,      // static fails, failure found
  unconfirmed,    // static fails, no failure found within the budget
  soundness_bug,  // static holds, failure found
};
std::string_view name_of(FuzzClass c);

/// One failing application.
struct Counterexample {
  Map host;
  std::vector<Dart> hooks;
  std::vector<std::pair<std::string, Dart>> match;  // L node -> dart (DPO rules)
  std::optional<Map> result;                        // H; empty when H has no dense form
  std::vector<Violation> violations;                // what H breaks
  std::string unrepresentable;                      // why H has no dense form, if so
  std::string origin;                               // which phase found it, and how it was shrunk
  bool minimal = false;                             // every smaller host of the exhaustive class was tried
  std::vector<std::string> broken() const;          // "I(1)", "C(0,2)", ... sorted, unique
  /// What H does wrong as a sentence's predicate: "breaks I(1), O(1)",
  /// "breaks C(0,2) and has no dense form (not-representable)",
  /// "contradicts the static event log (events)".
  std::string broken_predicate() const;
  /// The same with the broken constraints as the caller writes them (a
  /// picture's "I(2) at darts 0, 4; C(0,2) at dart 3"), empty if none.
  std::string broken_predicate(std::string_view constraints) const;
  /// Embedded rules: H's orbits with two values or unlabeled darts, and
  /// the extended rule's conflicts (003 Def. 6, 13), as sentences, and
  /// the embeddings they concern ("embedding(pos)").
  std::vector<std::string> embedding_failures;
  std::vector<std::string> broken_embeddings;
  /// Per dart of H (empty for topological counterexamples): the values of
  /// the darts of every orbit with two values or an unlabeled dart
  /// ("pos (1, 1)", "pos: none"), empty for the other darts.
  std::vector<std::string> orbit_values;
  /// A valid H whose event logs contradict the rule's static events
  /// (analysis/event_checks): one sentence each. Only in
  /// FuzzReport::event_contradiction.
  std::vector<std::string> event_contradictions;
  /// R node -> dart of H (every position of a scheme's node): the rule
  /// nodes H's darts come from, for its picture as the match is for G's.
  std::vector<std::pair<std::string, Dart>> comatch;
};

struct FuzzReport {
  std::string rule;
  std::vector<std::string> static_failures;
  FuzzClass verdict = FuzzClass::consistent;
  std::string reason;                           // why no failure was found (unconfirmed, or consistent but never applied)
  std::size_t applications = 0;                 // derivations that took place and were checked
  std::size_t hosts = 0;                        // host maps tried
  std::size_t largest_host = 0;                 // darts
  std::size_t exhaustive_darts = 0;             // every host of up to this many darts was tried (0: none completely)
  std::map<std::string, std::size_t> refusals;  // refusal name -> count (no-match, dangling, ...)
  std::size_t event_checks = 0;                 // applications whose event logs were cross-checked
  /// What each application checked: "topology" (a rule without embedding
  /// values), "topology and values" (the embedded fuzzer evaluated every
  /// term), or "topology; values not computed" (a rule whose expressions
  /// dartcheck does not all read): the text never calls a rule consistent
  /// on more than this.
  std::string checked = "topology";
  bool out_of_time = false;
  double seconds = 0;
  std::optional<Counterexample> counterexample;
  /// The first application whose event logs contradict the rule's static
  /// events (004): a defect of dartcheck's event analysis, not of the
  /// rule, so `verdict` does not change. The search for a counterexample
  /// goes on; event checks stop.
  std::optional<Counterexample> event_contradiction;
};

struct FuzzProgress {
  const std::string* rule;
  std::size_t applications, hosts;
  double seconds;
};

struct FuzzOptions {
  std::uint64_t seed = 1;
  std::size_t runs = 10'000;  // applications per rule; the search stops at this count
  std::optional<std::chrono::steady_clock::time_point> deadline;
  std::size_t max_darts = 128;            // largest random host
  std::size_t exhaustive_hosts = 20'000;  // phase 1 budget for the models with a random generator
  /// Applications per consistent rule whose event logs are cross-checked
  /// against its static events (004; 0: none). Each costs a traversal of
  /// both maps per orbit type, so only the first ones are checked.
  std::size_t event_checks = 2'000;
  /// The static verdict to set the dynamic one against; `check_rule` by
  /// default. Tests plant weakened checkers here.
  std::function<RuleVerdict(const Operation&)> static_check;
  std::function<void(const FuzzProgress&)> progress;  // called about every 4096 attempts
};

/// Fuzzes one rule; `seeds` are the given maps (any model: those of
/// another model are skipped).
FuzzReport fuzz_rule(const Operation& rule, const std::vector<Map>& seeds, const FuzzOptions& options);

/// Fuzzes each rule in turn. With `seconds`, the rules share that budget:
/// each gets an equal part of what is left (options.deadline is set per
/// rule). `progress` prints a progress line on stderr (a terminal's);
/// without it, a line per finished rule. After SIGINT/SIGTERM
/// (analysis/interrupt) it returns the reports of the rules it finished.
/// `finished(k, report)` is called as each rule finishes, so a caller can
/// stream its results (and write its files) before the run ends.
std::vector<FuzzReport> fuzz_rules(const std::vector<const Operation*>& rules, const std::vector<Map>& seeds, FuzzOptions options,
                                   std::optional<double> seconds, bool progress,
                                   const std::function<void(std::size_t, const FuzzReport&)>& finished = {});

/// The outcome in one line: "consistent (checked ...)", "confirmed: at
/// hook 3 of a 6-dart map, H breaks C(0,2) (minimal)", ...
std::string outcome_text(const FuzzReport& r);

/// "EVENT ANALYSIS CONTRADICTED: at hook 0 of a 2-dart map, <2>: ..."
/// (the first contradiction; empty when there is none).
std::string event_outcome_text(const FuzzReport& r);

/// One application on a copy of g (into `scratch`), checked with
/// check_map: the counterexample if H is invalid or has no dense form,
/// nullopt if H is valid or the rule does not apply (`refusal` says why;
/// not_representable comes with a counterexample). `applier` (an Applier
/// of entry, kept across calls so a scheme's tables are reused) applies it
/// when given, else a fresh one.
std::optional<Counterexample> apply_and_check(const Operation& entry, const Map& g, std::span<const Dart> hooks, Map& scratch, Refusal& refusal,
                                              Applier* applier = nullptr);

/// A stable per-rule random stream: the same rule gets the same hosts
/// whether it is fuzzed alone (--rule) or with its whole catalog.
std::uint64_t rule_seed(std::uint64_t seed, const std::string& name);

/// The static failures the default checker finds ("I(0)", "C(0,2)", ...).
std::vector<std::string> static_failures(const RuleVerdict& v);

}  // namespace dartcheck::analysis
