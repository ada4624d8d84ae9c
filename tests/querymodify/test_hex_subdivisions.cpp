// The subdivisions of the hexahedron into tetrahedra (001 Sec. 7.1). The
// expected counts are published ones, not the program's: Pellerin,
// Verhetsel and Remacle (2018) count 174 subdivisions up to the 48
// symmetries of the cube; the cube's vertices have 74 triangulations
// (De Loera, Rambau, Santos, "Triangulations", the 3-cube), 6 up to
// symmetry: one with 5 tetrahedra and five with 6.
#include <gtest/gtest.h>

#include <map>
#include <set>

#include "querymodify/hex_queries.hpp"
#include "querymodify/hex_subdivisions.hpp"

namespace dartcheck::querymodify {
namespace {

TEST(HexSubdivisions, CandidatesAndSymmetries) {
  EXPECT_EQ(candidate_tets().size(), 64u);  // C(8,4) = 70 minus the 6 faces
  const auto& g = cube_symmetries();
  ASSERT_EQ(g.size(), 48u);
  std::set<std::array<int, 8>> distinct(g.begin(), g.end());
  EXPECT_EQ(distinct.size(), 48u);
  // Every symmetry maps faces to faces.
  for (const auto& p : g)
    for (const auto& f : hex_faces()) {
      std::set<int> image;
      for (int v : f) image.insert(p[static_cast<std::size_t>(v)]);
      bool is_face = false;
      for (const auto& h : hex_faces()) is_face |= image == std::set<int>(h.begin(), h.end());
      EXPECT_TRUE(is_face);
    }
}

// The table compiled at build time (what the queries are built from) is
// the enumeration, entry for entry.
TEST(HexSubdivisions, BuildTimeTableIsTheEnumeration) { EXPECT_EQ(labeled_hex_subdivisions(), enumerate_hex_subdivisions()); }

TEST(HexSubdivisions, PublishedCounts) {
  const auto all = enumerate_hex_subdivisions();
  std::set<std::uint64_t> classes, chiral_classes;
  std::set<std::uint64_t> cube_triangulations, cube_classes;
  std::map<std::size_t, std::size_t> cube_sizes;
  for (auto s : all) {
    classes.insert(canonical_subdivision(s));
    chiral_classes.insert(canonical_subdivision(s, 24));
    if (triangulates_unit_cube(s)) {
      cube_triangulations.insert(s);
      if (cube_classes.insert(canonical_subdivision(s)).second) ++cube_sizes[tets_of(s).size()];
    }
  }
  EXPECT_EQ(classes.size(), 174u);
  EXPECT_EQ(cube_triangulations.size(), 74u);
  EXPECT_EQ(cube_classes.size(), 6u);
  EXPECT_EQ(cube_sizes[5], 1u);
  EXPECT_EQ(cube_sizes[6], 5u);
  std::cerr << "labeled subdivisions " << all.size() << ", classes under rotations only " << chiral_classes.size() << "\n";
}

}  // namespace
}  // namespace dartcheck::querymodify
