// Shape builders: every shape is a valid map of its model, with the cell
// counts of the solid it represents (counted by hand).
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "checkers/map_validity.hpp"
#include "core/orbit.hpp"
#include "generators/random_maps.hpp"
#include "tests/map_recipe_gen.hpp"
#include "generators/shapes.hpp"

using namespace dartcheck;

namespace {
struct Expect {
  std::size_t darts;
  std::vector<std::size_t> cells;  // V, E, F[, Vol]
};

void expect_shape(const Model& m, const ShapeSpec& s, const Expect& e) {
  SCOPED_TRACE(m.name + " " + s.kind);
  Map map = build_shape(m, s);
  EXPECT_TRUE(check_map(map).valid());
  EXPECT_EQ(map.size(), e.darts);
  EXPECT_EQ(count_cells(map).cells, e.cells);
}
}  // namespace

// A k-gon has k vertices and k edges; as a G-map 2k darts and one face; as
// a 2-O-map k half-edges inside and k in the outer face (002 Example 5).
TEST(Shapes, Polygon) {
  expect_shape(Model::gmap(2), {"polygon", {5}}, {10, {5, 5, 1}});
  expect_shape(Model::omap(2), {"polygon", {5}}, {10, {5, 5, 2}});
  expect_shape(Model::gmap(3), {"polygon", {5}}, {10, {5, 5, 1, 1}});
}

TEST(Shapes, Cube) {
  // 6 faces x 4 sides x 2 darts = 48 G-map darts, 24 half-edges.
  expect_shape(Model::gmap(2), {"cube", {}}, {48, {8, 12, 6}});
  expect_shape(Model::omap(2), {"cube", {}}, {24, {8, 12, 6}});
  expect_shape(Model::gmap(3), {"cube", {}}, {48, {8, 12, 6, 1}});
}

TEST(Shapes, Tetrahedron) {
  expect_shape(Model::gmap(2), {"tetrahedron", {}}, {24, {4, 6, 4}});
  expect_shape(Model::omap(2), {"tetrahedron", {}}, {12, {4, 6, 4}});
  expect_shape(Model::gmap(3), {"tetrahedron", {}}, {24, {4, 6, 4, 1}});
}

// 000 Sec. 3.1: "the stacked cubes ... contains 96 darts, 48 0-links,
// 48 1-links, 48 2-links, and 88 3-links", a link being an unordered pair
// {d, alpha_i(d)} (a loop is one link). 12 vertices, 20 edges, 11 faces,
// 2 volumes.
TEST(Shapes, StackedCubesOfPaper000) {
  Map m = build_shape(Model::gmap(3), {"stacked-cubes", {}});
  EXPECT_TRUE(check_map(m).valid());
  EXPECT_EQ(m.size(), 96u);
  EXPECT_EQ(count_cells(m).cells, (std::vector<std::size_t>{12, 20, 11, 2}));
  std::vector<std::size_t> links;
  for (Dim i = 0; i <= 3; ++i) {
    std::size_t count = 0;
    for (Dart d = 0; d < m.size(); ++d) count += m.link(i, d) >= d;
    links.push_back(count);
  }
  EXPECT_EQ(links, (std::vector<std::size_t>{48, 48, 48, 88}));
  EXPECT_THROW(build_shape(Model::gmap(2), {"stacked-cubes", {}}), BuildError);
}

TEST(Shapes, RejectsBadParameters) {
  EXPECT_THROW(build_shape(Model::gmap(2), {"polygon", {2}}), BuildError);
  EXPECT_THROW(build_shape(Model::gmap(2), {"grid", {3}}), BuildError);
  EXPECT_THROW(build_shape(Model::gmap(2), {"sphere", {}}), BuildError);
  EXPECT_THROW(build_shape(Model::omap(3), {"cube", {}}), BuildError);
  EXPECT_THROW(parse_shape("grid:3y4"), BuildError);
  EXPECT_EQ(parse_shape("grid:3x4").params, (std::vector<int>{3, 4}));
}

// Grid r x c: (r+1)(c+1) vertices, r(c+1) + c(r+1) edges, rc faces (+1 outer
// face in a 2-O-map); 8rc G-map darts, 4rc + 2(r+c) O-map darts.
RC_GTEST_PROP(Shapes, GridCellCounts, ()) {
  const int r = *rc::gen::inRange(1, 12), c = *rc::gen::inRange(1, 12);
  const std::size_t V = (r + 1) * (c + 1), E = r * (c + 1) + c * (r + 1), F = r * c;
  Map g = build_shape(Model::gmap(2), {"grid", {r, c}});
  RC_ASSERT(check_map(g).valid());
  RC_ASSERT(g.size() == 8 * F);
  RC_ASSERT(count_cells(g).cells == (std::vector<std::size_t>{V, E, F}));
  Map o = build_shape(Model::omap(2), {"grid", {r, c}});
  RC_ASSERT(check_map(o).valid());
  RC_ASSERT(o.size() == 4 * F + 2 * (r + c));
  RC_ASSERT(count_cells(o).cells == (std::vector<std::size_t>{V, E, F + 1}));
  Map g3 = build_shape(Model::gmap(3), {"grid", {r, c}});
  RC_ASSERT(check_map(g3).valid());
}

// Prism k: 2k vertices, 3k edges, k+2 faces; a closed surface, so
// V - E + F = 2.
RC_GTEST_PROP(Shapes, PrismCellCounts, ()) {
  const int k = *rc::gen::inRange(3, 40);
  const std::vector<std::size_t> cells{2u * k, 3u * k, k + 2u};
  for (const Model& m : {Model::gmap(2), Model::omap(2)}) {
    Map p = build_shape(m, {"prism", {k}});
    RC_ASSERT(check_map(p).valid());
    RC_ASSERT(count_cells(p).cells == cells);
    RC_ASSERT(count_cells(p).euler() == 2);
  }
  Map v = build_shape(Model::gmap(3), {"prism", {k}});
  RC_ASSERT(check_map(v).valid());
  RC_ASSERT(v.size() == 12u * k);
}

// The recipe generator's promise: every recipe builds a valid map.
RC_GTEST_PROP(RandomMaps, EveryRecipeBuildsAValidMap, ()) {
  const auto model = *rc::gen::element(Model::gmap(1), Model::gmap(2), Model::gmap(3), Model::omap(2), Model::omap(3));
  Map m = build_random_map(model, *gen_map_recipe(1, 30));
  const auto report = check_map(m);
  RC_ASSERT(report.valid());
  RC_ASSERT(check_map_exact(m).valid());
}
