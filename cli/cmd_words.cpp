// dartcheck words: normal forms of a word under R_{N,E}, or the congruence
// of two words.
#include <fmt/format.h>

#include "cli/commands.hpp"
#include "core/conjugate_words.hpp"
#include "core/input_error.hpp"
#include "generators/word_separation.hpp"
#include "io/map_io.hpp"
#include "proofs/word_congruence.hpp"

namespace dartcheck::cli {

static ConjWord parse_arg(const std::string& text, const Model& model, const char* which) {
  try {
    return parse_conj_word(text, model);
  } catch (const std::invalid_argument& e) {
    throw InputError("<command line>", 0, 0, fmt::format("{}: {}", which, e.what()));
  }
}

int words(const WordsOptions& o) {
  const auto model = Model::by_name(o.model);
  if (!model) throw InputError("<command line>", 0, 0, fmt::format("unknown model '{}' (expected {})", o.model, Model::known_names()));
  ConjugateRewriting r(*model);
  const ConjWord w = parse_arg(o.word, *model, "WORD");
  if (!o.other) {
    const auto& nfs = r.normal_forms(w);
    fmt::print("{} in R_{{N,E}} of {}: {} normal form{}\n", w.str(), model->name, nfs.size(), nfs.size() == 1 ? "" : "s");
    for (const auto& nf : nfs) fmt::print("  {}\n", nf.str());
    fmt::print("reduces to ε: {}\n", r.reduces_to_empty(w) ? "yes" : "no");
    return ok;
  }
  const ConjWord w2 = parse_arg(*o.other, *model, "WORD2");
  const ConjWord probe = w + r.conjugate(w2);
  const bool congruent = r.congruent(w, w2);
  std::optional<proofs::WordSeparation> solver;
  if (o.prove_darts > 0) solver = proofs::separate_words(*model, w, w2, o.prove_darts, 200'000'000);
  auto solver_line = [&]() -> std::string {
    if (!solver) return "";
    switch (solver->answer) {
      case proofs::Answer::sat: {
        const Map& m = *solver->map;
        return fmt::format("\nZ3: a {} of {} darts separates them at dart 0 (ends {} and {}):\n{}", model->name, m.size(), follow(m, 0, w),
                           follow(m, 0, w2), map_to_yaml(m));
      }
      case proofs::Answer::unsat:
        return fmt::format("\nZ3: no {} of up to {} darts separates them", model->name, o.prove_darts);
      case proofs::Answer::unknown:
        return "\nZ3: unknown (rlimit reached)";
    }
    return "";
  };
  if (congruent) {
    fmt::print("{} <->* {}: congruent ({} ->* ε){}\n", w.str(), w2.str(), probe.str(), solver_line());
    // Lemma 3: congruent words end at the same dart on every valid map.
    return solver && solver->answer == proofs::Answer::sat ? soundness_bug : ok;
  }
  if (solver && solver->answer != proofs::Answer::unknown) {
    fmt::print("{} and {}: {} has no rewriting to ε in R_{{N,E}}{}\n", w.str(), w2.str(), probe.str(), solver_line());
    if (solver->answer == proofs::Answer::unsat) fmt::print("note: R_{{N,E}} does not prove them congruent, yet no bounded map separates them\n");
    return violation;
  }
  if (auto witness = separating_random_map(*model, w, w2)) {
    fmt::print("{} and {}: not congruent: {}{}\n", w.str(), w2.str(), *witness, solver_line());
    return violation;
  }
  fmt::print("{} and {}: not shown congruent ({} has no rewriting to ε, and no random map separates them){}\n", w.str(), w2.str(), probe.str(),
             solver_line());
  return violation;
}

}  // namespace dartcheck::cli
