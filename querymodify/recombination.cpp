#include "querymodify/recombination.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <set>

#include "querymodify/modify.hpp"
#include "querymodify/orientation.hpp"
#include "querymodify/overlap.hpp"

namespace dartcheck::querymodify {

std::vector<std::uint32_t> query_corners(const HexQuery& q) {
  // Rebuild the query's tetrahedral map to read its darts' corners: the
  // construction is deterministic, so the darts are the query's.
  auto tets = subdivision_tets(q.subdivision);
  if (q.mirrored)
    for (auto& t : tets) std::swap(t[2], t[3]);
  return build_tet_map(tets).vertex;
}

std::array<std::uint32_t, 8> match_corners(const HexQuery& q, const std::vector<std::uint32_t>& corners, const QueryMatch& m,
                                           const std::vector<std::uint32_t>& vertex_of_dart) {
  const Labeling l = bfs_labeling(q.map, 0);
  std::array<std::uint32_t, 8> out{};
  for (std::size_t k = 0; k < l.darts.size(); ++k) out[corners[l.darts[k]]] = vertex_of_dart[m.darts[k]];
  return out;
}

namespace {

using Corners = std::array<std::array<double, 3>, 8>;

// The floating-point value, and the hex's handedness (+1: corners positive).
std::pair<double, int> float_jacobian(const Corners& p) {
  double sum = 0, lo = 1e300, hi = -1e300;
  for (int v = 0; v < 8; ++v) {
    double e[3][3];
    for (int axis = 0; axis < 3; ++axis) {
      const int w = v ^ (1 << axis);
      const double sign = (v >> axis) & 1 ? -1.0 : 1.0;  // always along +axis
      for (int c = 0; c < 3; ++c)
        e[axis][c] =
            sign * (p[static_cast<std::size_t>(w)][static_cast<std::size_t>(c)] - p[static_cast<std::size_t>(v)][static_cast<std::size_t>(c)]);
    }
    const double det = e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) - e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
                       e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]);
    double len = 1;
    for (auto& x : e) len *= std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
    const double j = len > 0 ? det / len : 0;
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

double scaled_jacobian(const Corners& p) {
  const auto [quality, handedness] = float_jacobian(p);
  // Positive in floating point: every corner must also be oriented the
  // hex's way exactly, or the hex is numerically flat or inverted there.
  if (quality > 0 && !corners_exact(p, handedness)) return 0.0;
  return quality;
}

namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// The best reading of a match as a hexahedron: a pattern whose triangles
// pair into quads in several ways is read by the pairing that fits the
// geometry. Without points, the first reading and NaN.
std::pair<std::array<std::uint32_t, 8>, double> best_reading(const HexQuery& q, const std::array<std::uint32_t, 8>& c,
                                                             const std::vector<std::array<double, 3>>* points) {
  std::array<std::uint32_t, 8> best_corners{};
  double best = -2;
  // The best reading by the floating-point value, then its sign made exact;
  // only if that fails (numerically flat) is every reading judged exactly.
  auto choose = [&](bool exact) {
    best = -2;
    for (const auto& reading : q.readings) {
      std::array<std::uint32_t, 8> corners{};
      for (int v = 0; v < 8; ++v) corners[reading[static_cast<std::size_t>(v)]] = c[static_cast<std::size_t>(v)];
      Corners p{};
      for (int v = 0; v < 8; ++v) p[static_cast<std::size_t>(v)] = (*points)[corners[static_cast<std::size_t>(v)]];
      const double j = exact ? scaled_jacobian(p) : float_jacobian(p).first;
      if (j > best) best = j, best_corners = corners;
    }
  };
  if (!points) {
    if (q.readings.empty()) return {best_corners, best};
    std::array<std::uint32_t, 8> corners{};
    for (int v = 0; v < 8; ++v) corners[q.readings.front()[static_cast<std::size_t>(v)]] = c[static_cast<std::size_t>(v)];
    return {corners, std::nan("")};
  }
  choose(false);
  if (best > 0) {
    Corners p{};
    for (int v = 0; v < 8; ++v) p[static_cast<std::size_t>(v)] = (*points)[best_corners[static_cast<std::size_t>(v)]];
    if (scaled_jacobian(p) != best) choose(true);
  }
  // Right-handed (x, y, z at corner 0 a positive frame), as mesh formats
  // want it: otherwise mirror x.
  if (points) {
    const auto& p = *points;
    auto at = [&](int v) { return p[best_corners[static_cast<std::size_t>(v)]]; };
    double u[3], v[3], w[3];
    for (int k = 0; k < 3; ++k) u[k] = at(1)[k] - at(0)[k], v[k] = at(2)[k] - at(0)[k], w[k] = at(4)[k] - at(0)[k];
    const double det = u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) + u[2] * (v[0] * w[1] - v[1] * w[0]);
    if (det < 0) {
      auto mirrored = best_corners;
      for (std::size_t k = 0; k < 8; ++k) mirrored[k] = best_corners[k ^ 1];
      best_corners = mirrored;
    }
  }
  return {best_corners, best};
}

}  // namespace

Recombination recombine(TetMap& mesh, const std::vector<HexQuery>& queries, Strategy strategy, const std::vector<std::array<double, 3>>* points,
                        double min_quality) {
  QueryTrie trie;
  for (std::size_t k = 0; k < queries.size(); ++k) trie.add(queries[k].word, static_cast<int>(k));
  std::vector<std::vector<std::uint32_t>> corners;
  for (const auto& q : queries) corners.push_back(query_corners(q));
  auto reading = [&](const QueryMatch& m) {
    const HexQuery& q = queries[static_cast<std::size_t>(m.query)];
    return best_reading(q, match_corners(q, corners[static_cast<std::size_t>(m.query)], m, mesh.vertex), points);
  };
  // 8 distinct corners and, with points, a quality above the threshold.
  auto acceptable = [&](const std::array<std::uint32_t, 8>& c, double quality) {
    auto sorted = c;
    std::sort(sorted.begin(), sorted.end());
    if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) return false;
    return !points || quality > min_quality;
  };
  // A hex spans 8 mesh vertices: the search abandons larger partial matches.
  std::uint32_t vertices = 0;
  for (auto v : mesh.vertex) vertices = std::max(vertices, v + 1);
  std::vector<std::uint32_t> per_vertex(vertices, 0);
  const ClassBound bound{&mesh.vertex, 8, &per_vertex};
  Recombination r;
  auto t = Clock::now();
  const auto all = all_matches(mesh.map, trie, &bound);
  r.raw_matches = all.raw;
  r.distinct_matches = all.distinct.size();
  r.match_seconds = since(t);
  t = Clock::now();
  if (strategy == Strategy::greedy) {
    r.selected = greedy_matches(mesh.map, trie, &bound, [&](const QueryMatch& m) {
      const auto [c, quality] = reading(m);
      return acceptable(c, quality);
    });
    for (const auto& m : all.distinct) {
      const auto [c, quality] = reading(m);
      r.acceptable += acceptable(c, quality);
    }
  } else {
    // Each candidate read once: its best reading scores it.
    AllMatches candidates;
    std::vector<double> scores;
    for (const auto& m : all.distinct) {
      const auto [c, quality] = reading(m);
      if (!acceptable(c, quality)) continue;
      candidates.distinct.push_back(m);
      scores.push_back(points ? quality : -static_cast<double>(m.darts.size()));  // without points: fewer tetrahedra first
    }
    r.acceptable = candidates.distinct.size();
    r.selected = global_matches(candidates, mesh.map.size(), scores);
  }
  r.select_seconds = since(t);
  std::vector<bool> used(mesh.tets.size(), false);
  for (const auto& m : r.selected) {
    const auto [c, quality] = reading(m);
    r.hex_corners.push_back(c);
    r.quality.push_back(quality);
    for (Dart d : m.darts) used[d / 12] = true;
  }
  for (std::size_t k = 0; k < used.size(); ++k)
    if (!used[k]) r.remaining_tets.push_back(k);
  t = Clock::now();
  // Merge the selected matches; renumberings shift later matches' darts.
  std::vector<Dart> where(mesh.map.size());
  for (Dart d = 0; d < where.size(); ++d) where[d] = d;
  std::vector<Dart> at(mesh.map.size());  // current dart -> original
  for (Dart d = 0; d < at.size(); ++d) at[d] = d;
  for (const auto& m : r.selected) {
    std::vector<Dart> darts;
    for (Dart d : m.darts) darts.push_back(where[d]);
    const auto moved = merge_volumes(mesh.map, darts);
    for (const auto& [from, to] : moved) {
      const Dart original = at[from];
      where[original] = to;
      at[to] = original;
      mesh.vertex[to] = mesh.vertex[from];
    }
  }
  mesh.vertex.resize(mesh.map.size());
  r.merge_seconds = since(t);
  r.hexes = r.selected.size();
  r.tets = r.remaining_tets.size();
  return r;
}

}  // namespace dartcheck::querymodify
