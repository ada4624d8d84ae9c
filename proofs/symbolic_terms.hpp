// Embedding terms (003 Def. 9-10) evaluated on a host whose topology is
// known and whose values are not: each pi-orbit of the host G is one
// unknown, and a term becomes an expression over those unknowns (a
// SymExpr), shared by structure. The embedding prover (proofs/
// embedding_prover) hands the expressions to Z3 in two readings.
//
// The semantics are 003's, written again from the definitions and not
// through rewriting/term_eval, so that a disagreement between the two is
// seen (every solver counterexample is replayed by the evaluator): a node
// variable is the dart its L node matched in the copy; `x.alpha_i` the
// i-neighbour; `x.pi` the unknown of x's pi-orbit; `pi<o'>(x)` one
// element per (<o> ∩ <o'>)-orbit of the <o'>-orbit of x (G is consistent,
// so that element is the unknown of the pi-orbit containing it);
// `each(d in <o>(y): t)` t per dart, or per sub-orbit when t is one
// expression on all of its darts; lists concatenate.
#pragma once

#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

#include "core/error.hpp"
#include "core/map.hpp"
#include "rewriting/term.hpp"
#include "rewriting/term_functions.hpp"

namespace dartcheck::proofs {

/// One node of an expression, interned: equal structures have one index.
struct SymExpr {
  enum class Kind : std::uint8_t { unknown, literal, call };
  Kind kind = Kind::literal;
  ValueType type = ValueType::real;
  std::uint32_t unknown = 0;  // unknown: its number in the pool
  Value literal;              // literal
  const Function* function = nullptr;
  /// call: one entry per parameter; a multiset parameter is the elements
  /// of `bags[k]`, sorted by index (a canonical order of the multiset).
  std::vector<std::uint32_t> args;
  std::vector<std::vector<std::uint32_t>> bags;
  std::vector<bool> is_bag;
};

/// What an unknown stands for: the value of an embedding on one orbit of G.
struct Unknown {
  std::string embedding;
  ValueType type = ValueType::real;
  Dart dart = no_dart;  // the smallest dart of the orbit in G
};

/// Expressions and unknowns of one host. Unknowns are numbered in the
/// order they are first met, so hosts that differ by a renaming of darts
/// read in the same order give the same text (the prover's cache key).
class SymPool {
 public:
  std::uint32_t unknown(const std::string& embedding, ValueType type, std::uint32_t orbit, Dart first);
  std::uint32_t literal(const Value& v);
  std::uint32_t call(const Function* f, std::vector<std::uint32_t> args, std::vector<std::vector<std::uint32_t>> bags, std::vector<bool> is_bag);
  const SymExpr& at(std::uint32_t k) const { return nodes_[k]; }
  std::size_t size() const { return nodes_.size(); }
  const std::vector<Unknown>& unknowns() const { return unknowns_; }
  /// The expression as text: `u3`, `(0.5, 1)`, `center{u1, u2}`.
  std::string str(std::uint32_t k) const;

 private:
  std::uint32_t intern(SymExpr e, const std::string& key);
  std::vector<SymExpr> nodes_;
  std::vector<std::string> keys_;
  std::unordered_map<std::string, std::uint32_t> by_key_;
  std::map<std::pair<std::string, std::uint32_t>, std::uint32_t> unknown_of_;  // (embedding, orbit of G) -> unknown
  std::vector<Unknown> unknowns_;
};

/// A term the host cannot evaluate whatever its values (a missing
/// neighbour, an empty center): the library refuses that application.
class NoValue : public Error {
  using Error::Error;
};
/// A term this encoding does not cover (an each body that differs inside
/// a sub-orbit: whether it has a value depends on the values).
class NotEncoded : public Error {
  using Error::Error;
};

/// The host's topology and its orbits per embedding.
class SymbolicEvaluator {
 public:
  SymbolicEvaluator(const Map& g, const std::vector<EmbeddingSignature>& embeddings, SymPool& pool);
  /// The unknown of pi's orbit at dart d.
  std::uint32_t value_at(const std::string& embedding, Dart d);
  /// The orbit of pi containing d (its number in G's partition).
  std::uint32_t orbit_of(const std::string& embedding, Dart d) const;
  /// A value-sorted term with its node variables bound to `darts`
  /// (names[k] to darts[k]). Throws NoValue or NotEncoded.
  std::uint32_t value(const Term& t, const std::vector<std::string>& names, const std::vector<Dart>& darts);

 private:
  struct Result {
    bool is_dart = false, is_bag = false;
    Dart dart = no_dart;
    std::uint32_t value = 0;
    std::vector<std::uint32_t> bag;
  };
  Result eval(const Term& t);
  Result eval_each(const Term& t);  // each(x in <o>(y): t), per dart or per sub-orbit
  Result eval_call(const Term& t);  // a function of the pool on the arguments' expressions
  const EmbeddingSignature& signature(const std::string& embedding) const;

  const Map& g_;
  const std::vector<EmbeddingSignature>& embeddings_;
  SymPool& pool_;
  std::vector<std::vector<std::uint32_t>> orbit_;    // per embedding: orbit of each dart
  std::vector<std::vector<Dart>> first_;             // per embedding: smallest dart of each orbit
  std::vector<std::pair<std::string, Dart>> scope_;  // bound names, innermost last
};

}  // namespace dartcheck::proofs
