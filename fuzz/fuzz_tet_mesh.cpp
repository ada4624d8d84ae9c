// Tetrahedral meshes (io/tet_mesh_io): medit .mesh, gmsh .msh (an input
// starting "$MeshFormat"), and TetGen .node/.ele pairs (the input is split
// at the first line "%%": the .node text, then the .ele text). A medit
// mesh that reads is written back (write_medit) and must read back equal:
// points bit for bit, tetrahedra and hexahedra; a gmsh mesh is written in
// both versions and must read back with the same points and the same
// cells once each is given gmsh's handedness (the writer mirrors
// left-handed ones).
#include <sstream>
#include <stdexcept>
#include <string>

#include "core/input_error.hpp"
#include "fuzz/harness.hpp"
#include "io/gmsh_msh.hpp"
#include "io/tet_mesh_io.hpp"
#include "io/volume_cells.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace dartcheck;
  const std::string_view text = fuzzing::as_text(data, size);
  try {
    const auto split = text.find("\n%%\n");
    if (text.starts_with("$MeshFormat")) {
      const TetMesh m = read_gmsh(fuzzing::input_file(data, size, ".msh"));
      const VolumeCells cells = volume_cells(m, CornerConvention::gmsh);
      for (const GmshVersion v : {GmshVersion::v41, GmshVersion::v22}) {
        std::ostringstream out;
        write_gmsh(out, m, v);
        const std::string written = out.str();
        const TetMesh back = read_gmsh(fuzzing::input_file(reinterpret_cast<const std::uint8_t*>(written.data()), written.size(), ".msh"));
        if (back.points != m.points || volume_cells(back, CornerConvention::gmsh).connectivity != cells.connectivity)
          throw std::logic_error("write_gmsh does not read back");
      }
    } else if (split == std::string_view::npos) {
      const TetMesh m = read_medit(fuzzing::input_file(data, size, ".mesh"));
      std::ostringstream out;
      write_medit(out, m);
      const std::string written = out.str();
      const TetMesh back = read_medit(fuzzing::input_file(reinterpret_cast<const std::uint8_t*>(written.data()), written.size(), ".mesh"));
      if (back.points != m.points || back.tets != m.tets || back.hexes != m.hexes) throw std::logic_error("write_medit does not read back");
    } else {
      const std::string node = fuzzing::input_file(data, split + 1, ".node");
      const std::string ele = node.substr(0, node.size() - 5) + ".ele";
      const std::string_view rest = text.substr(split + 4);
      std::ofstream(ele, std::ios::binary | std::ios::trunc).write(rest.data(), static_cast<std::streamsize>(rest.size()));
      (void)read_tetgen(node);
    }
  } catch (const InputError&) {
  }
  return 0;
}
