#include "analysis/word_comparison.hpp"

#include "analysis/exit_status.hpp"
#include "generators/word_separation.hpp"

namespace dartcheck::analysis {

int WordComparison::status() const {
  if (congruent) return solver && solver->answer == proofs::Answer::sat ? exit_status::soundness_bug : exit_status::ok;
  return exit_status::violation;
}

WordComparison compare_words(const Model& model, const ConjWord& w, const ConjWord& w2, std::size_t prove_darts) {
  ConjugateRewriting r(model);
  WordComparison c{w, w2, w + r.conjugate(w2), r.congruent(w, w2), std::nullopt, prove_darts, std::nullopt};
  if (prove_darts > 0) c.solver = proofs::separate_words(model, w, w2, prove_darts, 200'000'000);
  if (!c.congruent && (!c.solver || c.solver->answer == proofs::Answer::unknown)) c.random_witness = separating_random_map(model, w, w2);
  return c;
}

}  // namespace dartcheck::analysis
