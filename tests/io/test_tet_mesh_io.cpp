// TetGen and medit readers: the same two tetrahedra from both formats, and
// errors at file:line:column.
#include <gtest/gtest.h>

#include "core/input_error.hpp"
#include "io/tet_mesh_io.hpp"

namespace dartcheck {
namespace {

std::string data(const std::string& f) { return std::string(DARTCHECK_SOURCE_DIR) + "/tests/data/" + f; }

TEST(TetMeshIo, TetgenAndMeditAgree) {
  const TetMesh a = read_tet_mesh(data("two-tets.node")), b = read_tet_mesh(data("two-tets.ele")), c = read_tet_mesh(data("two-tets.mesh"));
  const std::vector<std::array<std::uint32_t, 4>> tets{{0, 1, 2, 3}, {1, 2, 3, 4}};
  for (const TetMesh* m : {&a, &b, &c}) {
    EXPECT_EQ(m->points.size(), 5u);
    EXPECT_EQ(m->tets, tets);
    EXPECT_EQ(m->points[4], (std::array<double, 3>{1, 1, 1}));
  }
  EXPECT_EQ(c.tet_lines, (std::vector<int>{15, 16}));  // lines 15 and 16 of two-tets.mesh
}

TEST(TetMeshIo, ErrorsArePositioned) {
  try {
    read_tet_mesh(data("bad-tets.mesh"));
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 11);  // the tetrahedron naming vertex 9
    EXPECT_NE(std::string(e.what()).find("out of range"), std::string::npos) << e.what();
  }
  EXPECT_THROW(read_tet_mesh(data("no-such.ele")), InputError);
  EXPECT_THROW(read_tet_mesh(data("two-tets.yaml")), InputError);
}

}  // namespace
}  // namespace dartcheck
