#include "querymodify/hex_quality.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "querymodify/orientation.hpp"

namespace dartcheck::querymodify {

namespace {

using Corners = std::array<std::array<double, 3>, 8>;

// The floating-point value, and the hex's handedness (+1: corners
// positive). Computed so that every reading of one hexahedron under a
// symmetry of the cube gives the same bits: at each corner the three edges
// are taken in the order of their far ends' points (the parity of that
// order is exact) and the corners are summed in the order of their points.
// Without it the two searches (hex_search.hpp) could read one hex at -0
// and at 1e-16.
std::pair<double, int> float_jacobian(const Corners& p) {
  std::array<int, 8> by_point{0, 1, 2, 3, 4, 5, 6, 7};
  std::sort(by_point.begin(), by_point.end(), [&](int a, int b) { return p[static_cast<std::size_t>(a)] < p[static_cast<std::size_t>(b)]; });
  std::array<double, 8> value{};
  for (int v = 0; v < 8; ++v) {
    std::array<int, 3> axes{0, 1, 2};
    auto far = [&](int axis) { return p[static_cast<std::size_t>(v ^ (1 << axis))]; };
    // Sorted by insertion; each swap flips the determinant's sign.
    double parity = 1;
    for (int i = 1; i < 3; ++i)
      for (int j = i; j > 0 && far(axes[static_cast<std::size_t>(j)]) < far(axes[static_cast<std::size_t>(j - 1)]); --j) {
        std::swap(axes[static_cast<std::size_t>(j)], axes[static_cast<std::size_t>(j - 1)]);
        parity = -parity;
      }
    double e[3][3];
    for (int k = 0; k < 3; ++k) {
      const int axis = axes[static_cast<std::size_t>(k)];
      const double sign = (v >> axis) & 1 ? -1.0 : 1.0;  // always along +axis
      for (std::size_t c = 0; c < 3; ++c) e[k][c] = sign * (far(axis)[c] - p[static_cast<std::size_t>(v)][c]);
    }
    const double det = e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) - e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
                       e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]);
    double len = 1;
    for (auto& x : e) len *= std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
    value[static_cast<std::size_t>(v)] = len > 0 ? parity * det / len : 0;
  }
  double sum = 0, lo = 1e300, hi = -1e300;
  for (int v : by_point) {
    const double j = value[static_cast<std::size_t>(v)];
    sum += j;
    lo = std::min(lo, j);
    hi = std::max(hi, j);
  }
  return sum >= 0 ? std::pair{lo, 1} : std::pair{-hi, -1};
}

// Every corner's determinant has the hex's sign, exactly.
bool corners_exact(const Corners& p, int handedness) {
  for (int v = 0; v < 8; ++v) {
    int sign = handedness;
    for (int axis = 0; axis < 3; ++axis) sign *= (v >> axis) & 1 ? -1 : 1;
    const auto& x = p[static_cast<std::size_t>(v ^ 1)];
    const auto& y = p[static_cast<std::size_t>(v ^ 2)];
    const auto& z = p[static_cast<std::size_t>(v ^ 4)];
    if (orientation_sign(x, y, z, p[static_cast<std::size_t>(v)]) != sign) return false;
  }
  return true;
}

}  // namespace

double scaled_jacobian_estimate(const Corners& p) { return float_jacobian(p).first; }

double scaled_jacobian(const Corners& p) {
  const auto [quality, handedness] = float_jacobian(p);
  // Positive in floating point: every corner must also be oriented the
  // hex's way exactly, or the hex is numerically flat or inverted there.
  if (quality > 0 && !corners_exact(p, handedness)) return 0.0;
  return quality;
}

Corners corner_points(const std::array<std::uint32_t, 8>& corners, const std::vector<std::array<double, 3>>& points) {
  Corners p{};
  for (std::size_t v = 0; v < 8; ++v) p[v] = points[corners[v]];
  return p;
}

std::array<std::uint32_t, 8> right_handed(const std::array<std::uint32_t, 8>& corners, const std::vector<std::array<double, 3>>& points) {
  auto at = [&](std::size_t v) { return points[corners[v]]; };
  double u[3], v[3], w[3];
  for (int k = 0; k < 3; ++k) u[k] = at(1)[k] - at(0)[k], v[k] = at(2)[k] - at(0)[k], w[k] = at(4)[k] - at(0)[k];
  const double det = u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) + u[2] * (v[0] * w[1] - v[1] * w[0]);
  if (det >= 0) return corners;
  std::array<std::uint32_t, 8> mirrored{};
  for (std::size_t k = 0; k < 8; ++k) mirrored[k] = corners[k ^ 1];
  return mirrored;
}

}  // namespace dartcheck::querymodify
