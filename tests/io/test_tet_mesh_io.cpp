// TetGen and medit readers: the same two tetrahedra from both formats, and
// errors at file:line:column.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

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

TEST(TetMeshIo, MeditWrittenReadsBack) {
  TetMesh m;
  for (int v = 0; v < 8; ++v) m.points.push_back({double(v & 1), double((v >> 1) & 1), 0.1 + double(v >> 2)});
  m.points.push_back({0.5, 0.5, 1.7});
  m.tets = {{4, 5, 6, 8}};
  m.hexes = {{0, 1, 3, 2, 4, 5, 7, 6}};
  std::stringstream out;
  write_medit(out, m);
  const auto path = std::filesystem::temp_directory_path() / "dartcheck-medit-roundtrip.mesh";
  std::ofstream(path) << out.str();
  const TetMesh back = read_tet_mesh(path.string());
  EXPECT_EQ(back.points, m.points);  // shortest round-trip decimals
  EXPECT_EQ(back.tets, m.tets);
  EXPECT_EQ(back.hexes, m.hexes);
  std::filesystem::remove(path);
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
