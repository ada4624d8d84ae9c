// Tetrahedral meshes as open 3-O-maps (001 Def. 1): 12 darts per
// tetrahedron, 3 per triangular face; β1 turns around a face, β2 joins the
// two faces of a tetrahedron along an edge, β3 the faces two tetrahedra
// share (free on the boundary). Dart 12t + 3f + j of tetrahedron t goes
// from the j-th to the (j+1)-th vertex of its face f.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "core/cell_gluing.hpp"

namespace dartcheck::querymodify {

struct TetMap {
  Map map{Model::open_omap(3)};
  /// The mesh vertex each dart starts from.
  std::vector<std::uint32_t> vertex;
  /// The tetrahedra as oriented (positive volume, or a consistent
  /// combinatorial orientation when no points are given).
  std::vector<std::array<std::uint32_t, 4>> tets;
};

/// Builds the map. With `points`, each tetrahedron is oriented by the sign
/// of its volume (throws on a flat one, and on two tetrahedra on the same
/// side of their shared face); without, orientations are propagated
/// across shared faces (throws if the mesh is not orientable). Throws
/// when a face is shared by more than two tetrahedra. Throws BuildError
/// naming the tetrahedron (Culprit::cell, its index in the input); the
/// map is glued by glue_cells (core/cell_gluing.hpp). Messages name
/// vertices and tetrahedra as index + `numbered_from`: as the file numbers
/// them (medit from 1, TetGen from its first index).
/// O(T log T) for T tetrahedra.
TetMap build_tet_map(const std::vector<std::array<std::uint32_t, 4>>& tets, const std::vector<std::array<double, 3>>* points = nullptr,
                     std::uint32_t numbered_from = 0);

}  // namespace dartcheck::querymodify
