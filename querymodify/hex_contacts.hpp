// How two hexahedra of a recombined mesh meet. A hex-dominant mesh for a
// solver must be conforming: two hexes share nothing, a vertex, a whole
// edge or a whole quad face of both. 001's recombination needs no such
// thing (a merged hex keeps its boundary triangles, so two hexes may
// share one triangle of a quad, or a face diagonal), and gmsh's
// recombinator requires it; `recombine --conforming` selects only hexes
// that meet the ones already selected this way.
#pragma once

#include <array>
#include <cstdint>

namespace dartcheck::querymodify {

/// The mesh vertex at each cube corner (v = x + 2y + 4z).
using HexCorners = std::array<std::uint32_t, 8>;

/// True when the vertices `a` and `b` share are none, one, the two ends of
/// an edge of both, or the four corners of a face of both; false for any
/// other contact (three vertices, a face diagonal, a face of one only...).
bool conforming_contact(const HexCorners& a, const HexCorners& b);

}  // namespace dartcheck::querymodify
