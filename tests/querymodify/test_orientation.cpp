// The exact orientation predicate (querymodify/orientation.hpp) against an
// independent exact evaluation: points on a lattice of step 2^-30 around
// 2^22 (every coordinate a double, 52 significant bits), whose
// determinant is computed in 128-bit integers from the lattice offsets.
// Half the cases are exactly coplanar, then nudged by one lattice step,
// where floating point alone gets the sign wrong.
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "querymodify/cell_quality.hpp"
#include "querymodify/orientation.hpp"
#include "querymodify/recombination.hpp"

namespace dartcheck::querymodify {
namespace {

__extension__ using Int = __int128;  // exact for the determinants below (< 2^100)
using Lattice = std::array<long long, 3>;

constexpr long long offset = 1LL << 52;  // 2^22 in lattice steps

Point3 point(const Lattice& q) {
  Point3 p{};
  for (std::size_t k = 0; k < 3; ++k) p[k] = std::ldexp(static_cast<double>(offset + q[k]), -30);
  return p;
}

// det[a - d, b - d, c - d] on the lattice, exactly.
int lattice_sign(const Lattice& a, const Lattice& b, const Lattice& c, const Lattice& d) {
  Int u[3], v[3], w[3];
  for (std::size_t k = 0; k < 3; ++k) u[k] = a[k] - d[k], v[k] = b[k] - d[k], w[k] = c[k] - d[k];
  const Int det = u[2] * (v[0] * w[1] - w[0] * v[1]) + v[2] * (w[0] * u[1] - u[0] * w[1]) + w[2] * (u[0] * v[1] - v[0] * u[1]);
  return det > 0 ? 1 : det < 0 ? -1 : 0;
}

TEST(Orientation, SignIsExactOnNearlyCoplanarPoints) {
  std::mt19937_64 rng(41);
  auto r = [&](long long m) { return static_cast<long long>(rng() % static_cast<unsigned long long>(2 * m + 1)) - m; };
  int float_wrong = 0, zero = 0;
  for (int t = 0; t < 200000; ++t) {
    const long long m = 1LL << 24;
    const Lattice a{r(m), r(m), r(m)}, b{r(m), r(m), r(m)}, c{r(m), r(m), r(m)};
    Lattice d{r(m), r(m), r(m)};
    if (t % 2) {
      // d = a + s (b - a) + u (c - a): on the plane abc, then one step off.
      const long long s = r(3), u = r(3);
      for (std::size_t k = 0; k < 3; ++k) d[k] = a[k] + s * (b[k] - a[k]) + u * (c[k] - a[k]);
      d[static_cast<std::size_t>(t % 3)] += r(1);
    }
    const int expected = lattice_sign(a, b, c, d);
    ASSERT_EQ(orientation_sign(point(a), point(b), point(c), point(d)), expected) << "case " << t;
    const double estimate = orientation_estimate(point(a), point(b), point(c), point(d));
    float_wrong += (estimate > 0) - (estimate < 0) != expected;
    zero += expected == 0;
  }
  // Not vacuous: floating point alone is wrong on some of these, and some
  // are exactly flat.
  EXPECT_GT(float_wrong, 100);
  EXPECT_GT(zero, 100);
}

TEST(Orientation, SwappingTwoPointsFlipsTheSign) {
  std::mt19937_64 rng(43);
  for (int t = 0; t < 10000; ++t) {
    Point3 p[4];
    for (auto& x : p)
      for (auto& c : x) c = std::ldexp(static_cast<double>(rng() % (1u << 20)), -10) + 1e6;
    EXPECT_EQ(orientation_sign(p[0], p[1], p[2], p[3]), -orientation_sign(p[1], p[0], p[2], p[3]));
  }
}

// A hexahedron whose corner 0 is exactly flat (corners 1, 2 and 4 lie on a
// plane through corner 0: the lattice determinant below is 0) but whose
// floating-point scaled Jacobian is positive (1.03e-17, at corner 0): found
// by a search over random frames on the lattice.
// Before exact signs, recombination accepted such hexes at threshold 0.
TEST(Orientation, NearlyFlatHexIsNotAccepted) {
  const Lattice q[8] = {{-280616, -266929, 860261}, {1017481, -486636, 940228}, {-106883, 989312, 926392},  {1191214, 769605, 1006359},
                        {-842798, 471045, 853343},  {945472, -531695, 1985357}, {-178892, 944253, 1971521}, {1119205, 724546, 2051488}};
  ASSERT_EQ(lattice_sign(q[1], q[2], q[4], q[0]), 0);
  std::array<Point3, 8> p{};
  for (std::size_t v = 0; v < 8; ++v) p[v] = point(q[v]);
  // Corner 0's scaled Jacobian in floating point, edges from the corner as
  // 001 defines it, is positive: alone it would accept the hex.
  double e[3][3];
  for (std::size_t axis = 0; axis < 3; ++axis)
    for (std::size_t c = 0; c < 3; ++c) e[axis][c] = p[std::size_t{1} << axis][c] - p[0][c];
  const double corner0 = e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) - e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
                         e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]);
  EXPECT_GT(corner0, 0);
  EXPECT_EQ(orientation_sign(p[1], p[2], p[4], p[0]), 0);
  EXPECT_EQ(scaled_jacobian(p), 0.0);
  // The same hex with corner 4 lifted halfway up its vertical edge is
  // accepted.
  std::array<Point3, 8> lifted = p;
  for (std::size_t c = 0; c < 3; ++c) lifted[4][c] += 0.5 * (p[5][c] - p[1][c]);
  EXPECT_GT(scaled_jacobian(lifted), 0.0);
}

// A prism and a pyramid exactly flat at corner 0 but positive there (and
// everywhere) in floating point: base vectors 8u and 8v from corner 0, and
// the point u + v behind corner 0 in their plane as the prism's corner 3
// (above corner 0) or the pyramid's apex; the prism's top is 8u + w and 8v
// + w, the pyramid's far base corner 8u + 8v + w. Found by a search over
// random lattice frames; lattice_sign shows the flat corner exactly.
// Floating point alone would accept both.
TEST(Orientation, NearlyFlatPrismAndPyramidAreNotAccepted) {
  const Lattice p0{949767, 651482, -69038}, u{13993978, -4803273, -4145898}, v{7412493, 11534855, -2103646}, w{-3675900, 1581371, 33236927};
  auto at = [&](long long a, long long b, long long c) {
    Lattice q{};
    for (std::size_t k = 0; k < 3; ++k) q[k] = p0[k] + a * u[k] + b * v[k] + c * w[k];
    return q;
  };
  const Lattice c0 = at(0, 0, 0), c1 = at(8, 0, 0), c2 = at(0, 8, 0), behind = at(-1, -1, 0);
  ASSERT_EQ(lattice_sign(c1, c2, behind, c0), 0);
  // det[e1, e2, e3] in floating point, as both qualities compute it.
  auto det = [](const Point3& x, const Point3& a, const Point3& b, const Point3& c) {
    double e[3][3];
    for (std::size_t k = 0; k < 3; ++k) e[0][k] = a[k] - x[k], e[1][k] = b[k] - x[k], e[2][k] = c[k] - x[k];
    return e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) - e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
           e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]);
  };
  auto least = [&](const auto& p, const auto& corners) {
    double lo = 1e300;
    for (const auto& c : corners)
      lo = std::min(lo, det(p[static_cast<std::size_t>(c[0])], p[static_cast<std::size_t>(c[1])], p[static_cast<std::size_t>(c[2])],
                            p[static_cast<std::size_t>(c[3])]));
    return lo;
  };
  // Each corner with its two edges in its triangle (base) and its third
  // edge, as cell_quality orders them.
  const std::array<std::array<int, 4>, 6> prism_corners{{{0, 1, 2, 3}, {1, 2, 0, 4}, {2, 0, 1, 5}, {3, 5, 4, 0}, {4, 3, 5, 1}, {5, 4, 3, 2}}};
  const std::array<std::array<int, 4>, 4> pyramid_corners{{{0, 1, 3, 4}, {1, 2, 0, 4}, {2, 3, 1, 4}, {3, 0, 2, 4}}};
  const std::array<Point3, 6> prism{point(c0), point(c1), point(c2), point(behind), point(at(8, 0, 1)), point(at(0, 8, 1))};
  EXPECT_GT(least(prism, prism_corners), 0);  // every corner positive in floating point
  EXPECT_EQ(prism_quality(prism), 0.0);
  const std::array<Point3, 5> pyramid{point(c0), point(c1), point(at(8, 8, 1)), point(c2), point(behind)};
  EXPECT_GT(least(pyramid, pyramid_corners), 0);
  EXPECT_EQ(pyramid_quality(pyramid), 0.0);
  // Corner 3 lifted along w, and the apex too: both are accepted.
  std::array<Point3, 6> lifted = prism;
  lifted[3] = point(at(-1, -1, 1));
  EXPECT_GT(prism_quality(lifted), 0.0);
  std::array<Point3, 5> raised = pyramid;
  raised[4] = point(at(-1, -1, 1));
  EXPECT_GT(pyramid_quality(raised), 0.0);
}

}  // namespace
}  // namespace dartcheck::querymodify
