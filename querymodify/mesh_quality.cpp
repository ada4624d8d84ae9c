#include "querymodify/mesh_quality.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "querymodify/cell_quality.hpp"
#include "querymodify/hex_quality.hpp"

namespace dartcheck::querymodify {
namespace {

using P = std::array<double, 3>;

P minus(const P& a, const P& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double det(const P& u, const P& v, const P& w) {
  return (u[1] * v[2] - u[2] * v[1]) * w[0] + (u[2] * v[0] - u[0] * v[2]) * w[1] + (u[0] * v[1] - u[1] * v[0]) * w[2];
}
double norm(const P& u) { return std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]); }

template <std::size_t N>
std::array<P, N> points_of(const std::array<std::uint32_t, N>& c, const std::vector<P>& points) {
  std::array<P, N> out{};
  for (std::size_t j = 0; j < N; ++j) out[j] = points[c[j]];
  return out;
}

double tet_volume(const P& a, const P& b, const P& c, const P& d) { return std::abs(det(minus(b, a), minus(c, a), minus(d, a))) / 6; }

}  // namespace

const std::array<const char*, 7> quantile_names{"min", "p05", "p25", "median", "p75", "p95", "max"};
const std::array<const char*, 11> histogram_labels{"< 0",        "[0, 0.1)",   "[0.1, 0.2)", "[0.2, 0.3)", "[0.3, 0.4)", "[0.4, 0.5)",
                                                   "[0.5, 0.6)", "[0.6, 0.7)", "[0.7, 0.8)", "[0.8, 0.9)", ">= 0.9"};

double tet_quality(const std::array<P, 4>& c) {
  const double six_v = std::abs(det(minus(c[1], c[0]), minus(c[2], c[0]), minus(c[3], c[0])));
  double q = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < 4; ++k) {
    double lengths = 1;
    for (std::size_t j = 0; j < 4; ++j)
      if (j != k) lengths *= norm(minus(c[j], c[k]));
    q = std::min(q, lengths > 0 ? six_v / lengths : 0.0);
  }
  return q * std::sqrt(2.0);
}

std::vector<double> cell_qualities(const TetMesh& m) {
  std::vector<double> q;
  q.reserve(m.hexes.size() + m.prisms.size() + m.pyramids.size() + m.tets.size());
  // medit's hexahedron order back to the cube's corners v = x + 2y + 4z.
  for (const auto& h : m.hexes) q.push_back(scaled_jacobian(corner_points({h[0], h[1], h[3], h[2], h[4], h[5], h[7], h[6]}, m.points)));
  for (const auto& c : m.prisms) q.push_back(prism_quality(points_of(c, m.points)));
  for (const auto& c : m.pyramids) q.push_back(pyramid_quality(points_of(c, m.points)));
  for (const auto& c : m.tets) q.push_back(tet_quality(points_of(c, m.points)));
  return q;
}

QualitySummary summarize_quality(const TetMesh& m, const std::vector<double>& quality) {
  QualitySummary s;
  s.cells = m.hexes.size() + m.prisms.size() + m.pyramids.size();
  std::vector<double> recombined(quality.begin(), quality.begin() + static_cast<std::ptrdiff_t>(std::min(s.cells, quality.size())));
  std::sort(recombined.begin(), recombined.end());
  static constexpr std::array<double, 7> at{0, 0.05, 0.25, 0.5, 0.75, 0.95, 1};
  for (std::size_t k = 0; k < at.size(); ++k)
    s.quantiles[k] = recombined.empty() ? std::numeric_limits<double>::quiet_NaN()
                                        : recombined[static_cast<std::size_t>(std::lround(at[k] * static_cast<double>(recombined.size() - 1)))];
  for (double x : recombined) {
    s.histogram[x < 0 ? 0 : 1 + std::min<std::size_t>(9, static_cast<std::size_t>(x * 10))] += 1;
    s.poor += x < poor_quality;
  }
  const auto& p = m.points;
  std::array<double, 4> volume{};
  for (const auto& h : m.hexes)  // 6 tetrahedra around the diagonal 0-6
    for (const auto& [a, b] : {std::pair{1, 2}, {2, 3}, {3, 7}, {7, 4}, {4, 5}, {5, 1}})
      volume[0] += tet_volume(p[h[0]], p[h[static_cast<std::size_t>(a)]], p[h[static_cast<std::size_t>(b)]], p[h[6]]);
  for (const auto& c : m.prisms)
    volume[1] += tet_volume(p[c[0]], p[c[1]], p[c[2]], p[c[3]]) + tet_volume(p[c[1]], p[c[2]], p[c[3]], p[c[4]]) +
                 tet_volume(p[c[2]], p[c[3]], p[c[4]], p[c[5]]);
  for (const auto& c : m.pyramids) volume[2] += tet_volume(p[c[0]], p[c[1]], p[c[2]], p[c[4]]) + tet_volume(p[c[0]], p[c[2]], p[c[3]], p[c[4]]);
  for (const auto& t : m.tets) volume[3] += tet_volume(p[t[0]], p[t[1]], p[t[2]], p[t[3]]);
  const double total = volume[0] + volume[1] + volume[2] + volume[3];
  for (std::size_t k = 0; k < 4; ++k) s.volume_share[k] = total > 0 ? volume[k] / total : 0;
  return s;
}

}  // namespace dartcheck::querymodify
