// The cells of a volume mesh (TetMesh: hexahedra, prisms, pyramids and
// tetrahedra) as one list, in the order every mesh writer numbers them
// (hexahedra, prisms, pyramids, tetrahedra), each cell's corners in a
// file format's convention: gmsh's and VTK's agree on the corner order
// of each kind (a bottom face, then the vertices above it, or the apex)
// and on the handedness of all but the prism, whose first triangle's
// normal points at the other triangle in gmsh and away from it in VTK.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "core/formatting.hpp"
#include "io/tet_mesh_io.hpp"

namespace dartcheck {

// The faces of a polygon mesh (apply's result on a surface) are cells too:
// triangles, quadrangles and larger polygons.
enum class CellKind : std::uint8_t { hexahedron, prism, pyramid, tetrahedron, triangle, quadrangle, polygon };
enum class CornerConvention { gmsh, vtk };

using Points = std::vector<std::array<double, 3>>;

struct VolumeCells {
  std::vector<CellKind> kind;
  std::vector<std::uint32_t> offset{0};  // cell k's corners: connectivity[offset[k], offset[k+1])
  std::vector<std::uint32_t> connectivity;
  std::size_t size() const { return kind.size(); }
  std::span<const std::uint32_t> corners(std::size_t k) const { return {connectivity.data() + offset[k], connectivity.data() + offset[k + 1]}; }
};

/// One value per cell, in writing order (a scaled Jacobian, a cell kind),
/// which the VTK and gmsh writers carry as cell data.
struct CellField {
  std::string name;
  std::vector<double> values;
  bool integer = false;  // written as Int32 (legacy VTK: int)
};

/// The cells of `m` in writing order, each mirrored where its handedness
/// (the sign of the volume spanned at corner 0 by its edges to corners 1,
/// the corner before it in its first face, and the first corner of the
/// other face or the apex) is not the convention's; a flat cell is kept as
/// it is.
VolumeCells volume_cells(const TetMesh& m, CornerConvention convention);

/// A polygon mesh's faces as cells: each face's corners in its order, the
/// kind from their number (at least 3; fewer is a caller's defect,
/// InternalError).
VolumeCells polygon_cells(const std::vector<std::vector<std::uint32_t>>& faces);

/// gmsh's element type (5, 6, 7, 4, 2, 3; 0 for a polygon, which gmsh
/// has no element for) and VTK's cell type (12, 13, 14, 10, 5, 9, 7).
int gmsh_type(CellKind k);
int vtk_type(CellKind k);
/// "hexahedron", "prism", "pyramid", "tetrahedron", "triangle", ...
const char* name_of(CellKind k);

}  // namespace dartcheck
