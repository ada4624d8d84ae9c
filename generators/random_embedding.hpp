// Random embedded G-maps (003 Def. 6): one value drawn per orbit of each
// embedding, from a small pool so that neighbouring orbits often share a
// value (the same color on two faces, as in Fig. 31) and often do not.
#pragma once

#include <random>
#include <vector>

#include "rewriting/embedded_map.hpp"

namespace dartcheck {

/// A value of type t from the pool: coordinates in 0..3, the four corner
/// colors red/green/blue/yellow, reals and integers 0..3, strings s0..s3.
Value random_value(ValueType t, std::mt19937& rng);

/// `map` with the given embeddings, each orbit labeled with a random value.
EmbeddedMap embed_randomly(Map map, const std::vector<EmbeddingSignature>& embeddings, std::mt19937& rng);

}  // namespace dartcheck
