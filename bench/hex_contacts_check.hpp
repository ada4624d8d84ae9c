// The benchmarks' own check of how written cells meet (independent of
// querymodify/hex_contacts.cpp and cell_contacts.cpp, which `recombine
// --conforming` uses): two cells (hexes, prisms, pyramids) of a conforming
// mesh share none, one vertex, the two ends of an edge of both, or a face
// of both. Read from medit's face cycles. Used by check_hex_corners and
// bench_gmsh_recombination.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <set>
#include <vector>

namespace {

using MeditHex = std::array<std::uint32_t, 8>;  // medit's order: bottom quad, top quad above it
using MeditCell = std::vector<std::uint32_t>;     // a hex (8), prism (6) or pyramid (5) in medit's order

// medit's face cycles of a cell of n vertices: a hex's bottom and top
// quads and sides; a prism's two triangles and three sides; a pyramid's
// base and four sides.
const std::vector<std::vector<int>>& medit_faces(std::size_t n) {
  static const std::vector<std::vector<int>> hex{{0, 1, 2, 3}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  static const std::vector<std::vector<int>> prism{{0, 1, 2}, {3, 4, 5}, {0, 1, 4, 3}, {1, 2, 5, 4}, {2, 0, 3, 5}};
  static const std::vector<std::vector<int>> pyramid{{0, 1, 2, 3}, {0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}};
  return n == 8 ? hex : n == 6 ? prism : pyramid;
}

// The vertex sets one cell may share with another: none, each vertex, the
// two ends of each edge (consecutive on a face cycle), each face.
std::set<std::set<std::uint32_t>> allowed_contacts(const MeditCell& h) {
  std::set<std::set<std::uint32_t>> out{{}};
  for (std::uint32_t v : h) out.insert({v});
  for (const auto& f : medit_faces(h.size())) {
    std::set<std::uint32_t> face;
    for (std::size_t k = 0; k < f.size(); ++k) {
      face.insert(h[static_cast<std::size_t>(f[k])]);
      out.insert({h[static_cast<std::size_t>(f[k])], h[static_cast<std::size_t>(f[(k + 1) % f.size()])]});
    }
    out.insert(face);
  }
  return out;
}

/// Pairs of `cells` (vertex indices below `points`) that share vertices
/// in any other way.
[[maybe_unused]] std::size_t nonconforming_pairs(const std::vector<MeditCell>& hexes, std::size_t points) {
  std::vector<std::vector<std::size_t>> at(points);
  std::vector<std::set<std::set<std::uint32_t>>> allowed;
  allowed.reserve(hexes.size());
  for (std::size_t i = 0; i < hexes.size(); ++i) {
    for (std::uint32_t v : hexes[i]) at[v].push_back(i);
    allowed.push_back(allowed_contacts(hexes[i]));
  }
  std::size_t bad = 0;
  for (std::size_t i = 0; i < hexes.size(); ++i) {
    std::set<std::size_t> near;
    for (std::uint32_t v : hexes[i])
      for (std::size_t j : at[v])
        if (j > i) near.insert(j);
    for (std::size_t j : near) {
      std::set<std::uint32_t> shared;
      for (std::uint32_t v : hexes[i])
        if (std::find(hexes[j].begin(), hexes[j].end(), v) != hexes[j].end()) shared.insert(v);
      bad += !(allowed[i].count(shared) && allowed[j].count(shared));
    }
  }
  return bad;
}

/// The same for hexes alone.
[[maybe_unused]] std::size_t nonconforming_pairs(const std::vector<MeditHex>& hexes, std::size_t points) {
  std::vector<MeditCell> cells;
  for (const auto& h : hexes) cells.emplace_back(h.begin(), h.end());
  return nonconforming_pairs(cells, points);
}

}  // namespace
