// The quality of a hexahedron given by its 8 corner points (corner v =
// x + 2y + 4z): what the recombination's global strategy scores and its
// threshold accepts (001 Sec. 7.1).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace dartcheck::querymodify {

/// The scaled Jacobian: at each corner, the determinant of its three edge
/// vectors (towards +x, +y, +z, reversed where the corner is on the high
/// side) over the product of their lengths; the quality is the minimum
/// over the corners, signed so that a hex of either handedness scores
/// positive when every corner agrees (1 for a cube, <= 0 for an inverted
/// or folded one). The value is floating point, its sign is exact: a
/// quality computed positive is 0 when some corner's determinant is not
/// of the hex's sign in exact arithmetic (orientation.hpp), so no hex
/// accepted at a threshold >= 0 has a flat or inverted corner.
double scaled_jacobian(const std::array<std::array<double, 3>, 8>& corner);

/// The same in floating point only (the exact sign is not checked): the
/// cheap first pass over many readings of one match.
double scaled_jacobian_estimate(const std::array<std::array<double, 3>, 8>& corner);

/// The points of the mesh vertices at the 8 corners.
std::array<std::array<double, 3>, 8> corner_points(const std::array<std::uint32_t, 8>& corners, const std::vector<std::array<double, 3>>& points);

/// The corners mirrored in x if needed so that x, y, z at corner 0 are a
/// positive frame, as mesh formats want hexahedra.
std::array<std::uint32_t, 8> right_handed(const std::array<std::uint32_t, 8>& corners, const std::vector<std::array<double, 3>>& points);

}  // namespace dartcheck::querymodify
