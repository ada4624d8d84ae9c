// The solver on embeddings (003 Theorems 2 and 4 are sufficient, not
// necessary): is there a host of up to K darts with a consistent
// embedding (one value per orbit) on which applying the rule leaves an
// orbit of H with two values or a dart without one?
//
// Hosts: every map of the rule's model up to K darts that contains the
// match (L's nodes as darts 0..|L|-1 for a DPO rule; the hook at dart 0
// for a scheme), connected to it; the topology is enumerated and applied
// by the library (rewriting/application), since the terms read orbits of
// any size. Values: one unknown per orbit of G, L's terms as constraints
// (the labeled match), R's terms evaluated symbolically (proofs/
// symbolic_terms), H's values by 003 Def. 12-13 from the definitions, and
// Z3 asked for unknowns that make an orbit of H inconsistent. Queries are
// cached by their text: hosts equal up to renaming ask once.
//
// Two readings (docs/prove.md, "Embeddings"):
//  - uninterpreted: every function is an uninterpreted symbol (multisets
//    in a canonical order); `none` holds for every interpretation of the
//    operations, which is what the syntactic conditions approximate;
//  - arithmetic: dartcheck's algebra in real arithmetic (sums, scalings,
//    differences, averages of multisets whose sizes the host fixes);
//    functions outside it (length) stay uninterpreted and are listed.
// A counterexample in the arithmetic reading is replayed by the library
// (the Applier on an embedded map + check_embedding) with the model's values as doubles.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/formatting.hpp"
#include "rewriting/embedded_map.hpp"
#include "rewriting/operation.hpp"

namespace dartcheck::proofs {

enum class Reading : std::uint8_t { uninterpreted, arithmetic };
std::string_view name_of(Reading r);

struct EmbeddingProveOptions {
  std::size_t max_darts = 6;            // K
  unsigned rlimit = 20'000'000;         // Z3 resource units per query
  std::size_t host_budget = 2'000'000;  // maps enumerated per rule, at most
  std::function<bool()> stop;           // polled between queries (Ctrl-C)
  /// Tests only, planted encoding faults: `fresh_writes` reads every value
  /// R writes as a fresh unknown (counterexamples that do not replay);
  /// `no_breaks` never asks Z3 (`none` where fuzz breaks the embedding).
  enum class Fault : std::uint8_t { none, fresh_writes, no_breaks } fault = Fault::none;
};

struct EmbeddingAnswer {
  std::string embedding;                     // pi
  std::vector<std::string> static_failures;  // A(pi), C(pi), ... that fail
  Reading reading = Reading::uninterpreted;
  enum class Status : std::uint8_t { counterexample, none, unknown } status = Status::none;
  std::size_t darts = 0;                   // the counterexample's host size, or K searched
  std::string why;                         // unknown: the limit; counterexample: what breaks
  std::vector<std::string> uninterpreted;  // arithmetic reading: functions left uninterpreted
  std::vector<std::string> functions;      // the functions the embedding's terms call
  // A counterexample: the host with its values (arithmetic), the hooks,
  // and whether the library's application breaks the same embedding.
  std::optional<EmbeddedMap> host;
  std::vector<Dart> hooks;
  bool replayed = false;
  std::string replay;  // what the library's application said
  /// A counterexample where the embedding's static conditions hold
  /// (Theorems 2 and 4 forbid it), or one that does not replay: a bug.
  bool disagree = false;
  std::string note;  // "false alarm up to K darts", or why it disagrees
  std::string condition() const { return "embedding(" + embedding + ")"; }
};
std::string_view name_of(EmbeddingAnswer::Status s);

struct EmbeddingProof {
  std::vector<EmbeddingAnswer> answers;  // per embedding R labels, uninterpreted then arithmetic
  std::size_t hosts = 0, applications = 0, queries = 0, cached = 0;
  double z3_seconds = 0;     // inside Z3's checks
  std::string out_of_scope;  // why the rule is not encoded (no terms, ...)
  bool interrupted = false;
  double seconds = 0;
};

EmbeddingProof prove_embeddings(const Operation& op, const EmbeddingProveOptions& options);

/// K for a rule: `asked` when set (prove --embedding-darts), else |L| + 4
/// (the bound; the host budget bounds the work).
inline std::size_t embedding_host_darts(const Rule& rule, std::size_t asked) { return asked > 0 ? asked : rule.left().node_count() + 4; }

}  // namespace dartcheck::proofs
