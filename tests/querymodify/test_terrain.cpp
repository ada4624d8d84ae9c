// 001 Sec. 7.4 and Table 2: the voxel terrain, flat spots by query-apply,
// houses by query-extend. Expected counts are derived by hand from the
// construction (26 darts per voxel: 5 quads and 2 triangles; a flattened
// 3 x 3 spot loses 12 inner walls of 8 darts and 12 inner upper edges of
// 2 darts) and match Table 2's rows (1) and (2) exactly; row (3) depends
// on the house, which 001 only draws (see docs/querymodify.md).
#include <gtest/gtest.h>

#include <cmath>

#include "core/isomorphism.hpp"
#include "core/orbit.hpp"
#include "core/cell_gluing.hpp"
#include "querymodify/map_checks.hpp"
#include "map_counts.hpp"
#include "querymodify/overlap.hpp"
#include "querymodify/terrain.hpp"

namespace dartcheck::querymodify {
namespace {

using test::free3;
using test::volumes;

TEST(CellMap, VoxelGridByHand) {
  const auto g = terrain::voxel_grid(2, std::vector<double>(9, 1.5));
  EXPECT_EQ(g.map.size(), 104U);  // 4 voxels x 26
  EXPECT_TRUE(check_3map(g.map).valid());
  // Boundary: 4 upper quads (16), 8 bottom triangles (24), 8 outer side
  // quads (32); the 4 inner walls are sewn on both sides (32).
  EXPECT_EQ(free3(g.map), 72U);
  EXPECT_EQ(volumes(g.map), 4U);
  OrbitWalker w(g.map);
  EXPECT_EQ(w.count_orbits(cell_generators(g.map.model(), 0)), 18U);  // 9 lower and 9 upper grid points
}

TEST(CellMap, BadCellsNameTheCell) {
  const Polyhedron tet{{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  EXPECT_NO_THROW(glue_cells(CellComplex::of({tet})));
  Polyhedron open = tet;
  open.pop_back();
  try {
    glue_cells(CellComplex::of({tet, open}));
    FAIL() << "an open cell was accepted";
  } catch (const BuildError& e) {
    EXPECT_EQ(e.culprit(), BuildError::Culprit::cell);
    EXPECT_EQ(e.index(), 1U);
  }
  // The same tetrahedron's mirror image glued on face 1 2 3 traversed the
  // same way: the orientations differ.
  const Polyhedron other{{1, 3, 4}, {3, 2, 4}, {2, 1, 4}, {1, 2, 3}};
  EXPECT_THROW(glue_cells(CellComplex::of({tet, other})), BuildError);
  const Polyhedron flipped{{1, 2, 4}, {2, 3, 4}, {3, 1, 4}, {1, 3, 2}};
  EXPECT_TRUE(check_3map(glue_cells(CellComplex::of({tet, flipped})).map).valid());
  EXPECT_THROW(glue_cells(CellComplex::of({{{0, 1}}})), BuildError);
}

TEST(Terrain, FlattenedSpotIsTheHouseQuery) {
  auto q = terrain::spot_query();
  terrain::Mesh m = q.mesh;
  std::vector<Dart> identity(m.map.size());
  for (Dart d = 0; d < identity.size(); ++d) identity[d] = d;
  // Heights 1..16 on the upper points: their mean is 8.5.
  for (Dart d = 0; d < m.map.size(); ++d)
    if (m.points[d][2] > 0) m.points[d][2] = 1 + m.points[d][0] + 4 * m.points[d][1];
  terrain::flatten_spot(m, q, identity);
  EXPECT_EQ(m.map.size(), 114U);  // 234 - 12 x 8 - 12 x 2
  EXPECT_TRUE(check_3map(m.map).valid());
  EXPECT_TRUE(isomorphic(m.map, terrain::house_rule().query.map));
  for (const auto& p : m.points) EXPECT_TRUE(p[2] == 0 || p[2] == 8.5) << p[2];
}

// Table 2 at 001's size: a 128 x 128 grid, 50 spots, 50 houses.
TEST(Terrain, Table2) {
  const auto x = terrain::run_experiment(7, 50, 2025);
  EXPECT_EQ(x.grid.volumes, 16384U);  // Table 2 (1)
  EXPECT_EQ(x.grid.darts, 425984U);
  // Every 3 x 3 window, found twice (the half turn keeps the bottoms'
  // diagonals; a quarter turn does not).
  EXPECT_EQ(x.flattened.distinct_matches, 126U * 126U);
  EXPECT_EQ(x.flattened.raw_matches, 2U * 126U * 126U);
  EXPECT_EQ(x.flattened.applied, 50U);
  EXPECT_EQ(x.flattened.volumes, 15984U);  // Table 2 (2)
  EXPECT_EQ(x.flattened.darts, 419984U);
  // Only the 50 spots are flattened spots, each found from both halves.
  EXPECT_EQ(x.housed.distinct_matches, 50U);
  EXPECT_EQ(x.housed.raw_matches, 100U);
  EXPECT_EQ(x.housed.volumes, 16134U);              // Table 2 (3)
  EXPECT_EQ(x.housed.darts, 419984U + 50U * 192U);  // 001's house has 234 darts, ours 192
  EXPECT_TRUE(check_3map(x.mesh.map).valid());
  // The roof's apex is 4.5 spot heights up, above the spot's centre: the
  // spot is an affine image of the target's [0, 3]^2 x [0, 1].
  ASSERT_EQ(x.houses.size(), 50U);
  for (const auto& h : x.houses) {
    EXPECT_NEAR(h.apex[0], h.spot_centre[0], 1e-9);
    EXPECT_NEAR(h.apex[1], h.spot_centre[1], 1e-9);
    EXPECT_NEAR(h.apex[2], 4.5 * h.spot_centre[2], 1e-9);
  }
}

}  // namespace
}  // namespace dartcheck::querymodify
