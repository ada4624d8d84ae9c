// The benchmarks' own check of how written hexes meet (independent of
// querymodify/hex_contacts.cpp, which `recombine --conforming` uses):
// two hexes of a conforming mesh share none, one vertex, the two ends of
// an edge of both, or a face of both. Read from medit's face cycles.
// Used by check_hex_corners and bench_gmsh_recombination.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <set>
#include <vector>

namespace {

using MeditHex = std::array<std::uint32_t, 8>;  // medit's order: bottom quad, top quad above it

// The vertex sets one hex may share with another: none, each vertex, the
// two ends of each edge (consecutive on a face cycle), each face.
std::set<std::set<std::uint32_t>> allowed_contacts(const MeditHex& h) {
  static const int faces[6][4] = {{0, 1, 2, 3}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  std::set<std::set<std::uint32_t>> out{{}};
  for (std::uint32_t v : h) out.insert({v});
  for (const auto& f : faces) {
    std::set<std::uint32_t> face;
    for (int k = 0; k < 4; ++k) {
      face.insert(h[static_cast<std::size_t>(f[k])]);
      out.insert({h[static_cast<std::size_t>(f[k])], h[static_cast<std::size_t>(f[(k + 1) % 4])]});
    }
    out.insert(face);
  }
  return out;
}

/// Pairs of `hexes` (vertex indices below `points`) that share vertices
/// in any other way.
[[maybe_unused]] std::size_t nonconforming_pairs(const std::vector<MeditHex>& hexes, std::size_t points) {
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

}  // namespace
