// dartcheck words: normal forms of a word under R_{N,E}, or the congruence
// of two words.
#include <fmt/format.h>

#include "cli/commands.hpp"
#include "core/conjugate_words.hpp"
#include "core/input_error.hpp"
#include "generators/random_maps.hpp"
#include "io/map_io.hpp"
#include "proofs/word_congruence.hpp"

#include <random>

namespace dartcheck::cli {

static ConjWord parse_arg(const std::string& text, const Model& model, const char* which) {
  try {
    return parse_conj_word(text, model);
  } catch (const std::invalid_argument& e) {
    throw InputError("<command line>", 0, 0, fmt::format("{}: {}", which, e.what()));
  }
}

// Lemma 3 read backwards: congruent words end at the same dart on every
// valid map, so two different endpoints prove the words are not congruent.
// Looks for such a map among seeded random maps of the model.
static std::optional<std::string> separating_map(const Model& model, const ConjWord& w, const ConjWord& w2) {
  const bool supported = (model.is_generalized() && model.dimension() <= 3 && model == Model::gmap(model.dimension())) ||
                         (model == Model::omap(2) || model == Model::omap(3));
  if (!supported) return std::nullopt;
  std::mt19937 rng(1);
  for (int attempt = 0; attempt < 200; ++attempt) {
    MapRecipe recipe;
    for (int f = 1 + attempt % 8; f > 0; --f) recipe.face_sizes.push_back(static_cast<std::uint8_t>(1 + rng() % 6));
    for (int s = static_cast<int>(rng() % 12); s > 0; --s)
      recipe.sewings.push_back({static_cast<std::uint8_t>(model.dims[rng() % model.dims.size()]), static_cast<std::uint32_t>(rng()),
                                static_cast<std::uint32_t>(rng()), static_cast<std::uint32_t>(rng())});
    const Map map = build_random_map(model, recipe);
    for (Dart d = 0; d < map.size(); ++d) {
      const Dart a = follow(map, d, w), b = follow(map, d, w2);
      if (a != b)
        return fmt::format("on a random {} of {} darts (seed 1, attempt {}) the paths from dart {} end at {} and {}", model.name, map.size(), attempt,
                           d, a, b);
    }
  }
  return std::nullopt;
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
  if (auto witness = separating_map(*model, w, w2)) {
    fmt::print("{} and {}: not congruent: {}{}\n", w.str(), w2.str(), *witness, solver_line());
    return violation;
  }
  fmt::print("{} and {}: not shown congruent ({} has no rewriting to ε, and no random map separates them){}\n", w.str(), w2.str(), probe.str(),
             solver_line());
  return violation;
}

}  // namespace dartcheck::cli
