// dartcheck words: normal forms of a word under R_{N,E}, or the congruence
// of two words.
#include <fmt/format.h>

#include "core/error.hpp"
#include "cli/commands.hpp"
#include "core/conjugate_words.hpp"
#include "core/input_error.hpp"
#include "reports/words_text.hpp"

namespace dartcheck::cli {

static ConjWord parse_arg(const std::string& text, const Model& model, const char* which) {
  try {
    return parse_conj_word(text, model);
  } catch (const ValueError& e) {
    throw UsageError(fmt::format("{}: {}", which, e.what()));
  }
}

int words(const WordsOptions& o) {
  const auto model = Model::by_name(o.model);
  if (!model) throw UsageError(fmt::format("unknown model '{}' (expected {})", o.model, Model::known_names()));
  const ConjWord w = parse_arg(o.word, *model, "WORD");
  if (!o.other) {
    fmt::print("{}", reports::normal_forms_text(*model, w));
    return ok;
  }
  const auto comparison = analysis::compare_words(*model, w, parse_arg(*o.other, *model, "WORD2"), o.prove_darts);
  fmt::print("{}", reports::word_comparison_text(*model, comparison));
  return comparison.status();
}

}  // namespace dartcheck::cli
