// Where to draw a map's darts when the map has vertex positions: an
// exploded view, as Jerboa's viewer draws G-maps. Each dart sits near its
// vertex, pulled toward the centre of its face and the middle of its edge,
// so a face's darts ring its centre and an edge's two sides face each
// other; 3D points are projected obliquely. Without it, a layout engine
// places a cube's 48 darts as a tangle.
#pragma once

#include <array>
#include <vector>

#include "core/map.hpp"

namespace dartcheck::reports {

/// Per dart, its drawing position in inches (x right, y up), from the
/// position of its vertex (`points[d]`), scaled so that a dart's nearest
/// neighbour is typically (the median) an inch away, and
/// at most `max_inches` wide. O(n^2) in the darts: for pictures, not meshes.
std::vector<std::array<double, 2>> exploded_layout(const Map& map, const std::vector<std::array<double, 3>>& points, double max_inches = 40);

}  // namespace dartcheck::reports
