// `dartcheck prove` for one rule: for every constraint of the model, ask
// the solver for a host whose derived graph H breaks it, once over the
// hosts of the theorem that speaks of the constraint (to cross-check the
// theorem's "iff" against the static checker) and once over the valid
// maps of the model (the user's question). Every counterexample is
// replayed through the library's own graph derivation before it is
// believed.
#pragma once

#include <functional>

#include <optional>
#include <string>
#include <vector>

#include "core/formatting.hpp"
#include "rewriting/operation.hpp"
#include "core/graph.hpp"
#include "proofs/embedding_prover.hpp"
#include "proofs/host_class.hpp"
#include "proofs/solver_types.hpp"

namespace dartcheck::proofs {

struct ProveOptions {
  std::size_t max_darts = 12;
  /// Schemes: hosts of up to min(max_darts, scheme_darts) darts (H has
  /// that many darts per node of R, so queries grow faster).
  std::size_t scheme_darts = 6;
  /// Z3 resource units per query (deterministic, unlike seconds).
  unsigned rlimit = 200'000'000;
  /// Wall-clock cap per query in milliseconds (0: none); answers then
  /// depend on the machine.
  unsigned timeout_ms = 0;
  bool minimize = true;
  EncodingFault fault = EncodingFault::none;
  /// Polled every 20 ms while the solver runs: when it returns true, Z3 is
  /// interrupted (its context's interrupt), the running query and the
  /// rule's remaining ones end "unknown" with why "interrupted" (Ctrl-C
  /// must not wait for a query that may run for minutes).
  std::function<bool()> stop;
  /// Embeddings and potential events: hosts of up to this many darts for
  /// rules with terms; 0 gives |L| + 4 (the host budget bounds the work).
  std::size_t embedding_darts = 0;
  bool embeddings = true;
};

enum class Status {
  counterexample,  // a host whose H breaks the constraint
  none,            // no such host up to `darts` darts
  unknown,         // the solver ran out of resources
  vacuous,         // no host of the class admits a derivation (up to `darts`)
};
std::string_view name_of(Status s);

struct ClassAnswer {
  std::string class_name;
  Status status = Status::unknown;
  std::size_t darts = 0;  // the counterexample's size, or the largest size searched
  bool minimal = false;   // no counterexample on fewer darts
  /// A small-model bound (docs/prove.md): a counterexample exists iff one
  /// exists on at most `bound` darts. 0 when none is known.
  std::size_t bound = 0;
  std::vector<std::string> core;  // unsat core: the assumptions that sufficed
  std::string why;                // for vacuous and unknown answers
  std::optional<SymbolicHost> host;
  TopoGraph host_graph, result_graph;  // the counterexample as D-graphs
  bool replayed = false;               // the library's derivation on host_graph breaks the constraint too
  std::string replay_failure;
  double seconds = 0;
  bool proved_for_all() const { return status == Status::none && bound > 0 && darts >= bound; }
};

enum class Agreement {
  agree,
  disagree,      // contradicts a theorem's "iff", or a replay failed: exit 3
  unresolved,    // static fails, no counterexample up to k below the bound
  not_compared,  // the theorem's premise fails, the class is vacuous, or unknown
};
std::string_view name_of(Agreement a);

struct ConstraintProof {
  HConstraint constraint;
  std::optional<bool> static_holds;    // the static condition of the same name
  std::optional<ClassAnswer> theorem;  // none for no-loop: no theorem covers it
  ClassAnswer model;
  Agreement agreement = Agreement::not_compared;
  std::string note;
};

struct RuleProof {
  std::string rule;
  std::string model;
  bool scheme = false;       // a rule scheme: maps of the model only (no theorem class)
  std::string out_of_scope;  // why the solver does not encode this rule
  std::vector<std::string> static_failures;
  std::vector<ConstraintProof> constraints;
  bool interrupted = false;  // ProveOptions::stop fired: constraints may be missing, answers "interrupted"
  double seconds = 0;
  /// The embedding answers of a rule with terms (each judged against the
  /// static conditions of its embedding: EmbeddingAnswer::disagree).
  std::optional<EmbeddingProof> embedding;
  std::size_t count(Agreement a) const;
  /// Embedding answers that contradict Theorem 2/4 or do not replay.
  std::size_t embedding_disagreements() const;
};

RuleProof prove_rule(const Operation& entry, const ProveOptions& options);

/// Why the solver does not encode this rule scheme ("" if it does: one
/// hook node with loops, the form of every operation of 002 Sec. 10).
std::string scheme_out_of_scope(const Rule& core);

/// The host of a solver answer as a D-graph of the class: the encoded links
/// plus, on the other dimensions, L's arcs (Theorem 1) or L's arcs
/// completed to permutations (D-combinatorial classes).
TopoGraph host_graph(const Rule& rule, const HostClass& cls, const SymbolicHost& h);
/// The host as a dense map of the rule's model (model class only).
Map host_map(const Model& model, const SymbolicHost& h);

}  // namespace dartcheck::proofs
