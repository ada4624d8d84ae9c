// Lemma 3 of 002 read backwards: congruent words end at the same dart on
// every valid map, so a map on which the two paths from one dart end at
// different darts proves the words are not congruent.
#pragma once

#include <optional>
#include <string>

#include "core/conjugate_words.hpp"

namespace dartcheck {

/// Looks for such a map among 200 seeded random maps of `model` (G-maps
/// of dimension up to 3 and 2- and 3-O-maps; nullopt for other models):
/// a sentence naming the map and the two ends, or nullopt if none
/// separates the words.
std::optional<std::string> separating_random_map(const Model& model, const ConjWord& w, const ConjWord& w2);

}  // namespace dartcheck
