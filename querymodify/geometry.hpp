// The geometry of the modify operations (001 Sec. 6.5): vertices that a
// modification keeps keep their points; a vertex the target creates is
// placed by its generalized barycentric coordinates in the target,
// expressed on the kept vertices, applied to their points in the input.
// The coordinates are the mean value coordinates of Ju, Schaefer and
// Warren (2005, 001's [23]) with respect to the query's boundary surface.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "core/error.hpp"
#include "core/map.hpp"

namespace dartcheck::querymodify {

using Point3 = std::array<double, 3>;

/// Mean value coordinates of x with respect to a closed triangulated
/// surface (Ju, Schaefer, Warren 2005, the algorithm of their Fig. 4):
/// weights on `vertices` summing to 1 with sum w_i v_i = x (linear
/// precision), for x inside or outside the surface. Triangles must be
/// oriented alike; degenerate ones (collinear corners) carry no weight.
/// On a vertex or a triangle, x gets that vertex's or the triangle's own
/// barycentric coordinates. Throws ValueError when the weights
/// cancel out (no triangle sees x).
std::vector<double> mean_value_coordinates(std::span<const Point3> vertices, std::span<const std::array<std::uint32_t, 3>> triangles,
                                           const Point3& x);

/// Points for a target's darts after a modification (001 Sec. 6.5).
/// `t_points` is T's point per dart, `q_to_t` is m_QT (no_dart where a
/// query dart has no image) and `matched_points[x]` the input point of
/// query dart x's image, read before the modification. A vertex orbit of
/// T holding the image of a query dart keeps that input point; every other
/// vertex of T is created: it is placed by its mean value coordinates in T
/// with respect to the query's boundary in T (the faces of the images of
/// Q's 3-free darts, fanned into triangles), applied to those vertices'
/// input points. An affine map between T's and the input's points of the
/// kept vertices thus carries the created vertices along (tested). Throws
/// ValueError if a vertex is created and Q has no boundary.
std::vector<Point3> place_target_points(const Map& q, const Map& t, std::span<const Point3> t_points, std::span<const Dart> q_to_t,
                                        std::span<const Point3> matched_points);

/// A point per dart from the point of each dart's vertex.
std::vector<Point3> dart_points(std::span<const std::uint32_t> vertex_of_dart, std::span<const Point3> points);

}  // namespace dartcheck::querymodify
