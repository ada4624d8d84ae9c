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

// Hostile numbers (issue 38): each file differs from a valid one in one
// token, and the error names that token's line and column, with vertices
// numbered as the file numbers them.
struct Hostile {
  const char* name;
  const char* node;  // empty: a medit file
  const char* ele_or_mesh;
  int line, column;
  const char* says;
};

TEST(TetMeshIo, HostileNumbersAreRefusedWhereTheyAre) {
  const Hostile cases[] = {
      {"tetgen-inf", "5 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n5 inf 1 1\n", "2 4 0\n1 1 2 3 4\n2 2 3 4 5\n", 6, 3,
       "x is not a finite number (inf)"},
      {"tetgen-nan", "4 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 nan 0\n4 0 0 1\n", "1 4 0\n1 1 2 3 4\n", 4, 5, "y is not a finite number (nan)"},
      // 2^32 + 5 would wrap to vertex 5 through a 32-bit index.
      {"tetgen-wrap", "5 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n5 1 1 1\n", "2 4 0\n1 1 2 3 4\n2 2 3 4 4294967301\n", 3, 9,
       "vertex index 4294967301 out of range 1..5"},
      {"tetgen-first-seven", "2 3 0 0\n7 0 0 0\n8 1 0 0\n", "0 4 0\n", 2, 1, "point indices start at 0 or 1"},
      {"tetgen-repeat", "4 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n", "1 4 0\n1 1 2 4 4\n", 2, 3, "repeats vertex 4"},
      {"medit-inf", "", "MeshVersionFormatted 1\nDimension 3\nVertices\n1\n0 -inf 0 0\nEnd\n", 5, 3, "y is not a finite number (-inf)"},
      {"medit-wrap", "",
       "MeshVersionFormatted 1\nDimension 3\nVertices\n4\n0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\nTetrahedra\n1\n1 2 3 4294967297 0\nEnd\n", 11, 7,
       "vertex index 4294967297 out of range 1..4"},
  };
  const auto dir = std::filesystem::temp_directory_path() / "dartcheck-hostile-tets";
  std::filesystem::create_directories(dir);
  for (const auto& c : cases) {
    const bool tetgen = *c.node;
    const auto base = dir / c.name;
    if (tetgen) std::ofstream(base.string() + ".node") << c.node;
    const std::string file = base.string() + (tetgen ? ".ele" : ".mesh");
    std::ofstream(file) << c.ele_or_mesh;
    try {
      read_tet_mesh(file);
      ADD_FAILURE() << c.name << ": read";
    } catch (const InputError& e) {
      EXPECT_EQ(e.line(), c.line) << c.name << ": " << e.what();
      EXPECT_EQ(e.column(), c.column) << c.name << ": " << e.what();
      EXPECT_NE(std::string(e.what()).find(c.says), std::string::npos) << c.name << ": " << e.what();
      EXPECT_NE(std::string(e.what()).find(c.name), std::string::npos) << c.name << ": the file is not named: " << e.what();
    }
  }
}

}  // namespace
}  // namespace dartcheck
