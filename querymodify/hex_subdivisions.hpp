// The combinatorial subdivisions of the hexahedron into tetrahedra (001
// Sec. 7.1, after Pellerin, Verhetsel and Remacle 2018): the patterns the
// tet -> hex recombination looks for.
//
// A subdivision is a set of tetrahedra on the hex's 8 vertices that forms
// a simplicial 3-ball whose boundary is the hex surface with each quad
// split by one of its diagonals; no tetrahedron uses the 4 vertices of one
// face. Vertices are numbered by their corner of the unit cube, v = x + 2y
// + 4z, so the 48 symmetries of the cube act on them as permutations and
// reflections of the coordinate bits.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace dartcheck::querymodify {

/// A tetrahedron as the bit set of its 4 vertices (8 bits).
using TetMask = std::uint8_t;

/// The 64 tetrahedra a subdivision may use (4-subsets of the 8 vertices
/// that are not a face), in increasing mask order. A subdivision is a set
/// of them: bit k of a 64-bit word for candidate k.
const std::vector<TetMask>& candidate_tets();

/// The six quad faces as vertex cycles.
const std::array<std::array<int, 4>, 6>& hex_faces();

/// The 48 symmetries of the cube as vertex permutations; the first 24 are
/// the rotations (orientation-preserving).
const std::vector<std::array<int, 8>>& cube_symmetries();

/// Every subdivision, labeled (vertices fixed), in increasing order;
/// computed once (about 3 s of CPU, split between the cores) and kept.
const std::vector<std::uint64_t>& enumerate_hex_subdivisions();

/// The smallest image of a subdivision under the first `group_size`
/// symmetries (48: the full group, 24: rotations only).
std::uint64_t canonical_subdivision(std::uint64_t subdivision, int group_size = 48);

/// The tetrahedra of a subdivision.
std::vector<TetMask> tets_of(std::uint64_t subdivision);

/// True if the subdivision is a geometric triangulation of the unit
/// cube's vertices: every tetrahedron has positive volume, the volumes sum
/// to 1, and the two tetrahedra at each interior triangle lie on opposite
/// sides of it.
bool triangulates_unit_cube(std::uint64_t subdivision);

}  // namespace dartcheck::querymodify
