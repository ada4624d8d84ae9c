// The exact sign of a 3D orientation determinant, so that a hexahedron is
// accepted only when every corner is positively oriented in exact
// arithmetic (001 Sec. 7.1's quality threshold; floating point alone
// accepted numerically flat corners). A floating-point filter with
// Shewchuk's error bound for orient3d decides almost every call; the rest
// are evaluated exactly in rationals (GMP), where every double is exact.
#pragma once

#include <array>

namespace dartcheck::querymodify {

using Point3 = std::array<double, 3>;

/// The sign (-1, 0 or 1) of det[a - d, b - d, c - d], exactly: positive
/// when d lies on the side of the plane abc from which a, b, c turn
/// clockwise (Shewchuk's orient3d convention). 0 if a coordinate is not
/// finite (the mesh readers refuse those).
int orientation_sign(const Point3& a, const Point3& b, const Point3& c, const Point3& d);

/// The version of the GMP library in use (the exact fallback).
const char* exact_arithmetic_version();

/// The same determinant in floating point, as the filter computes it.
double orientation_estimate(const Point3& a, const Point3& b, const Point3& c, const Point3& d);

}  // namespace dartcheck::querymodify
