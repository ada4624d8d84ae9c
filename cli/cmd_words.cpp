// dartcheck words: normal forms of a word under R_{N,E}, or the congruence
// of two words.
#include <fmt/format.h>

#include "cli/commands.hpp"
#include "core/conjugate_words.hpp"
#include "core/input_error.hpp"
#include "generators/random_maps.hpp"

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
        return fmt::format("on a random {} of {} darts (seed 1, attempt {}) the paths from dart {} end at {} and {}", model.name,
                           map.size(), attempt, d, a, b);
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
  if (r.congruent(w, w2)) {
    fmt::print("{} <->* {}: congruent ({} ->* ε)\n", w.str(), w2.str(), probe.str());
    return ok;
  }
  if (auto witness = separating_map(*model, w, w2)) {
    fmt::print("{} and {}: not congruent: {}\n", w.str(), w2.str(), *witness);
    return violation;
  }
  fmt::print("{} and {}: not shown congruent ({} has no rewriting to ε, and no random map separates them)\n", w.str(),
             w2.str(), probe.str());
  return violation;
}

}  // namespace dartcheck::cli
