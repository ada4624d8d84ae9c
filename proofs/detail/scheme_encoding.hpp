// The bit-vector encoding of a rule scheme's application (002 Sec. 6.3)
// on a symbolic host of up to k darts, for schemes whose left-hand side is
// one hook node with loops (the form of every operation of 002 Sec. 10).
//
// The hook is dart 0. The pattern graph P_v (Def. 20) is the prefix
// 0..np-1 of the darts, np symbolic: closed under the scheme's words and
// their conjugates, and numbered so that every pattern dart but 0 is the
// end of an L-word path from an earlier one (a BFS order, so the prefix is
// exactly the darts reachable from the hook, and ι(L, P_v) is connected as
// application requires). Every host has such a numbering, so this breaks
// symmetry without losing hosts. The match sends (p, hook) to dart p.
//
// H's darts are the host's (without the pattern if the hook is deleted)
// plus one block of k indices per added node y of R, (p, y) at
// k·block(y) + p, present for p < np. Each arc x -(w,i)-> y of R \ K gives
// one candidate i-arc per pattern position p, to (p·w, y), where p·w is a
// composed look-up in the host. The constraints of H are then read off
// these candidates, not derived by the theorems' reasoning, so the answer
// is independent evidence for Theorems 4-6: I and O at the images of R's
// nodes (the touched darts: the locality argument of docs/prove.md
// carries over, since L \ K's instances join pattern darts and R \ K's
// join touched ones), C's ijij-path at every present dart.
#pragma once

#include "rewriting/rule.hpp"
#include "proofs/detail/host_encoding.hpp"
#include "proofs/rule_prover.hpp"

namespace dartcheck::proofs {

class SchemeEncoding : public HostEncoding {
 public:
  /// `cls` must encode every dimension of the model (pattern paths read
  /// them all).
  SchemeEncoding(z3::context& ctx, const Rule& core, const ArcWords& words, const HostClass& cls, std::size_t max_darts, unsigned rlimit,
                 unsigned timeout_ms = 0);

 private:
  struct Candidate {
    std::size_t source;  // H index
    z3::expr present;
    z3::expr target;    // H index
    std::size_t block;  // the block the target lies in
  };
  z3::expr in_pattern(std::size_t x) { return z3::ult(val(x), np_); }
  z3::expr shift(std::size_t x, const ConjWord& w);         // the host dart p·w for pattern dart x
  z3::expr index(std::size_t block, const z3::expr& dart);  // the H index of (dart, node of that block)
  z3::expr present_at(const z3::expr& index);
  void encode_pattern_and_match();
  void encode_derived();
  z3::expr violation(const HConstraint& c) override;
  z3::expr incident_violation(Dim d) override;

  const Rule& core_;
  ArcWords words_;
  bool hook_kept_;
  std::vector<std::size_t> block_;  // per R node: 0 for the hook, 1.. for added nodes
  std::size_t blocks_;
  z3::expr np_;
  std::vector<ConjWord> gens_;
  std::vector<Exprs> shift_;                  // per generator, per host dart
  std::vector<std::vector<Candidate>> arcs_;  // per dimension
  Exprs present_;                             // per H index
  std::vector<std::size_t> touched_;          // H indices of the images of R's nodes
  std::vector<Exprs> hlink_;                  // per dimension, per H index: the first present candidate
  /// Per dimension, per H index: the blocks hlink's value may lie in (bit
  /// b), so that look-ups into H read k entries per block, not all.
  std::vector<std::vector<std::uint32_t>> hblocks_;
  /// h[t] for t in `blocks`; `blocks` becomes the blocks of the result.
  z3::expr hlookup(Dim d, const z3::expr& t, std::uint32_t& blocks);
};

}  // namespace dartcheck::proofs
