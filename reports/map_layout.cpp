#include "reports/map_layout.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <limits>
#include <numbers>

#include <fmt/format.h>

#include "core/orbit.hpp"
#include "reports/render.hpp"

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
    // Pulls that space a square's darts evenly: the two darts of a corner
    // (alpha1), of an edge's side (alpha0) and of the two sides (alpha2)
    // all end up about 0.3 of an edge apart.
    for (int k = 0; k < 3; ++k) p[k] = v[k] + 0.3 * (f[k] - v[k]) + 0.4 * (e[k] - v[k]);
    out[d] = project(p);
  }
  // Turned to the smallest bounding box (in degree steps): a grid laid
  // out on its diagonal would fill a square twice its area.
  double best_area = std::numeric_limits<double>::infinity(), best_angle = 0;
  for (int step = 0; step < 90; ++step) {
    const double a = step * std::numbers::pi / 180, c = std::cos(a), s = std::sin(a);
    double x0 = std::numeric_limits<double>::infinity(), x1 = -x0, y0 = x0, y1 = -x0;
    for (const auto& q : out) {
      const double x = c * q[0] - s * q[1], y = s * q[0] + c * q[1];
      x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
    }
    // Ties (a square): the first, so an aligned layout stays as it is.
    if ((x1 - x0) * (y1 - y0) < best_area * (1 - 1e-9)) best_area = (x1 - x0) * (y1 - y0), best_angle = a;
  }
  for (auto& q : out) q = {std::cos(best_angle) * q[0] - std::sin(best_angle) * q[1], std::sin(best_angle) * q[0] + std::cos(best_angle) * q[1]};
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

std::vector<P3> skeleton_points(const Map& map) {
  const std::size_t n = map.size();
  const OrbitPartition vertex = partition_orbits(map, cell_generators(map.model(), 0));
  const std::size_t vertices = vertex.size();
  // A surface with a boundary lies flat (a disk, a grid); a closed
  // surface or a volume needs the third dimension to unfold.
  const Dim top = static_cast<Dim>(map.model().dimension());
  bool closed = top >= 3;
  if (!closed) {
    closed = true;
    for (Dart d = 0; d < n && closed; ++d) closed = map.link(top, d) != d && map.link(top, d) != no_dart;
  }
  std::string dot = fmt::format("graph skeleton {{\n  graph [dim={0}, dimen={0}, start=1, maxiter=2000];\n  node [shape=point];\n", closed ? 3 : 2);
  for (std::size_t v = 0; v < vertices; ++v) dot += fmt::format("  v{};\n", v);
  OrbitWalker walker(map);
  for_each_orbit(walker, map, cell_generators(map.model(), 1), [&](Dart, const std::vector<Dart>& edge) {
    std::vector<std::uint32_t> ends;
    for (Dart e : edge)
      if (std::find(ends.begin(), ends.end(), vertex.of[e]) == ends.end()) ends.push_back(vertex.of[e]);
    for (std::size_t i = 0; i < ends.size(); ++i)
      for (std::size_t j = i + 1; j < ends.size(); ++j) dot += fmt::format("  v{} -- v{};\n", ends[i], ends[j]);
  });
  dot += "}\n";
  std::vector<P3> at(vertices, P3{0, 0, 0});
  for (const NodePosition& p : node_positions(dot, "neato")) at[std::stoul(p.name.substr(1))] = p.at;
  if (closed) {
    // neato aligns a cube with its axes, which the oblique projection then
    // shows face on, its side faces squashed: turned 25 degrees about the
    // vertical and 15 about the horizontal, every face shows.
    const double yaw = 25 * std::numbers::pi / 180, pitch = 15 * std::numbers::pi / 180;
    for (P3& p : at) {
      const double x = std::cos(yaw) * p[0] + std::sin(yaw) * p[2], z = -std::sin(yaw) * p[0] + std::cos(yaw) * p[2];
      p = {x, std::cos(pitch) * p[1] - std::sin(pitch) * z, std::sin(pitch) * p[1] + std::cos(pitch) * z};
    }
  }
  std::vector<P3> out(n);
  for (Dart d = 0; d < n; ++d) out[d] = at[vertex.of[d]];
  return out;
}

}  // namespace dartcheck::reports
