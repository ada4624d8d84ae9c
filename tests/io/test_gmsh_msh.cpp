// gmsh's .msh: dartcheck's writer read back by its reader in both versions
// (gmsh's and meshio's readings of the same files: tests/cli/mesh_outputs.py),
// the handedness each writer gives the cells, and errors at
// file:line:column.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/input_error.hpp"
#include "io/gmsh_msh.hpp"
#include "io/volume_cells.hpp"
#include "io/vtk_writer.hpp"

namespace dartcheck {
namespace {

std::string written(const std::string& name, const std::string& text) {
  const auto path = std::filesystem::temp_directory_path() / name;
  std::ofstream(path) << text;
  return path.string();
}

std::string message_of(const std::string& text) {
  try {
    read_gmsh(written("dartcheck-gmsh-error.msh", text));
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

// A unit cube as one hex, a prism and a pyramid on it, and a tetrahedron
// given left-handed (corners 1 and 2 swapped).
TetMesh sample() {
  TetMesh m;
  for (int v = 0; v < 8; ++v) m.points.push_back({double(v & 1), double((v >> 1) & 1), double(v >> 2)});
  m.points.push_back({0.5, 0.5, 1.5});      // 8: apex above the top face
  m.points.push_back({0, 0, -1});           // 9, 10, 11: a prism under the bottom face's triangle 0 1 2
  m.points.push_back({1, 0, -1});
  m.hexes = {{0, 1, 3, 2, 4, 5, 7, 6}};     // medit: bottom cycle, then the top above it
  m.pyramids = {{4, 5, 7, 6, 8}};
  m.points.push_back({0, 1, -1});           // 11
  m.prisms = {{9, 10, 11, 0, 1, 2}};        // triangle z = -1, the one above at z = 0: right-handed
  m.tets = {{4, 6, 5, 8}};                  // left-handed
  return m;
}

TEST(GmshMsh, WrittenReadsBackInBothVersions) {
  const TetMesh m = sample();
  for (const GmshVersion v : {GmshVersion::v41, GmshVersion::v22}) {
    std::ostringstream out;
    write_gmsh(out, m, v, {{"q", {1, 2, 3, 4}, false}});
    const TetMesh back = read_gmsh(written("dartcheck-gmsh-roundtrip.msh", out.str()));
    EXPECT_EQ(back.points, m.points);  // shortest round-trip decimals
    EXPECT_EQ(back.hexes, m.hexes);    // right-handed already: kept
    EXPECT_EQ(back.prisms, m.prisms);
    EXPECT_EQ(back.pyramids, m.pyramids);
    // The left-handed tetrahedron mirrored (corners 1 and 2 swapped back).
    EXPECT_EQ(back.tets, (std::vector<std::array<std::uint32_t, 4>>{{4, 5, 6, 8}}));
    EXPECT_NE(out.str().find("$ElementData\n1\n\"q\"\n1\n0\n3\n0\n1\n4\n1 1\n2 2\n3 3\n4 4\n$EndElementData\n"), std::string::npos);
  }
}

// Property: in gmsh's convention every cell is positive at corner 0 (edges
// to corner 1, to the corner before 0 in its first face, to the first
// corner of the other face or the apex); VTK's is the same but the prism,
// negative. Checked on the sample's cells mirrored both ways.
TEST(GmshMsh, CellsTakeTheirFormatsHandedness) {
  TetMesh m = sample();
  TetMesh mirrored = m;
  for (auto& p : mirrored.points) p[2] = -p[2];  // a reflection: every cell turns left-handed
  for (const TetMesh* mesh : {&m, &mirrored})
    for (const CornerConvention c : {CornerConvention::gmsh, CornerConvention::vtk}) {
      const VolumeCells cells = volume_cells(*mesh, c);
      ASSERT_EQ(cells.size(), 4U);
      for (std::size_t k = 0; k < cells.size(); ++k) {
        const auto v = cells.corners(k);
        const auto& p = mesh->points;
        const std::size_t before = cells.kind[k] == CellKind::prism ? 2 : cells.kind[k] == CellKind::tetrahedron ? 2 : 3;
        const std::size_t other = cells.kind[k] == CellKind::tetrahedron ? 3 : cells.kind[k] == CellKind::prism ? 3 : 4;
        std::array<double, 3> a{}, b{}, d{};
        for (int i = 0; i < 3; ++i) {
          a[i] = p[v[1]][i] - p[v[0]][i];
          b[i] = p[v[before]][i] - p[v[0]][i];
          d[i] = p[v[other]][i] - p[v[0]][i];
        }
        const double det = (a[1] * b[2] - a[2] * b[1]) * d[0] + (a[2] * b[0] - a[0] * b[2]) * d[1] + (a[0] * b[1] - a[1] * b[0]) * d[2];
        const bool vtk_prism = c == CornerConvention::vtk && cells.kind[k] == CellKind::prism;
        EXPECT_EQ(det > 0, !vtk_prism) << name_of(cells.kind[k]);
      }
    }
}

TEST(GmshMsh, ErrorsArePositioned) {
  const std::string head = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n";
  const std::string nodes = "$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n$EndNodes\n";
  EXPECT_NE(message_of("$MeshFormat\n2.2 1 8\n"), "no error");
  EXPECT_NE(message_of("$MeshFormat\n2.2 1 8\n").find(":2:5: a binary .msh file"), std::string::npos) << message_of("$MeshFormat\n2.2 1 8\n");
  EXPECT_NE(message_of("$MeshFormat\n3.0 0 8\n$EndMeshFormat\n").find(":2:1: gmsh format 3.0: only 4.1 and 2.2 are read"), std::string::npos);
  EXPECT_NE(message_of(head + "$Elements\n0\n$EndElements\n").find(":4:1: $Elements before $Nodes"), std::string::npos);
  const std::string unknown = message_of(head + nodes + "$Elements\n1\n1 4 2 0 1 1 2 3 7\n$EndElements\n");
  EXPECT_NE(unknown.find(":13:17: node tag 7 is not in $Nodes"), std::string::npos) << unknown;
  const std::string repeated = message_of(head + nodes + "$Elements\n1\n1 4 2 0 1 1 2 3 2\n$EndElements\n");
  EXPECT_NE(repeated.find(":13:17: an element repeats node 2"), std::string::npos) << repeated;
  const std::string more = message_of(head + nodes + "$Elements\n1\n1 4 2 0 1 1 2 3 4\n2 4 2 0 1 1 2 3 4\n$EndElements\n");
  EXPECT_NE(more.find(":14:1: '2' where $EndElements was expected"), std::string::npos) << more;
  const std::string short_nodes = message_of(head + "$Nodes\n5\n1 0 0 0\n$EndNodes\n");
  EXPECT_NE(short_nodes.find(":7:1: expected a node tag, got '$EndNodes'"), std::string::npos) << short_nodes;
  EXPECT_NE(message_of(head + nodes).find("no tetrahedra, hexahedra, prisms or pyramids"), std::string::npos);
  // 4.1: a block holding more nodes than the header announces, an entity of no dimension.
  const std::string v41 = "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n";
  const std::string over = message_of(v41 + "$Nodes\n1 1 1 1\n3 1 0 2\n1\n2\n0 0 0\n1 0 0\n$EndNodes\n");
  EXPECT_NE(over.find(":6:7: the blocks hold more than the 1 nodes the header announces (line 5)"), std::string::npos) << over;
  const std::string dimension = message_of(v41 + "$Nodes\n1 1 1 1\n7 1 0 1\n1\n0 0 0\n$EndNodes\n");
  EXPECT_NE(dimension.find(":6:1: an entity of dimension 7 (0 to 3)"), std::string::npos) << dimension;
  EXPECT_NE(message_of("$Nodes\n").find(":1:1: a .msh file starts with $MeshFormat"), std::string::npos);
  // Boundary elements are skipped, tetrahedra of 10 nodes read by their first 4.
  const TetMesh m = read_gmsh(written("dartcheck-gmsh-tet10.msh",
                                      head + "$Nodes\n10\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n5 .5 0 0\n6 .5 .5 0\n7 0 .5 0\n8 0 0 .5\n9 0 .5 .5\n10 .5 0 .5\n"
                                             "$EndNodes\n$Elements\n2\n1 2 2 0 1 1 2 3\n2 11 2 0 1 1 2 3 4 5 6 7 8 9 10\n$EndElements\n"));
  EXPECT_EQ(m.tets, (std::vector<std::array<std::uint32_t, 4>>{{0, 1, 2, 3}}));
}

}  // namespace
}  // namespace dartcheck
