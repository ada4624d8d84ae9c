// Volume and polygon meshes as VTK files, which ParaView and VisIt open: the XML
// unstructured grid (.vtu) and the legacy format (.vtk), ASCII. Cells are
// numbered as every mesh writer numbers them (io/volume_cells.hpp:
// hexahedra, prisms, pyramids, tetrahedra) with VTK's corner conventions;
// per-cell values go along as cell data.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "io/volume_cells.hpp"

namespace dartcheck {

/// Throws InternalError when a field has not one value per cell
/// (a caller's defect: the fields are computed from the same mesh).
void write_vtu(std::ostream& out, const TetMesh& m, const std::vector<CellField>& fields = {});
void write_legacy_vtk(std::ostream& out, const TetMesh& m, const std::vector<CellField>& fields = {});
/// The same for any cells over `points` (a polygon mesh's faces), given in
/// VTK's corner order.
void write_vtu(std::ostream& out, const Points& points, const VolumeCells& cells, const std::vector<CellField>& fields = {});
void write_legacy_vtk(std::ostream& out, const Points& points, const VolumeCells& cells, const std::vector<CellField>& fields = {});

}  // namespace dartcheck
