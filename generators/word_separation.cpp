#include "generators/word_separation.hpp"

#include <random>

#include <fmt/format.h>

#include "generators/random_maps.hpp"

namespace dartcheck {

std::optional<std::string> separating_random_map(const Model& model, const ConjWord& w, const ConjWord& w2) {
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

}  // namespace dartcheck
