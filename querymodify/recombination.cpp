#include "querymodify/recombination.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include "querymodify/modify.hpp"
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

double scaled_jacobian(const std::array<std::array<double, 3>, 8>& p) {
  double sum = 0, lo = 1e300, hi = -1e300;
  for (int v = 0; v < 8; ++v) {
    double e[3][3];
    for (int axis = 0; axis < 3; ++axis) {
      const int w = v ^ (1 << axis);
      const double sign = (v >> axis) & 1 ? -1.0 : 1.0;  // always along +axis
      for (int c = 0; c < 3; ++c) e[axis][c] = sign * (p[static_cast<std::size_t>(w)][static_cast<std::size_t>(c)] - p[static_cast<std::size_t>(v)][static_cast<std::size_t>(c)]);
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
  return sum >= 0 ? lo : -hi;
}

Recombination recombine(TetMap& mesh, const std::vector<HexQuery>& queries, Strategy strategy, const std::vector<std::array<double, 3>>* points) {
  QueryTrie trie;
  for (std::size_t k = 0; k < queries.size(); ++k) trie.add(queries[k].word, static_cast<int>(k));
  Recombination r;
  const auto all = all_matches(mesh.map, trie);
  r.raw_matches = all.raw;
  r.distinct_matches = all.distinct.size();
  if (strategy == Strategy::greedy) {
    r.selected = greedy_matches(mesh.map, trie);
  } else {
    std::vector<std::vector<std::uint32_t>> corners;
    if (points)
      for (const auto& q : queries) corners.push_back(query_corners(q));
    r.selected = global_matches(mesh.map, trie, [&](const QueryMatch& m) {
      if (!points) return -static_cast<double>(m.darts.size());  // fewer tetrahedra first
      // The best of the query's readings as a hexahedron: a pattern whose
      // triangles pair into quads in several ways is scored by the pairing
      // that fits the geometry.
      const HexQuery& q = queries[static_cast<std::size_t>(m.query)];
      const auto c = match_corners(q, corners[static_cast<std::size_t>(m.query)], m, mesh.vertex);
      double best = -2;
      for (const auto& reading : q.readings) {
        std::array<std::array<double, 3>, 8> p{};
        for (int v = 0; v < 8; ++v) p[reading[static_cast<std::size_t>(v)]] = (*points)[c[static_cast<std::size_t>(v)]];
        best = std::max(best, scaled_jacobian(p));
      }
      return best;
    });
  }
  // Merge the selected matches; renumberings shift later matches' darts.
  std::vector<Dart> where(mesh.map.size());
  for (Dart d = 0; d < where.size(); ++d) where[d] = d;
  std::vector<Dart> at(mesh.map.size());  // current dart -> original
  for (Dart d = 0; d < at.size(); ++d) at[d] = d;
  for (const auto& m : r.selected) {
    std::vector<Dart> darts;
    for (Dart d : m.darts) darts.push_back(where[d]);
    const auto moved = merge_volumes(mesh.map, darts);
    std::vector<std::uint32_t> vertex_moved;
    for (const auto& [from, to] : moved) {
      const Dart original = at[from];
      where[original] = to;
      at[to] = original;
      mesh.vertex[to] = mesh.vertex[from];
    }
  }
  mesh.vertex.resize(mesh.map.size());
  r.hexes = r.selected.size();
  std::size_t matched_tets = 0;
  for (const auto& m : r.selected) matched_tets += m.darts.size() / 12;
  r.tets = mesh.tets.size() - matched_tets;
  return r;
}

}  // namespace dartcheck::querymodify
