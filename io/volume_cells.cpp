#include "io/volume_cells.hpp"

#include "core/error.hpp"

#include <algorithm>
#include <array>
#include <stdexcept>

#include <fmt/format.h>

namespace dartcheck {
namespace {

// The sign of (b - a) x (c - a) . (d - a) in floating point: the writers'
// choice of mirror, not a predicate any verdict rests on.
int handedness(const std::vector<std::array<double, 3>>& p, std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) {
  std::array<double, 3> u{}, v{}, w{};
  for (int i = 0; i < 3; ++i) {
    u[i] = p[b][i] - p[a][i];
    v[i] = p[c][i] - p[a][i];
    w[i] = p[d][i] - p[a][i];
  }
  const double det = (u[1] * v[2] - u[2] * v[1]) * w[0] + (u[2] * v[0] - u[0] * v[2]) * w[1] + (u[0] * v[1] - u[1] * v[0]) * w[2];
  return (det > 0) - (det < 0);
}

template <std::size_t N>
void add(VolumeCells& out, CellKind kind, const std::array<std::uint32_t, N>& c, int sign, int wanted, const std::array<int, N>& mirror) {
  out.kind.push_back(kind);
  for (std::size_t j = 0; j < N; ++j) out.connectivity.push_back(sign == -wanted ? c[static_cast<std::size_t>(mirror[j])] : c[j]);
  out.offset.push_back(static_cast<std::uint32_t>(out.connectivity.size()));
}

}  // namespace

VolumeCells volume_cells(const TetMesh& m, CornerConvention convention) {
  VolumeCells out;
  const auto& p = m.points;
  for (const auto& c : m.hexes) add(out, CellKind::hexahedron, c, handedness(p, c[0], c[1], c[3], c[4]), 1, {0, 3, 2, 1, 4, 7, 6, 5});
  const int prism_sign = convention == CornerConvention::gmsh ? 1 : -1;
  for (const auto& c : m.prisms) add(out, CellKind::prism, c, handedness(p, c[0], c[1], c[2], c[3]), prism_sign, {0, 2, 1, 3, 5, 4});
  for (const auto& c : m.pyramids) add(out, CellKind::pyramid, c, handedness(p, c[0], c[1], c[3], c[4]), 1, {0, 3, 2, 1, 4});
  for (const auto& c : m.tets) add(out, CellKind::tetrahedron, c, handedness(p, c[0], c[1], c[2], c[3]), 1, {0, 2, 1, 3});
  return out;
}

VolumeCells polygon_cells(const std::vector<std::vector<std::uint32_t>>& faces) {
  VolumeCells out;
  for (const auto& f : faces) {
    if (f.size() < 3) throw InternalError(fmt::format("a face of {} corners", f.size()));
    out.kind.push_back(f.size() == 3 ? CellKind::triangle : f.size() == 4 ? CellKind::quadrangle : CellKind::polygon);
    out.connectivity.insert(out.connectivity.end(), f.begin(), f.end());
    out.offset.push_back(static_cast<std::uint32_t>(out.connectivity.size()));
  }
  return out;
}

int gmsh_type(CellKind k) {
  static constexpr int types[] = {5, 6, 7, 4, 2, 3, 0};
  return types[static_cast<int>(k)];
}
int vtk_type(CellKind k) {
  static constexpr int types[] = {12, 13, 14, 10, 5, 9, 7};
  return types[static_cast<int>(k)];
}
const char* name_of(CellKind k) {
  static constexpr const char* names[] = {"hexahedron", "prism", "pyramid", "tetrahedron", "triangle", "quadrangle", "polygon"};
  return names[static_cast<int>(k)];
}

}  // namespace dartcheck
