// How the cells of a hex-dominant recombination meet (recombine --cells
// with --conforming): hex_contacts.hpp's rule for any two cells, hexes,
// prisms or pyramids. A conforming mesh has two cells share nothing, a
// vertex, an edge of both or a face of both (a triangle of both, or a
// quad of both).
#pragma once

#include <cstdint>
#include <span>

#include "querymodify/cell_subdivisions.hpp"

namespace dartcheck::querymodify {

/// The hexahedron as a CellShape: corners v = x + 2y + 4z, faces
/// hex_faces().
const CellShape& hex_shape();

/// True when the vertices cells `a` (of shape `as`, the mesh vertex at each
/// corner) and `b` share are none, one, the two ends of an edge of both,
/// or the corners of a face of both.
bool conforming_contact(std::span<const std::uint32_t> a, const CellShape& as, std::span<const std::uint32_t> b, const CellShape& bs);

}  // namespace dartcheck::querymodify
