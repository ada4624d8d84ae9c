// The quality of a prism or a pyramid given by its corner points (corners
// as in cell_subdivisions.hpp): what the recombination into prisms and
// pyramids scores and its threshold accepts, in the spirit of the hex's
// scaled Jacobian (hex_quality.hpp).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace dartcheck::querymodify {

/// The scaled Jacobian of a prism: at each corner, the determinant of its
/// two edges in its triangle and its edge to the other triangle over the
/// product of their lengths, times 2/sqrt(3) so that the right prism on an
/// equilateral triangle scores 1; the minimum over the 6 corners, signed so
/// that a prism of either handedness scores positive when every corner
/// agrees. The value is floating point, its sign exact (orientation.hpp):
/// a value computed positive is 0 when a corner's determinant is not of the
/// prism's sign in exact arithmetic.
double prism_quality(const std::array<std::array<double, 3>, 6>& corner);

/// The same for a pyramid at its 4 base corners (the two base edges and
/// the edge to the apex), times sqrt(2) so that the pyramid with all edges
/// equal scores 1 (a taller one scores up to sqrt(2)). The 4 corner
/// determinants are the 4 tetrahedra of both splits of the base, so a
/// positive value means either split is a pair of positive tetrahedra.
double pyramid_quality(const std::array<std::array<double, 3>, 5>& corner);

/// The corners mirrored if needed so that the cell is right-handed, as
/// medit and gmsh want them: (c1 - c0) x (c2 - c0) . (c3 - c0) > 0 for a
/// prism (swapping corners 1, 2 and 4, 5), (c1 - c0) x (c3 - c0) . (c4 -
/// c0) > 0 for a pyramid (swapping corners 1 and 3).
std::array<std::uint32_t, 6> right_handed_prism(const std::array<std::uint32_t, 6>& corners, const std::vector<std::array<double, 3>>& points);
std::array<std::uint32_t, 5> right_handed_pyramid(const std::array<std::uint32_t, 5>& corners, const std::vector<std::array<double, 3>>& points);

}  // namespace dartcheck::querymodify
