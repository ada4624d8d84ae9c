// The quality of a recombined volume mesh, cell by cell and as a whole:
// the scaled Jacobian of every cell (hex_quality.hpp, cell_quality.hpp, and
// the tetrahedron's here), its distribution over the recombined cells, and
// the share of the volume each kind of cell fills. What a user reads
// before trusting a mesh to a solver: a minimum alone hides how many cells
// are poor, and a hex count hides how much of the volume they fill.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "io/tet_mesh_io.hpp"
#include "io/volume_cells.hpp"

namespace dartcheck::querymodify {

/// The scaled Jacobian of a tetrahedron: at each corner, the determinant of
/// its three edges over the product of their lengths, times sqrt(2) so that
/// the regular tetrahedron scores 1; the minimum over the 4 corners, of
/// either handedness (0 for a flat one).
double tet_quality(const std::array<std::array<double, 3>, 4>& corner);

/// The scaled Jacobian of every cell of `m`, in writing order
/// (volume_cells: hexahedra, prisms, pyramids, tetrahedra).
std::vector<double> cell_qualities(const TetMesh& m);

/// A scaled Jacobian below this is poor for a simulation (a common rule
/// of thumb of mesh generators); recombined cells under it are warned of.
inline constexpr double poor_quality = 0.2;

struct QualitySummary {
  /// Of the recombined cells (hexahedra, prisms, pyramids): how many, and
  /// the quantiles of their scaled Jacobian (min, 5%, 25%, median, 75%,
  /// 95%, max; NaN without cells), by the nearest rank.
  std::size_t cells = 0;
  std::array<double, 7> quantiles{};
  /// Their histogram: below 0 (inverted), then [0, 0.1), [0.1, 0.2), ...,
  /// [0.9, +inf) (a pyramid taller than the equilateral one scores up to
  /// sqrt(2)).
  std::array<std::size_t, 11> histogram{};
  /// Recombined cells under poor_quality.
  std::size_t poor = 0;
  /// The share of the mesh's volume in hexahedra, prisms, pyramids and
  /// tetrahedra (each cell's volume from its tetrahedra: a hex split into
  /// 6, a prism into 3, a pyramid into 2 around a diagonal).
  std::array<double, 4> volume_share{};
};
/// `quality`: cell_qualities(m).
QualitySummary summarize_quality(const TetMesh& m, const std::vector<double>& quality);

/// The quantiles' names ("min", "p05", "p25", "median", "p75", "p95", "max")
/// and the histogram bins' labels ("< 0", "[0, 0.1)", ..., ">= 0.9").
extern const std::array<const char*, 7> quantile_names;
extern const std::array<const char*, 11> histogram_labels;

}  // namespace dartcheck::querymodify
