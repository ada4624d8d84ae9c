// Operation inference (000): fold κ(G, H) from start darts of G, keep the
// well-formed schemes (Sec. 8.2: the static checker discards the others),
// deduplicate them (Sec. 10.3) and verify each on its example (App. A).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "checkers/rule_conditions.hpp"
#include "inference/folding.hpp"
#include "inference/inferred_rule.hpp"
#include "inference/kappa_graph.hpp"
#include "inference/verification.hpp"

namespace dartcheck::inference {

/// One start dart and what came of it.
struct Attempt {
  Dart start = 0;
  std::optional<FoldFailure> failure;  // the folding failed
  std::optional<GraphScheme> scheme;   // the folding succeeded
  std::string not_a_rule;              // the scheme is not a one-hook rule
  std::optional<InferredRule> rule;
  std::vector<std::string> ill_formed;       // failing conditions (Sec. 8.2), empty if well-formed
  std::optional<Verification> verification;  // App. A, for well-formed rules
  int duplicate_of = -1;                     // index of an earlier attempt with the same scheme
  /// The positions the example does not decide were freed (i -> _ with
  /// explicit loops) because keeping them gave a rule that does nothing.
  bool freed_undecided = false;
  /// The rule rewrites every match into itself (L = R): the example does
  /// not show the operation. Never counted as inferred.
  bool does_nothing = false;
  /// --generalize: the explicit loops dropped from preserved nodes
  /// ("n1 -1- n1"), or why the generalised rule was refused.
  std::vector<std::string> generalized;
  std::string not_generalized;
  /// Other <o>-orbits of G whose starts were not folded because this
  /// attempt's folding built them as nodes labelled as the hook: from them
  /// it is the same folding re-rooted (the same rule hooked elsewhere, or
  /// the same failure). One dart of each; found by infer, not by a lone
  /// --start.
  std::vector<Dart> same_starts;
  /// The scheme and rule of this start were dropped (InferOptions::
  /// keep_rejected false): the outcome says why it gives no rule.
  bool details_dropped = false;
  double seconds = 0;
  bool inferred() const { return rule && ill_formed.empty() && duplicate_of < 0 && verification && verification->holds && !does_nothing; }
};

struct InferOptions {
  FoldOptions fold;
  std::optional<Dart> start;  // only this dart
  bool all = false;           // every dart not already in an attempt's hook orbit
  std::string name = "inferred";
  bool verify = true;
  /// Drop an explicit i-loop that a preserved node has on both sides: the
  /// example's free i-link becomes "whatever it is, kept" (Jerboa's rules
  /// do not mention it), so the rule matches sewn hosts too. Kept only if
  /// the static checker finds the result consistent and it still gives the
  /// example back. Not the paper's behaviour (000 folds loops as arcs).
  bool generalize = false;
  /// Keep the scheme and rule of starts that give no rule. `infer --all`
  /// on a large example drops them: each can be as large as the example.
  bool keep_rejected = true;
};

/// The attempts, in order. Without `start` or `all`, darts of G are tried
/// in increasing order, skipping those in the hook orbit of an earlier
/// attempt (the paper's pool of unseen darts) and, outside strict mode,
/// those in a node that an earlier folding labelled as the hook (see
/// FoldResult::hook_like), until one gives a well-formed rule. Each
/// folding costs what it builds, and a folding stops at a node an earlier
/// failed one built, so `all` is linear in |G| + |H| when foldings fail
/// early or cover G with hook-labelled nodes. Rule k (k > 0) is named
/// `name`-k.
std::vector<Attempt> infer(const KappaGraph& graph, const std::vector<Dim>& orbit, const InferOptions& options);

/// Parses "<0,1,2>" as an inference orbit type: distinct dimensions of the
/// model, no '_'. Throws ValueError.
std::vector<Dim> parse_inference_orbit(const std::string& text, const Model& model);

}  // namespace dartcheck::inference
