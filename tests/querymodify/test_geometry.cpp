// 001 Sec. 6.5: created vertices placed by mean value coordinates (Ju,
// Schaefer, Warren 2005). Theorems tested: linear precision (the weights
// sum to 1 and reproduce the point, inside and outside a closed surface);
// positivity inside a convex one (Floater, Kós, Reimers 2005); and so
// place_target_points carries an affine image of the kept vertices over to
// the created ones. Hand-derived cases: a vertex, a point on a triangle,
// and the 1-4 split of a tetrahedron, whose new vertex must land on the
// input tetrahedron's centroid (the only weights on 4 affinely independent
// points with linear precision are its barycentric coordinates).
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <random>

#include "core/orbit.hpp"
#include "querymodify/geometry.hpp"
#include "querymodify/map_checks.hpp"
#include "querymodify/modify.hpp"
#include "querymodify/tet_map.hpp"
#include "querymodify/terrain.hpp"

namespace dartcheck::querymodify {
namespace {

using Triangles = std::vector<std::array<std::uint32_t, 3>>;

// A box [0,a] x [0,b] x [0,c], each face split in two, outward.
std::vector<Point3> box_points(double a, double b, double c) {
  std::vector<Point3> p;
  for (int v = 0; v < 8; ++v) p.push_back({(v & 1) ? a : 0.0, (v & 2) ? b : 0.0, (v & 4) ? c : 0.0});
  return p;
}
const Triangles box_triangles = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                                 {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};

Point3 interpolate(const std::vector<double>& w, const std::vector<Point3>& p) {
  Point3 x{0, 0, 0};
  for (std::size_t j = 0; j < w.size(); ++j)
    for (std::size_t k = 0; k < 3; ++k) x[k] += w[j] * p[j][k];
  return x;
}

double sum(const std::vector<double>& w) {
  double s = 0;
  for (double v : w) s += v;
  return s;
}

TEST(MeanValueCoordinates, HandCases) {
  const auto p = box_points(2, 3, 4);
  auto w = mean_value_coordinates(p, box_triangles, p[5]);
  for (std::size_t j = 0; j < 8; ++j) EXPECT_EQ(w[j], j == 5 ? 1.0 : 0.0);
  // Inside triangle (0, 2, 3) of the bottom face: 1/3 on each corner.
  const Point3 on{(p[0][0] + p[2][0] + p[3][0]) / 3, (p[0][1] + p[2][1] + p[3][1]) / 3, 0};
  w = mean_value_coordinates(p, box_triangles, on);
  for (std::size_t j = 0; j < 8; ++j) EXPECT_NEAR(w[j], j == 0 || j == 2 || j == 3 ? 1.0 / 3 : 0.0, 1e-12);
  // The centre of the box: the 8 corners weigh alike by symmetry... only
  // up to the triangulation, which is not symmetric; linear precision
  // holds regardless.
  const Point3 centre{1, 1.5, 2};
  w = mean_value_coordinates(p, box_triangles, centre);
  const Point3 back = interpolate(w, p);
  for (std::size_t k = 0; k < 3; ++k) EXPECT_NEAR(back[k], centre[k], 1e-12);
}

// A star-shaped closed surface: the box's corners pushed along rays from
// its centre by random factors (the triangles stay oriented alike).
RC_GTEST_PROP(MeanValueCoordinates, LinearPrecisionInsideAndOutside, ()) {
  const auto seed = *rc::gen::arbitrary<std::uint32_t>();
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> factor(0.6, 1.6), coord(-4.0, 4.0);
  auto p = box_points(2, 2, 2);
  for (auto& v : p)
    for (std::size_t k = 0; k < 3; ++k) v[k] = 1 + (v[k] - 1) * factor(rng);
  const Point3 x{coord(rng), coord(rng), coord(rng)};
  const auto w = mean_value_coordinates(p, box_triangles, x);
  RC_ASSERT(std::abs(sum(w) - 1) < 1e-9);
  const Point3 back = interpolate(w, p);
  for (std::size_t k = 0; k < 3; ++k) RC_ASSERT(std::abs(back[k] - x[k]) < 1e-8 * (1 + std::abs(x[k])));
}

RC_GTEST_PROP(MeanValueCoordinates, PositiveInsideAConvexBox, ()) {
  std::mt19937 rng(*rc::gen::arbitrary<std::uint32_t>());
  std::uniform_real_distribution<double> side(0.5, 5.0), t(0.01, 0.99);
  const double a = side(rng), b = side(rng), c = side(rng);
  const auto p = box_points(a, b, c);
  const Point3 x{a * t(rng), b * t(rng), c * t(rng)};
  for (double v : mean_value_coordinates(p, box_triangles, x)) RC_ASSERT(v > 0);
}

// The house of 001 Sec. 7.4 on its spot, with the spot's points moved by a
// random affine map: the created vertices move by the same map.
RC_GTEST_PROP(PlaceTargetPoints, CarriesAnAffineMapToCreatedVertices, ()) {
  std::mt19937 rng(*rc::gen::arbitrary<std::uint32_t>());
  std::uniform_real_distribution<double> entry(-2.0, 2.0);
  double a[3][4];
  for (auto& row : a)
    for (double& v : row) v = entry(rng);
  for (int k = 0; k < 3; ++k) a[k][k] += 5;  // far from singular
  auto image = [&](const Point3& x) {
    Point3 y{};
    for (std::size_t k = 0; k < 3; ++k) y[k] = a[k][0] * x[0] + a[k][1] * x[1] + a[k][2] * x[2] + a[k][3];
    return y;
  };
  const auto rule = terrain::house_rule();
  const Map& q = rule.query.map;
  std::vector<Dart> q_to_t(q.size());
  std::vector<Point3> matched;
  for (Dart x = 0; x < q.size(); ++x) {
    q_to_t[x] = x;
    matched.push_back(image(rule.query.points[x]));
  }
  const auto placed = place_target_points(q, rule.target.map, rule.target.points, q_to_t, matched);
  for (Dart d = 0; d < rule.target.map.size(); ++d) {
    const Point3 want = image(rule.target.points[d]);
    for (std::size_t k = 0; k < 3; ++k) RC_ASSERT(std::abs(placed[d][k] - want[k]) < 1e-8 * (1 + std::abs(want[k])));
  }
}

// Replace (Alg. 4) with geometry: the central tetrahedron of the unit cube
// cut into 5 is replaced by the 1-4 split of a reference tetrahedron.
TEST(PlaceTargetPoints, OneFourSplitLandsOnTheCentroid) {
  std::vector<Point3> cube;
  for (int v = 0; v < 8; ++v) cube.push_back({double(v & 1), double((v >> 1) & 1), double((v >> 2) & 1)});
  TetMap m = build_tet_map({{0, 3, 5, 6}, {1, 0, 3, 5}, {2, 0, 3, 6}, {4, 0, 5, 6}, {7, 3, 5, 6}}, &cube);
  const std::vector<Point3> ref = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0.25, 0.25, 0.25}};
  TetMap q = build_tet_map({{0, 1, 2, 3}}, &ref);
  TetMap t = build_tet_map({{4, 1, 2, 3}, {0, 4, 2, 3}, {0, 1, 4, 3}, {0, 1, 2, 4}}, &ref);
  // Reference vertex i is cube corner at[i] (same handedness: det = 2).
  const std::uint32_t at[4] = {0, 3, 6, 5};
  std::vector<Dart> q_to_t(q.map.size(), no_dart), q_to_m(q.map.size(), no_dart);
  for (Dart x = 0; x < q.map.size(); ++x) {
    const std::uint32_t u = q.vertex[x], v = q.vertex[q.map.link(1, x)];
    for (Dart y = 0; y < t.map.size(); ++y)
      if (t.map.link(3, y) == no_dart && t.vertex[y] == u && t.vertex[t.map.link(1, y)] == v) q_to_t[x] = y;
    for (Dart y = 0; y < 12; ++y)  // tetrahedron 0 of m: darts 0..11
      if (m.vertex[y] == at[u] && m.vertex[m.map.link(1, y)] == at[v]) q_to_m[x] = y;
    ASSERT_NE(q_to_t[x], no_dart);
    ASSERT_NE(q_to_m[x], no_dart);
  }
  std::vector<Point3> matched, t_points = dart_points(t.vertex, ref), m_points = dart_points(m.vertex, cube);
  for (Dart x = 0; x < q.map.size(); ++x) matched.push_back(m_points[q_to_m[x]]);
  Renumbering moved;
  const auto t_to_m = replace(m.map, q.map, t.map, q_to_t, q_to_m, &moved);
  follow(m_points, moved);
  m_points.resize(m.map.size());
  const auto placed = place_target_points(q.map, t.map, t_points, q_to_t, matched);
  for (Dart d = 0; d < t.map.size(); ++d) m_points[t_to_m[d]] = placed[d];
  EXPECT_TRUE(check_3map(m.map).valid());
  EXPECT_EQ(m.map.size(), 96U);  // 60 - 12 + 48
  // Every dart of the new vertex sits at the centroid of corners 0, 3, 5, 6.
  std::size_t at_centroid = 0;
  for (Dart d = 0; d < t.map.size(); ++d)
    if (t.vertex[d] == 4) {
      ++at_centroid;
      for (std::size_t k = 0; k < 3; ++k) EXPECT_NEAR(m_points[t_to_m[d]][k], 0.5, 1e-12);
    }
  EXPECT_EQ(at_centroid, 12U);  // 4 tetrahedra x 3 darts at the new vertex
  // Kept darts keep their points: each of m's darts sits at a cube corner.
  for (const auto& p : m_points)
    for (double c : p) EXPECT_TRUE(c == 0 || c == 1 || std::abs(c - 0.5) < 1e-12) << c;
}

}  // namespace
}  // namespace dartcheck::querymodify
