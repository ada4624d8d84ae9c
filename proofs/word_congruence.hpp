// Bounded congruence of conjugate words (002 Sec. 9.2, Lemma 3): do the
// paths of two words from a dart end at the same dart on every map of the
// model up to k darts? A cross-check of R_{N,E}: words it calls congruent
// must never be separated, and a pair it cannot rewrite to each other but
// that no bounded map separates is worth reporting.
#pragma once

#include <optional>

#include "core/conjugate_words.hpp"
#include "core/map.hpp"
#include "proofs/solver_types.hpp"

namespace dartcheck::proofs {

struct WordSeparation {
  Answer answer = Answer::unknown;  // sat: `map` separates the words at dart 0
  std::optional<Map> map;
};

WordSeparation separate_words(const Model& model, const ConjWord& a, const ConjWord& b, std::size_t max_darts, unsigned rlimit);

}  // namespace dartcheck::proofs
