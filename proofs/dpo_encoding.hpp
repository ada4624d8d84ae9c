// The bit-vector encoding of a DPO derivation G =>(r,m) H on a symbolic
// host of up to k darts (proofs of 002 Theorems 1-3, bounded).
//
// Every quantifier over darts is grounded: the host is one bit-vector link
// per dart and encoded dimension (NONE for "no arc"), darts at or past the
// symbolic `size` are absent, and composed links are ite look-ups. One
// query on k darts thus covers every host of 1..k darts. By symmetry the
// match is the identity on darts 0..|L|-1, so only the links are unknown.
//
// H needs no variables of its own: a dart of H has one out-arc candidate
// from G (its link, deleted with m(L \ K)) plus the arcs R adds, so each
// constraint of H is a formula over the host's links. Only the images of
// R's nodes can break a constraint of H: elsewhere H is G (the proof,
// which also justifies checking both ijij and jiji cycles there, is in
// docs/prove.md).
#pragma once

#include <z3++.h>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "core/conjugate_words.hpp"
#include "core/map.hpp"
#include "proofs/host_class.hpp"

namespace dartcheck::proofs {

/// A host the solver found: `size` darts and the links of the encoded
/// dimensions (no_dart for none).
struct SymbolicHost {
  std::size_t size = 0;
  std::vector<std::pair<Dim, std::vector<Dart>>> links;
  const std::vector<Dart>* find(Dim d) const;
};

/// Deliberate faults, for the tests that check that a wrong encoding is
/// caught (a planted bug must produce disagreements).
enum class EncodingFault { none, drop_dangling };

enum class Answer { sat, unsat, unknown };

class DpoEncoding {
 public:
  /// `rlimit` bounds each check by Z3's deterministic resource counter.
  /// `ctx` may serve several encodings (creating a context costs more than
  /// a small query); it must outlive this object.
  DpoEncoding(z3::context& ctx, const Rule& rule, const HostClass& cls, std::size_t max_darts, unsigned rlimit, unsigned timeout_ms = 0,
              EncodingFault fault = EncodingFault::none);

  /// Some host of the class on at most max_darts darts admits the match
  /// and the derivation.
  Answer derivable();
  /// Some such host yields an H that breaks `c` (for O and C: among the H
  /// that satisfy I on the dimensions c reads, as Theorems 2-3 assume). On
  /// unsat, `core` receives the names of the assumptions that sufficed.
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

 private:
  using Exprs = std::vector<z3::expr>;
  z3::expr val(std::size_t v) { return ctx_.bv_val(static_cast<std::uint64_t>(v), width_); }
  z3::expr none() { return val(none_); }
  z3::expr active(std::size_t x);
  z3::expr lookup(const Exprs& table, const z3::expr& index);
  std::size_t h_index(NodeId r) const;  // R node -> index of its image in H
  void encode_host();
  void encode_match_and_dangling();
  void encode_derived();
  z3::expr violation(const HConstraint& c);
  z3::expr incident_violation(Dim d);
  z3::expr follow(z3::expr from, const ConjWord& w);
  Answer run(const Exprs& assumptions, std::vector<std::string>* core);
  void decode(const z3::model& m);
  const Exprs& links(Dim d) const { return link_[static_cast<std::size_t>(d)]; }

  z3::context& ctx_;
  const Rule& rule_;
  HostClass cls_;
  std::size_t k_, nl_, added_;
  unsigned rlimit_;
  EncodingFault fault_;
  z3::solver solver_;
  unsigned width_ = 0;
  std::size_t none_ = 0;
  z3::expr size_;
  std::vector<Exprs> link_;    // per dimension, per host dart
  std::vector<Exprs> hlink_;   // per dimension, per H index: the unique out-arc when I(H) holds
  std::vector<std::size_t> r_nodes_;  // H indices of R's images
  SymbolicHost host_;
  Exprs last_;  // the assumptions of the last query, for minimize()
};

}  // namespace dartcheck::proofs
