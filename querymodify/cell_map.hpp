// Polyhedral meshes as open 3-O-maps (001 Def. 1), for the volumes a 3D
// modeler or a voxel grid makes (001 Sec. 7.2-7.4): one dart per edge of
// each face of each cell, β1 around the face, β2 between the two faces of
// a cell along an edge, β3 between the faces two cells share (free on the
// boundary). Tetrahedral meshes have their own builder (tet_map.hpp),
// which orients tetrahedra by volume; here the caller orients the faces.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/map.hpp"
#include "core/polyhedron.hpp"

namespace dartcheck::querymodify {

// A cell is a Polyhedron (core/polyhedron.hpp): its faces, each a cycle of
// mesh vertices. Here the faces of one cell are oriented alike (all
// outward or all inward), so each edge of the cell is traversed once in
// each direction.

struct CellMap {
  Map map{Model::open_omap(3)};
  /// The mesh vertex each dart starts from.
  std::vector<std::uint32_t> vertex;
  /// The cell each dart belongs to.
  std::vector<std::uint32_t> cell;
};

/// A polyhedral mesh that makes no 3-map, with the cell that shows it.
struct CellMapError : std::invalid_argument {
  CellMapError(std::size_t c, const std::string& what) : std::invalid_argument(what), cell(c) {}
  std::size_t cell;
};

/// Builds the map, darts in the order of the cells, their faces and the
/// faces' vertices. Throws CellMapError on a face of fewer than 3 vertices
/// or with a repeated vertex, an edge of a cell not traversed exactly once
/// in each direction, a face (vertex set) in more than two cells, and two
/// cells traversing their shared face the same way (inconsistent
/// orientations). O(D log D) for D darts.
CellMap build_cell_map(const std::vector<Polyhedron>& cells);

}  // namespace dartcheck::querymodify
