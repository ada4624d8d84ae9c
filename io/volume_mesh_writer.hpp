// A volume mesh written in the format its file name asks for: medit .mesh,
// VTK XML .vtu, legacy VTK .vtk, gmsh .msh (4.1, or 2.2 on request).
#pragma once

#include <string>
#include <vector>

#include "io/gmsh_msh.hpp"
#include "io/volume_cells.hpp"

namespace dartcheck {

/// Whether `path` ends in one of the extensions above.
bool is_volume_mesh_output(const std::string& path);
/// The extensions, for messages: ".mesh (medit), .vtu, .vtk (VTK) or .msh (gmsh)".
extern const char* const volume_mesh_outputs;

/// The file's text; `fields` go along where the format carries cell data
/// (VTK, gmsh; medit has none).
std::string volume_mesh_text(const TetMesh& m, const std::string& path, const std::vector<CellField>& fields = {},
                             GmshVersion gmsh = GmshVersion::v41);

}  // namespace dartcheck
