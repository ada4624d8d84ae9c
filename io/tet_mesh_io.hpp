// Tetrahedral meshes: TetGen's .node/.ele pair and medit's .mesh (the
// inputs of the tet -> hex recombination, 001 Sec. 7.1). Every error is an
// InputError with file:line:column: a bad header, a non-numeric token, an
// index out of range, a tetrahedron that repeats a vertex, a file that ends
// early.
#pragma once

#include <array>
#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

namespace dartcheck {

struct TetMesh {
  std::string file;
  std::vector<std::array<double, 3>> points;
  std::vector<std::array<std::uint32_t, 4>> tets;  // 0-based point indices
  std::vector<int> tet_lines;                      // 1-based line of each tetrahedron
  std::uint32_t numbered_from = 0;                 // the file's first vertex and tetrahedron number (medit 1, TetGen 0 or 1)
  /// medit's Hexahedra (0-based, medit order: a bottom quad, then the top
  /// quad above it vertex by vertex). Read, not used by the tet readers'
  /// callers; written by the recombination.
  std::vector<std::array<std::uint32_t, 8>> hexes;
  /// medit's Prisms (a triangle, then the triangle above it vertex by
  /// vertex) and Pyramids (the base quad as a cycle, then the apex), the
  /// other cells of a hex-dominant recombination.
  std::vector<std::array<std::uint32_t, 6>> prisms;
  std::vector<std::array<std::uint32_t, 5>> pyramids;
};

/// TetGen: `file` is the .node or the .ele file; the other one has the
/// same base name. Indices may start at 0 or 1 (the first point's index
/// says which). Only the first 4 nodes of 10-node elements are read.
TetMesh read_tetgen(const std::string& file);
/// medit .mesh (ASCII): Vertices, Tetrahedra, Hexahedra, Prisms and
/// Pyramids sections, 1-based; other sections are skipped by their counts.
TetMesh read_medit(const std::string& file);
/// medit .mesh (ASCII, MeshVersionFormatted 1): Vertices, Tetrahedra,
/// Hexahedra, Prisms and Pyramids (each written only when not empty),
/// reference 0 everywhere.
void write_medit(std::ostream& out, const TetMesh& m);
/// By extension: .node, .ele, .mesh, .msh (gmsh, io/gmsh_msh.hpp).
TetMesh read_tet_mesh(const std::string& file);
bool is_tet_mesh_path(const std::string& file);

}  // namespace dartcheck
