#include "querymodify/geometry.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "core/error.hpp"
#include "core/orbit.hpp"

namespace dartcheck::querymodify {
namespace {

Point3 minus(const Point3& a, const Point3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double norm(const Point3& a) { return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); }
double det(const Point3& a, const Point3& b, const Point3& c) {
  return a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
}

}  // namespace

std::vector<double> mean_value_coordinates(std::span<const Point3> vertices, std::span<const std::array<std::uint32_t, 3>> triangles,
                                           const Point3& x) {
  constexpr double eps = 1e-12;
  const std::size_t n = vertices.size();
  std::vector<double> w(n, 0.0), d(n);
  std::vector<Point3> u(n);
  for (std::size_t j = 0; j < n; ++j) {
    const Point3 v = minus(vertices[j], x);
    d[j] = norm(v);
    if (d[j] < eps) {  // x is a vertex
      w[j] = 1;
      return w;
    }
    u[j] = {v[0] / d[j], v[1] / d[j], v[2] / d[j]};
  }
  for (const auto& t : triangles) {
    double theta[3], c[3], s[3];
    double h = 0;
    for (int i = 0; i < 3; ++i) {
      const double l = norm(minus(u[t[static_cast<std::size_t>((i + 1) % 3)]], u[t[static_cast<std::size_t>((i + 2) % 3)]]));
      theta[i] = 2 * std::asin(std::min(1.0, l / 2));
      h += theta[i] / 2;
    }
    if (std::numbers::pi - h < eps) {  // x lies on t: its barycentric coordinates there
      std::fill(w.begin(), w.end(), 0.0);
      double sum = 0;
      for (int i = 0; i < 3; ++i) {
        const double b = std::sin(theta[i]) * d[t[static_cast<std::size_t>((i + 2) % 3)]] * d[t[static_cast<std::size_t>((i + 1) % 3)]];
        w[t[static_cast<std::size_t>(i)]] += b;
        sum += b;
      }
      for (double& v : w) v /= sum;
      return w;
    }
    const double sign = det(u[t[0]], u[t[1]], u[t[2]]) < 0 ? -1.0 : 1.0;
    bool flat = false;
    for (int i = 0; i < 3; ++i) {
      c[i] = 2 * std::sin(h) * std::sin(h - theta[i]) / (std::sin(theta[(i + 1) % 3]) * std::sin(theta[(i + 2) % 3])) - 1;
      s[i] = sign * std::sqrt(std::max(0.0, 1 - c[i] * c[i]));
      flat = flat || !(std::abs(s[i]) > eps);  // also catches NaN from a zero angle
    }
    if (flat) continue;  // x in t's plane but outside t, or t degenerate
    for (int i = 0; i < 3; ++i) {
      const int next = (i + 1) % 3, prev = (i + 2) % 3;
      w[t[static_cast<std::size_t>(i)]] +=
          (theta[i] - c[next] * theta[prev] - c[prev] * theta[next]) / (d[t[static_cast<std::size_t>(i)]] * std::sin(theta[next]) * s[prev]);
    }
  }
  double sum = 0;
  for (double v : w) sum += v;
  if (!(std::abs(sum) > eps))
    throw ValueError(fmt::format("mean value coordinates of ({}, {}, {}) are undefined: the weights cancel", x[0], x[1], x[2]));
  for (double& v : w) v /= sum;
  return w;
}

std::vector<Point3> place_target_points(const Map& q, const Map& t, std::span<const Point3> t_points, std::span<const Dart> q_to_t,
                                        std::span<const Point3> matched_points) {
  if (t_points.size() != t.size() || q_to_t.size() != q.size() || matched_points.size() != q.size())
    throw ValueError("place_target_points needs a point per target dart, and an image and a matched point per query dart");
  // T's vertices.
  const OrbitPartition t_vertices = partition_orbits(t, cell_generators(t.model(), 0));
  const std::vector<std::uint32_t>& vertex = t_vertices.of;
  const auto vertices = static_cast<std::uint32_t>(t_vertices.size());
  // Kept vertices take their input points.
  std::vector<bool> kept(vertices, false);
  std::vector<Point3> at(vertices);
  for (Dart x = 0; x < q.size(); ++x) {
    if (q_to_t[x] == no_dart) continue;
    if (q_to_t[x] >= t.size()) throw ValueError(fmt::format("m_QT sends query dart {} outside the target", x));
    const std::uint32_t v = vertex[q_to_t[x]];
    if (!kept[v]) kept[v] = true, at[v] = matched_points[x];
  }
  // The cage: Q's boundary faces in T, fanned from their first dart.
  std::vector<std::uint32_t> cage_index(vertices, UINT32_MAX);
  std::vector<Point3> cage_t, cage_m;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::vector<bool> seen(t.size(), false);
  auto cage_vertex = [&](Dart d) {
    const std::uint32_t v = vertex[d];
    if (cage_index[v] == UINT32_MAX) {
      cage_index[v] = static_cast<std::uint32_t>(cage_t.size());
      cage_t.push_back(t_points[d]);
      cage_m.push_back(at[v]);
    }
    return cage_index[v];
  };
  for (Dart x = 0; x < q.size(); ++x) {
    if (q.link(3, x) != no_dart || q_to_t[x] == no_dart || seen[q_to_t[x]]) continue;
    std::vector<std::uint32_t> face;
    for (Dart e = q_to_t[x]; e != no_dart && !seen[e]; e = t.link(1, e)) {
      seen[e] = true;
      face.push_back(cage_vertex(e));
    }
    for (std::size_t k = 1; k + 1 < face.size(); ++k) triangles.push_back({face[0], face[k], face[k + 1]});
  }
  std::vector<Point3> out(t.size());
  std::vector<bool> placed(vertices, false);
  for (Dart d = 0; d < t.size(); ++d) {
    const std::uint32_t v = vertex[d];
    if (!kept[v] && !placed[v]) {
      if (triangles.empty()) throw ValueError("the target creates a vertex but the query has no boundary to place it by");
      const auto w = mean_value_coordinates(cage_t, triangles, t_points[d]);
      Point3 p{0, 0, 0};
      for (std::size_t j = 0; j < w.size(); ++j)
        for (int k = 0; k < 3; ++k) p[static_cast<std::size_t>(k)] += w[j] * cage_m[j][static_cast<std::size_t>(k)];
      at[v] = p;
      placed[v] = true;
    }
    out[d] = at[v];
  }
  return out;
}

std::vector<Point3> dart_points(std::span<const std::uint32_t> vertex_of_dart, std::span<const Point3> points) {
  std::vector<Point3> out;
  out.reserve(vertex_of_dart.size());
  for (std::uint32_t v : vertex_of_dart) out.push_back(points[v]);
  return out;
}

}  // namespace dartcheck::querymodify
