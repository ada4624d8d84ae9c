// Modify operations on matched volumes (001 Sec. 6) that need no target
// map: deleting volumes (Alg. 3, corrected) and merging them into one
// (Alg. 4's first step, the replace used by the tet -> hex recombination).
// Both take the darts of whole volumes (closed under β1 and β2) and keep
// the map a valid 3-map; both renumber darts to keep the map dense and
// return the renumbering.
#pragma once

#include <utility>
#include <vector>

#include "core/map.hpp"

namespace dartcheck::querymodify {

/// Darts moved into the slots of removed ones: (old, new).
using Renumbering = std::vector<std::pair<Dart, Dart>>;

/// Deletes the volumes made of `darts`. Every β3 link between a deleted
/// dart and a kept one is unsewn first, whether or not the kept dart was
/// matched: 001's Alg. 3 unsews only the 3-links inside the query, which
/// leaves a kept dart 3-sewn to a deleted one when a deleted volume
/// touches the rest of the mesh (tests show it). Throws
/// std::invalid_argument if `darts` is not a union of volumes.
Renumbering delete_volumes(Map& m, const std::vector<Dart>& darts);

/// Merges the volumes made of `darts` into one by removing every face
/// between two of them (001 Alg. 4, lines 1-2): each remaining dart's
/// β2 becomes the next remaining dart around its edge, found by turning
/// through the removed faces (β2 then β3); edges and vertices inside the
/// merged volume disappear with their faces. Throws std::invalid_argument
/// if `darts` is not a union of volumes.
Renumbering merge_volumes(Map& m, const std::vector<Dart>& darts);

}  // namespace dartcheck::querymodify
