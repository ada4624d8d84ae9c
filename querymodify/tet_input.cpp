#include "querymodify/tet_input.hpp"

#include <filesystem>

#include <fmt/format.h>

#include "core/input_error.hpp"
#include "core/limits.hpp"

namespace dartcheck::querymodify {

TetInput load_tet_input(const std::string& path) {
  TetInput in;
  in.mesh = read_tet_mesh(path);
  // TetGen's tetrahedra are in the .ele file whichever file was named.
  std::string tet_file = path;
  if (std::filesystem::path(path).extension() == ".node") tet_file = std::filesystem::path(path).replace_extension(".ele").string();
  auto line_of = [&](std::size_t t) { return t < in.mesh.tet_lines.size() ? in.mesh.tet_lines[t] : 0; };
  if (in.mesh.tets.empty()) throw InputError(path, 0, 0, "the mesh has no tetrahedra");
  // Its other cells would not reach the output: refused, not dropped.
  if (const std::size_t other = in.mesh.hexes.size() + in.mesh.prisms.size() + in.mesh.pyramids.size(); other > 0)
    throw InputError(path, 0, 0,
                     fmt::format("the mesh has {} hexahedra, {} prisms and {} pyramids besides its tetrahedra; only tetrahedral meshes are recombined",
                                 in.mesh.hexes.size(), in.mesh.prisms.size(), in.mesh.pyramids.size()));
  const std::size_t most_tets = limits().darts / 12;
  if (in.mesh.tets.size() > most_tets)
    throw InputError(tet_file, line_of(most_tets), 1, over_limit("darts", 12 * in.mesh.tets.size(), limits().darts, "--limit-darts"));
  try {
    in.map = build_tet_map(in.mesh.tets, &in.mesh.points, in.mesh.numbered_from);
  } catch (const BuildError& e) {
    throw InputError(tet_file, e.culprit() == BuildError::Culprit::cell ? line_of(e.index()) : 0, 1, e.what());
  }
  return in;
}

}  // namespace dartcheck::querymodify
