#include "io/volume_mesh_writer.hpp"

#include <filesystem>
#include <sstream>

#include "io/vtk_writer.hpp"

namespace dartcheck {

const char* const volume_mesh_outputs = ".mesh (medit), .vtu, .vtk (VTK) or .msh (gmsh)";

bool is_volume_mesh_output(const std::string& path) {
  const std::string e = std::filesystem::path(path).extension().string();
  return e == ".mesh" || e == ".vtu" || e == ".vtk" || e == ".msh";
}

std::string volume_mesh_text(const TetMesh& m, const std::string& path, const std::vector<CellField>& fields, GmshVersion gmsh) {
  const std::string e = std::filesystem::path(path).extension().string();
  std::ostringstream out;
  if (e == ".vtu")
    write_vtu(out, m, fields);
  else if (e == ".vtk")
    write_legacy_vtk(out, m, fields);
  else if (e == ".msh")
    write_gmsh(out, m, gmsh, fields);
  else
    write_medit(out, m);
  return out.str();
}

}  // namespace dartcheck
