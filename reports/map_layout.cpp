#include "reports/map_layout.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/orbit.hpp"

namespace dartcheck::reports {
namespace {

using P3 = std::array<double, 3>;

// The mean of the points of d's orbit under `generators`.
P3 centre(OrbitWalker& walker, Dart d, std::span<const OrbitWord> generators, const std::vector<P3>& points) {
  P3 c{0, 0, 0};
  const auto& orbit = walker.orbit(d, generators);
  for (Dart x : orbit)
    for (int k = 0; k < 3; ++k) c[k] += points[x][k];
  for (double& x : c) x /= static_cast<double>(orbit.size());
  return c;
}

}  // namespace

std::vector<std::array<double, 2>> exploded_layout(const Map& map, const std::vector<P3>& points, double max_inches) {
  const std::size_t n = map.size();
  std::vector<std::array<double, 2>> out(n);
  if (n == 0 || points.size() != n) return out;
  OrbitWalker walker(map);
  const std::vector<OrbitWord> face = dims_generators({0, 1}), edge = dims_generators({0});
  // The oblique projection of a point: depth goes up and to the right.
  auto project = [](const P3& p) { return std::array<double, 2>{p[0] + 0.45 * p[2], p[1] + 0.3 * p[2]}; };
  for (Dart d = 0; d < n; ++d) {
    const P3 v = points[d], f = centre(walker, d, face, points), e = centre(walker, d, edge, points);
    P3 p{};
    for (int k = 0; k < 3; ++k) p[k] = v[k] + 0.3 * (f[k] - v[k]) + 0.25 * (e[k] - v[k]);
    out[d] = project(p);
  }
  // Scale: a dart's nearest neighbour typically (the median) an inch away
  // (a node and its links' labels between), within max_inches. Not the closest
  // pair: a projection may put two darts of different depths together.
  double lo_x = out[0][0], hi_x = lo_x, lo_y = out[0][1], hi_y = lo_y;
  std::vector<double> nearest;
  for (Dart a = 0; a < n; ++a) {
    lo_x = std::min(lo_x, out[a][0]), hi_x = std::max(hi_x, out[a][0]);
    lo_y = std::min(lo_y, out[a][1]), hi_y = std::max(hi_y, out[a][1]);
    double best = std::numeric_limits<double>::infinity();
    for (Dart b = 0; b < n; ++b)
      if (b != a) best = std::min(best, std::hypot(out[a][0] - out[b][0], out[a][1] - out[b][1]));
    if (std::isfinite(best) && best > 0) nearest.push_back(best);
  }
  const double extent = std::max({hi_x - lo_x, hi_y - lo_y, 1e-300});
  double scale = max_inches / extent;
  if (!nearest.empty()) {
    std::nth_element(nearest.begin(), nearest.begin() + static_cast<std::ptrdiff_t>(nearest.size() / 2), nearest.end());
    scale = std::min(scale, 1.0 / nearest[nearest.size() / 2]);
  }
  for (auto& p : out) p = {(p[0] - lo_x) * scale, (p[1] - lo_y) * scale};
  return out;
}

}  // namespace dartcheck::reports
