// The text of `dartcheck words`: a word's normal forms, or the comparison
// of two words with each opinion's evidence.
#pragma once

#include <string>

#include "analysis/word_comparison.hpp"

namespace dartcheck::reports {

/// The normal forms of `w` in R_{N,E} of `model`, and whether it reduces to ε.
std::string normal_forms_text(const Model& model, const ConjWord& w);

std::string word_comparison_text(const Model& model, const analysis::WordComparison& c);

}  // namespace dartcheck::reports
