// Symbolic embedding values (proofs/symbolic_terms) as Z3 expressions, in
// one of two readings (proofs/embedding_prover.hpp):
//  - uninterpreted: a value is an integer (an element of a domain with an
//    order, used only to sort multisets into a canonical order, so that a
//    function of a multiset sees the same arguments for equal multisets),
//    a literal a distinct constant, a function an uninterpreted symbol;
//  - arithmetic: a value is its coordinates (three reals for points,
//    vectors and colors, one real, integer or Boolean otherwise) and the
//    built-in algebra is real arithmetic; what it does not cover (length,
//    integer division, a modeler's own function) stays uninterpreted and
//    is listed in `uninterpreted()`.
// Divisions by a value that may be zero add the premise that it is not
// (`premises()`): the library refuses a zero-weight barycenter; for the
// other divisions the premise excludes hosts the reals cannot describe
// (the double gives an infinity), and is listed too.
#pragma once

#include <set>
#include <string>
#include <vector>

#include <z3++.h>

#include "proofs/embedding_prover.hpp"
#include "proofs/symbolic_terms.hpp"

namespace dartcheck::proofs {

class ValueEncoding {
 public:
  ValueEncoding(z3::context& ctx, const SymPool& pool, Reading reading);
  /// The coordinates of expression k (one entry in the uninterpreted reading).
  const z3::expr_vector& encode(std::uint32_t k);
  /// Whether expressions a and b have equal values.
  z3::expr equal(std::uint32_t a, std::uint32_t b);
  /// Conditions every encoded division needs (see above).
  const z3::expr_vector& premises() const { return premises_; }
  /// Functions the arithmetic reading left uninterpreted, and why.
  const std::set<std::string>& uninterpreted() const { return uninterpreted_; }
  /// The value of unknown u in a model (arithmetic reading).
  Value decode(const z3::model& m, std::uint32_t unknown);
  /// The unknowns' real coordinates restricted to small integers, to ask
  /// for values that doubles hold exactly (the caller pushes and pops).
  z3::expr_vector small_integers(std::int64_t bound);

 private:
  z3::expr_vector unknown(const SymExpr& e);
  z3::expr_vector literal(const Value& v);
  z3::expr_vector call(const SymExpr& e);
  z3::expr_vector arithmetic(const SymExpr& e, bool& done);
  z3::expr_vector opaque(const SymExpr& e);
  z3::sort component_sort(ValueType t);
  int width(ValueType t) const;

  z3::context& ctx_;
  const SymPool& pool_;
  Reading reading_;
  std::vector<std::optional<z3::expr_vector>> memo_;
  std::vector<std::optional<z3::expr_vector>> unknowns_;
  std::vector<std::string> literals_;  // uninterpreted: literal keys, index = constant
  z3::expr_vector premises_;
  std::set<std::string> uninterpreted_;
};

}  // namespace dartcheck::proofs
