// The prism and the pyramid and their subdivisions into tetrahedra: the
// other cells of a hex-dominant mesh (gmsh's hex + prism + pyramid mode),
// recombined from tetrahedra the way 001 Sec. 7.1 recombines hexahedra.
//
// A subdivision is a set of tetrahedra on the cell's corners that forms a
// simplicial 3-ball whose boundary is the cell's surface with each quad
// split by one of its diagonals (hex_subdivisions.hpp's definition, for
// cells small enough to enumerate every set of tetrahedra). Every corner
// is on the boundary, so there is no inner vertex. Corners:
//   prism    0 1 2 one triangle, 3 4 5 the other, corner i + 3 joined to i;
//            quads (0 1 4 3), (1 2 5 4), (2 0 3 5);
//   pyramid  0 1 2 3 the base quad as a cycle, 4 the apex.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

namespace dartcheck::querymodify {

/// A convex cell with every corner on its boundary: its faces as corner
/// cycles (triangles and quads).
struct CellShape {
  std::string_view name;
  int corners = 0;
  std::vector<std::vector<int>> faces;
  /// The corner permutations that map faces onto faces (prism 12, pyramid
  /// 8), the identity first.
  std::vector<std::vector<int>> symmetries;
};

const CellShape& prism_shape();
const CellShape& pyramid_shape();

/// A tetrahedron as the bit set of its 4 corners.
using CellTet = std::uint8_t;

/// Every labeled subdivision of `cell` (corners fixed), each as its
/// tetrahedra in increasing mask order; the sets of tetrahedra are tried
/// one by one (at most 2^12 for the prism), so the list is complete.
std::vector<std::vector<CellTet>> enumerate_cell_subdivisions(const CellShape& cell);

/// The diagonals a subdivision splits the quads by: bit q (q-th quad of
/// `cell.faces`) set when it is split by the quad's corners 1-3 rather
/// than 0-2.
unsigned cell_subdivision_diagonals(const CellShape& cell, std::span<const CellTet> subdivision);

/// How a set of tetrahedra on k mesh vertices reads as a cell: the set is
/// given by local masks, bit i for the i-th smallest of its k vertices.
/// Each reading gives the local vertex at every corner; readings that
/// differ by a symmetry of the cell are given once.
class CellReadings {
 public:
  explicit CellReadings(const CellShape& cell);
  /// The readings of a set of tetrahedra (local masks, any order); empty
  /// when it is no subdivision of the cell.
  std::span<const std::array<std::uint8_t, 6>> of(std::span<const CellTet> tets) const;
  const CellShape& cell() const { return *cell_; }

 private:
  const CellShape* cell_;
  // Key: bit m set for each local mask m (k <= 6, so m < 64); sorted, with
  // the reading of each entry beside it.
  std::vector<std::uint64_t> keys_;
  std::vector<std::array<std::uint8_t, 6>> readings_;
};

const CellReadings& prism_readings();
const CellReadings& pyramid_readings();

}  // namespace dartcheck::querymodify
