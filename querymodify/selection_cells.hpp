// A query's selection as cell data of the tetrahedral mesh it was found
// in, so that ParaView or gmsh can colour the tetrahedra each match
// covers (`dartcheck query MESH ... -o sel.vtu`).
#pragma once

#include <cstddef>
#include <vector>

#include "core/error.hpp"
#include "io/volume_cells.hpp"
#include "querymodify/annotation.hpp"

namespace dartcheck::querymodify {

/// Three fields over the `tetrahedra` of a tetrahedral mesh's map (12 darts
/// per tetrahedron, tet_map.hpp), from the matched darts of `matches`:
/// `match`, the index in `matches` of the first match with a dart in the
/// tetrahedron (-1: none); `query`, that match's query (-1: none);
/// `matches`, how many matches have a dart in it (more than one only where
/// the matches overlap, as `--strategy all` shows them). Throws
/// InternalError for a dart outside the map (a caller's defect).
std::vector<CellField> selection_fields(std::size_t tetrahedra, const std::vector<QueryMatch>& matches);

}  // namespace dartcheck::querymodify
