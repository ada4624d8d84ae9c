// gmsh's .msh meshes, ASCII: read (format 4.1 and 2.2) as the input of the
// tet -> hex recombination, and written (4.1 by default, 2.2 for older
// tools) with the recombination's cells.
//
// Reading keeps the volume elements: tetrahedra (type 4, and the first 4
// nodes of type 11), hexahedra (5; 12 and 17 by their first 8 nodes),
// prisms (6; 13, 18) and pyramids (7; 14, 19); points, lines, triangles and
// quadrangles (the boundary gmsh writes with the volume) are skipped, and
// so are the sections other than $MeshFormat, $Nodes and $Elements. Points
// are the nodes in the order of $Nodes, so a vertex is named by its
// position there from 1 (gmsh's own tags when they run 1..N, as gmsh
// writes them). Every error is an InputError with file:line:column: a
// binary file, a version other than 2.2 or 4.x, a count that does not
// match the data, an unknown node tag, a tetrahedron repeating a vertex.
#pragma once

#include <ostream>
#include <string>

#include "core/error.hpp"
#include "io/tet_mesh_io.hpp"
#include "io/volume_cells.hpp"

namespace dartcheck {

TetMesh read_gmsh(const std::string& file);

/// gmsh's versions written: 4.1 (one volume entity, node and element tags
/// from 1) and 2.2.
enum class GmshVersion { v41, v22 };

/// Writes the points and the cells of `m`, each block in gmsh's corner
/// order (which for hexahedra, prisms and pyramids is medit's, that of
/// TetMesh): hexahedra, prisms, pyramids, then tetrahedra, element tags
/// from 1 in that order (write_vtu numbers its cells the same way); each
/// field as an $ElementData view. Throws InternalError when a field has
/// not one value per cell.
void write_gmsh(std::ostream& out, const TetMesh& m, GmshVersion version = GmshVersion::v41, const std::vector<CellField>& fields = {});
/// The same for any cells over `points` in gmsh's corner order, in one
/// entity of `dimension` (2 for a polygon mesh's faces, 3 for volumes).
/// Throws InternalError for a polygon of more than 4 corners, which
/// gmsh has no element for (callers refuse it first).
void write_gmsh(std::ostream& out, const Points& points, const VolumeCells& cells, int dimension, GmshVersion version = GmshVersion::v41,
                const std::vector<CellField>& fields = {});

}  // namespace dartcheck
