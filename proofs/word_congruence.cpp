#include "proofs/word_congruence.hpp"

#include "proofs/rule_prover.hpp"
#include "proofs/detail/dpo_encoding.hpp"

namespace dartcheck::proofs {

WordSeparation separate_words(const Model& model, const ConjWord& a, const ConjWord& b, std::size_t max_darts, unsigned rlimit) {
  // The identity rule on one node: its hosts are the maps of the model
  // holding dart 0, and it rewrites nothing.
  TopoGraph one;
  one.add_node("x");
  const Rule identity("identity", model, one, one, {"x"});
  z3::context ctx;
  DpoEncoding enc(ctx, identity, model_class(model), max_darts, rlimit);
  WordSeparation out;
  out.answer = enc.separates(a, b);
  if (out.answer == Answer::sat) {
    enc.minimize();
    out.map = host_map(model, enc.host());
  }
  return out;
}

}  // namespace dartcheck::proofs
