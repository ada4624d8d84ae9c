// `dartcheck words W W2`: whether two words are congruent in R_{N,E}
// (002 Sec. 9.2), with the evidence each opinion gives: the rewriting of
// W·conj(W2) to ε, a bounded map from Z3 on which the paths differ, or a
// random map that separates them (Lemma 3 read backwards).
#pragma once

#include <optional>
#include <string>

#include "core/conjugate_words.hpp"
#include "proofs/word_congruence.hpp"

namespace dartcheck::analysis {

struct WordComparison {
  ConjWord w, w2, probe;                         // probe = w·conj(w2)
  bool congruent = false;                        // probe ->* ε in R_{N,E}
  std::optional<proofs::WordSeparation> solver;  // asked when prove_darts > 0
  std::size_t prove_darts = 0;
  /// A random map separating the words; searched only when neither the
  /// rewriting nor the solver decided.
  std::optional<std::string> random_witness;
  /// 0 congruent, 1 not shown congruent, 3 Z3 separates words R_{N,E}
  /// calls congruent (Lemma 3: congruent words end at the same dart on
  /// every valid map, so that is a defect).
  int status() const;
};

WordComparison compare_words(const Model& model, const ConjWord& w, const ConjWord& w2, std::size_t prove_darts);

}  // namespace dartcheck::analysis
