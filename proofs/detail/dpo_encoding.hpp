// The bit-vector encoding of a DPO derivation G =>(r,m) H on a symbolic
// host of up to k darts (proofs of 002 Theorems 1-3, bounded).
//
// By symmetry the match is the identity on darts 0..|L|-1, so only the
// host's links are unknown. H needs no variables of its own: a dart of H
// has one out-arc candidate from G (its link, deleted with m(L \ K)) plus
// the arcs R adds, so each constraint of H is a formula over the host's
// links. Only the images of R's nodes can break a constraint of H:
// elsewhere H is G (the proof, which also justifies checking both ijij and
// jiji cycles there, is in docs/prove.md).
#pragma once

#include "proofs/detail/host_encoding.hpp"

namespace dartcheck::proofs {

class DpoEncoding : public HostEncoding {
 public:
  DpoEncoding(z3::context& ctx, const Rule& rule, const HostClass& cls, std::size_t max_darts, unsigned rlimit, unsigned timeout_ms = 0,
              EncodingFault fault = EncodingFault::none);

 private:
  std::size_t h_index(NodeId r) const;  // R node -> index of its image in H
  void encode_match_and_dangling();
  void encode_derived();
  z3::expr violation(const HConstraint& c) override;
  z3::expr incident_violation(Dim d) override;

  const Rule& rule_;
  std::size_t nl_, added_;
  EncodingFault fault_;
  std::vector<Exprs> hlink_;          // per dimension, per H index: the unique out-arc when I(H) holds
  std::vector<std::size_t> r_nodes_;  // H indices of R's images
};

}  // namespace dartcheck::proofs
