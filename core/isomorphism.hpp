// Isomorphism of dense maps (a bijection of darts that preserves every
// link and recorded predecessor). Used to say that an operation followed by
// its inverse gives back the map, and later to compare shrunk
// counterexamples.
#pragma once

#include <cstdint>
#include <vector>

#include "core/map.hpp"

namespace dartcheck {

/// The canonical code of the connected component of `start`: the link table
/// renumbered in BFS order from `start`. Two components are isomorphic iff
/// some starts give equal codes.
std::vector<std::int64_t> component_code(const Map& map, Dart start);

/// True if the maps have the same model and isomorphic components with
/// the same multiplicities. Exact when every arc is recorded at both ends
/// (link of its source, inverse link of its target), as in any map that
/// satisfies I(D). Quadratic in the component sizes: meant for the small
/// maps of tests and counterexamples.
bool isomorphic(const Map& a, const Map& b);

}  // namespace dartcheck
