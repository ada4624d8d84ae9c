// Tetrahedral mesh files as maps (recombine, query): read, checked
// against --limit-darts, and built into an open 3-O-map, every error at
// file:line:column of the mesh.
#pragma once

#include <string>

#include "io/tet_mesh_io.hpp"
#include "querymodify/tet_map.hpp"

namespace dartcheck::querymodify {

struct TetInput {
  TetMesh mesh;
  TetMap map;
};

/// Reads a .node/.ele/.mesh file and builds its map, tetrahedra oriented
/// by their points' volume. Throws InputError.
TetInput load_tet_input(const std::string& path);

}  // namespace dartcheck::querymodify
