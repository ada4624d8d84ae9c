// glue_cells and shared_faces (core/cell_gluing): expected values by hand
// from the cells drawn in the comments.
#include <gtest/gtest.h>

#include "core/cell_gluing.hpp"

namespace dartcheck {
namespace {

// A tetrahedron 0 1 2 3 with outward faces, and its mirror 1 2 3 4 glued on
// face 1 2 3 (traversed 1 3 2 there, 1 2 3 here).
const Polyhedron tet{{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
const Polyhedron apex{{1, 2, 4}, {2, 3, 4}, {3, 1, 4}, {1, 3, 2}};

std::size_t free_links(const Map& m, Dim i) {
  std::size_t n = 0;
  for (Dart d = 0; d < m.size(); ++d) n += m.link(i, d) == no_dart;
  return n;
}

BuildError error_of(const std::vector<Polyhedron>& cells) {
  try {
    glue_cells(CellComplex::of(cells));
  } catch (const BuildError& e) {
    return e;
  }
  ADD_FAILURE() << "glued";
  return BuildError("none");
}

TEST(CellGluing, TwoTetrahedraShareOneFace) {
  const GluedCells g = glue_cells(CellComplex::of({tet, apex}));
  ASSERT_EQ(g.map.size(), 24U);
  EXPECT_EQ(free_links(g.map, 1), 0U);
  EXPECT_EQ(free_links(g.map, 2), 0U);
  EXPECT_EQ(free_links(g.map, 3), 18U);  // 6 outer faces of 3 darts
  // Dart 9 is 1 -> 2 on face 3 of the first cell; its β3 goes 2 -> 1 in the second.
  EXPECT_EQ(g.vertex[9], 1U);
  const Dart e = g.map.link(3, 9);
  ASSERT_NE(e, no_dart);
  EXPECT_EQ(g.cell[e], 1U);
  EXPECT_EQ(g.vertex[e], 2U);
  EXPECT_EQ(g.vertex[g.map.link(1, e)], 1U);
  // β2 of dart 0 (0 -> 2 on face 0) is 2 -> 0 on face 2.
  EXPECT_EQ(g.vertex[g.map.link(2, 0)], 2U);
  EXPECT_EQ(g.vertex[g.map.link(1, g.map.link(2, 0))], 0U);
}

TEST(CellGluing, ErrorsNameTheCell) {
  const Polyhedron same_way{{1, 3, 4}, {3, 2, 4}, {2, 1, 4}, {1, 2, 3}};  // face 1 2 3 the same way as tet
  EXPECT_EQ(error_of({tet, same_way}).index(), 1U);
  EXPECT_EQ(error_of({tet, same_way}).culprit(), BuildError::Culprit::cell);
  const Polyhedron third{{1, 2, 5}, {2, 3, 5}, {3, 1, 5}, {1, 3, 2}};
  const BuildError three = error_of({tet, apex, third});
  EXPECT_EQ(three.index(), 2U);
  EXPECT_NE(std::string(three.what()).find("shared by 3 cells"), std::string::npos) << three.what();
  Polyhedron open = tet;
  open.pop_back();
  EXPECT_EQ(error_of({tet, open}).index(), 1U);
  EXPECT_EQ(error_of({tet, {{0, 1, 1}}}).index(), 1U);
}

TEST(CellGluing, SharedFacesAreThePairsWithOneVertexSet) {
  CellComplex c;
  const std::uint32_t a[] = {0, 1, 2}, b[] = {2, 1, 0}, q[] = {0, 1, 2, 3}, r[] = {3, 2, 1, 0};
  c.add_face(a), c.add_face(q), c.end_cell();
  c.add_face(r), c.add_face(b), c.end_cell();
  using P = std::pair<std::size_t, std::size_t>;
  EXPECT_EQ(shared_faces(c), (std::vector<P>{{0, 3}, {1, 2}}));
  EXPECT_EQ(c.face_cells(), (std::vector<std::uint32_t>{0, 0, 1, 1}));
}

}  // namespace
}  // namespace dartcheck
