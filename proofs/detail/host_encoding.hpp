// The symbolic host shared by the solver's encodings (002 Theorems 1-6,
// bounded): a host graph of up to k darts on the dimensions a HostClass
// encodes, with that class's constraints.
//
// Every quantifier over darts is grounded: the host is one bit-vector link
// per dart and encoded dimension (NONE for "no arc"), darts at or past the
// symbolic `size` are absent, and composed links are ite look-ups. One
// query on k darts thus covers every host of 1..k darts. A derived class
// adds the match, the derivation and the violations of H; this class runs
// the queries (one assumption literal per constraint family, an rlimit per
// check) and decodes the answers.
#pragma once

#include <z3++.h>

#include <cstddef>
#include <string>
#include <vector>

#include "core/conjugate_words.hpp"
#include "core/map.hpp"
#include "proofs/host_class.hpp"
#include "proofs/solver_types.hpp"

namespace dartcheck::proofs {

class HostEncoding {
 public:
  virtual ~HostEncoding() = default;
  HostEncoding(const HostEncoding&) = delete;
  HostEncoding& operator=(const HostEncoding&) = delete;

  /// Some host of the class on at most max_darts darts admits the match
  /// and the derivation.
  Answer derivable();
  /// Some such host yields an H that breaks `c` (for O and C: among the H
  /// that satisfy I on the dimensions c reads, as Theorems 2-3 and 5-6
  /// assume). On unsat, `core` receives the names of the assumptions that
  /// sufficed.
  Answer breaks(const HConstraint& c, std::vector<std::string>* core = nullptr);
  /// Words (002 Sec. 9.2): is there a host on which the paths of `a` and
  /// `b` from dart 0 end at different darts (or one of them breaks off)?
  /// Conjugate letters follow arcs backwards. Unsat means a and b are
  /// congruent on every host of the class up to max_darts darts.
  Answer separates(const ConjWord& a, const ConjWord& b);
  /// After sat: looks for the same answer on fewer darts, as long as the
  /// solver answers; true if the last size is proved minimal.
  bool minimize();
  /// The host of the last sat answer.
  const SymbolicHost& host() const { return host_; }

 protected:
  using Exprs = std::vector<z3::expr>;
  /// Darts 0..min_darts-1 are always present (the match's image); indices
  /// up to `index_bound` (exclusive) name darts of H, and index_bound
  /// itself is NONE. `rlimit` bounds each check by Z3's deterministic
  /// resource counter; `ctx` may serve several encodings (creating a
  /// context costs more than a small query) and must outlive this object.
  HostEncoding(z3::context& ctx, const Model& model, const HostClass& cls, std::size_t max_darts, std::size_t min_darts, std::size_t index_bound,
               unsigned rlimit, unsigned timeout_ms);

  /// The disjunction of the places where H breaks c.
  virtual z3::expr violation(const HConstraint& c) = 0;
  /// H breaks I(d) (the premise "holds I(d)" of O and C queries).
  virtual z3::expr incident_violation(Dim d) = 0;

  z3::expr val(std::size_t v) { return ctx_.bv_val(static_cast<std::uint64_t>(v), width_); }
  z3::expr none() { return val(none_); }
  /// Host dart x is present (below the symbolic size).
  z3::expr active(std::size_t x);
  /// table[index], NONE past the table (so NONE maps to NONE).
  z3::expr lookup(const Exprs& table, const z3::expr& index);
  /// The end of the w-path from `from` in the host, NONE if it breaks off.
  z3::expr follow(z3::expr from, const ConjWord& w);
  const Exprs& links(Dim d) const { return link_[static_cast<std::size_t>(d)]; }

  z3::context& ctx_;
  Model model_;
  HostClass cls_;
  std::size_t k_, min_darts_;
  z3::solver solver_;
  unsigned width_ = 0;
  std::size_t none_ = 0;
  z3::expr size_;

 private:
  void encode_host();
  Answer run(const Exprs& assumptions, std::vector<std::string>* core);
  void decode(const z3::model& m);

  std::vector<Exprs> link_;  // per dimension, per host dart
  SymbolicHost host_;
  Exprs last_;  // the assumptions of the last query, for minimize()
};

/// The nodes R adds (its nodes with no L node of the same name).
std::size_t added_nodes(const Rule& rule);

/// Sums of 0/1 terms plus `fixed` known-true terms equal to `constant`, as
/// a pseudo-Boolean constraint (the counts here are a few arcs).
z3::expr count_is(z3::context& ctx, const std::vector<z3::expr>& terms, std::size_t constant, std::size_t fixed);

}  // namespace dartcheck::proofs
