// Where to draw a map's darts when the map has vertex positions: an
// exploded view, as Jerboa's viewer draws G-maps. Each dart sits near its
// vertex, pulled toward the centre of its face and the middle of its edge,
// so a face's darts ring its centre and an edge's two sides face each
// other; 3D points are projected obliquely. Without it, a layout engine
// places a cube's 48 darts as a tangle; a map without positions gets its
// vertices placed by its skeleton's layout first.
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

/// Positions for a map that has none (a shape, a YAML map): its 1-skeleton
/// (one node per vertex, one edge per edge between the vertices of its
/// darts) laid out in 3D by Graphviz's neato, whose stress layout places
/// vertices as far apart as their graph distance (a grid comes out as a
/// grid, a cube's 8 vertices as a cube). Per dart, its vertex's point; the
/// input of exploded_layout. The layout is deterministic (neato's fixed
/// start). Throws Error when Graphviz fails.
std::vector<std::array<double, 3>> skeleton_points(const Map& map);

}  // namespace dartcheck::reports
