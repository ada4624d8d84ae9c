// Hex grids cut into tetrahedra by known patterns: the ground truth of the
// recombination tests (every original hex must be found).
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <random>
#include <vector>

#include "querymodify/hex_queries.hpp"
#include "querymodify/hex_subdivisions.hpp"

namespace dartcheck::querymodify::test {

struct HexGrid {
  std::vector<std::array<double, 3>> points;
  std::vector<std::array<std::uint32_t, 4>> tets;
  std::vector<std::vector<std::uint32_t>> hex_tets;  // tetrahedra of each hex
};

/// The lattice point of corner c (v = x + 2y + 4z) of hex (i, j, k).
inline std::uint32_t lattice(std::uint32_t n, std::uint32_t i, std::uint32_t j, std::uint32_t k, int c) {
  const std::uint32_t s = n + 1;
  return (i + (c & 1)) + s * ((j + ((c >> 1) & 1)) + s * (k + ((c >> 2) & 1)));
}

/// n^3 hexes, each cut by `pick(i, j, k, diagonals)`: a labeled subdivision
/// whose face diagonals are `diagonals` (hex_faces() order, bit f = b-d),
/// chosen so that neighbouring hexes split their shared face alike.
/// `face_diagonal(i, j, k, axis)` chooses each grid face's diagonal.
template <class Pick, class FaceDiagonal>
HexGrid hex_grid(std::uint32_t n, Pick pick, FaceDiagonal face_diagonal) {
  HexGrid g;
  for (std::uint32_t k = 0; k <= n; ++k)
    for (std::uint32_t j = 0; j <= n; ++j)
      for (std::uint32_t i = 0; i <= n; ++i) g.points.push_back({double(i), double(j), double(k)});
  for (std::uint32_t k = 0; k < n; ++k)
    for (std::uint32_t j = 0; j < n; ++j)
      for (std::uint32_t i = 0; i < n; ++i) {
        // hex_faces(): x=0, x=1, y=0, y=1, z=0, z=1; each face's diagonal is
        // the one its grid face chose, read in the hex's corner order.
        int diagonals = 0;
        const std::uint32_t at[6][4] = {{i, j, k, 0}, {i + 1, j, k, 0}, {i, j, k, 1}, {i, j + 1, k, 1}, {i, j, k, 2}, {i, j, k + 1, 2}};
        for (int f = 0; f < 6; ++f)
          if (face_diagonal(at[f][0], at[f][1], at[f][2], static_cast<int>(at[f][3]))) diagonals |= 1 << f;
        const std::uint64_t s = pick(i, j, k, diagonals);
        std::vector<std::uint32_t> mine;
        for (const auto& t : subdivision_tets(s)) {
          mine.push_back(static_cast<std::uint32_t>(g.tets.size()));
          g.tets.push_back({lattice(n, i, j, k, static_cast<int>(t[0])), lattice(n, i, j, k, static_cast<int>(t[1])),
                            lattice(n, i, j, k, static_cast<int>(t[2])), lattice(n, i, j, k, static_cast<int>(t[3]))});
        }
        g.hex_tets.push_back(mine);
      }
  return g;
}

/// Labeled subdivisions by their diagonals.
inline const std::map<int, std::vector<std::uint64_t>>& subdivisions_by_diagonals() {
  static const std::map<int, std::vector<std::uint64_t>> by = [] {
    std::map<int, std::vector<std::uint64_t>> out;
    for (auto s : enumerate_hex_subdivisions()) out[subdivision_diagonals(s)].push_back(s);
    return out;
  }();
  return by;
}

// An n^3 grid of random labeled subdivisions fitting their faces'
// diagonals (redrawn when two would put one triangle in more than two
// tetrahedra); hex (0, 0, 0) is `member` if given, its faces' diagonals
// fixed by it.
inline HexGrid random_hexes(std::uint32_t n, std::mt19937& rng, std::optional<std::uint64_t> member = std::nullopt) {
  const int d = member ? subdivision_diagonals(*member) : 0;
  // hex_grid's faces of hex (0, 0, 0), in hex_faces() order.
  const std::map<std::array<std::uint32_t, 4>, int> own{{{0, 0, 0, 0}, 0}, {{1, 0, 0, 0}, 1}, {{0, 0, 0, 1}, 2},
                                                        {{0, 1, 0, 1}, 3}, {{0, 0, 0, 2}, 4}, {{0, 0, 1, 2}, 5}};
  std::map<std::array<std::uint32_t, 4>, bool> diag;
  std::map<std::array<std::uint32_t, 3>, int> uses;
  return hex_grid(
      n,
      [&](std::uint32_t i, std::uint32_t j, std::uint32_t k, int diagonals) {
        const auto& options = subdivisions_by_diagonals().at(diagonals);
        const bool fixed = member && i + j + k == 0;
        for (int attempt = 0;; ++attempt) {
          const std::uint64_t s = fixed ? *member : options[std::uniform_int_distribution<std::size_t>(0, options.size() - 1)(rng)];
          std::map<std::array<std::uint32_t, 3>, int> adds;
          for (const auto& t : subdivision_tets(s))
            for (int skip = 0; skip < 4; ++skip) {
              std::array<std::uint32_t, 3> tri{};
              for (int a = 0, b = 0; a < 4; ++a)
                if (a != skip) tri[static_cast<std::size_t>(b++)] = lattice(n, i, j, k, static_cast<int>(t[static_cast<std::size_t>(a)]));
              std::sort(tri.begin(), tri.end());
              ++adds[tri];
            }
          bool fits = true;
          for (const auto& [tri, c] : adds) fits = fits && uses[tri] + c <= 2;
          if (!fits && attempt < 200 && !fixed) continue;
          for (const auto& [tri, c] : adds) uses[tri] += c;
          return s;
        }
      },
      [&](std::uint32_t i, std::uint32_t j, std::uint32_t k, int axis) {
        const std::array<std::uint32_t, 4> key{i, j, k, static_cast<std::uint32_t>(axis)};
        if (const auto it = own.find(key); member && it != own.end()) return ((d >> it->second) & 1) != 0;
        auto [it, fresh] = diag.emplace(key, false);
        if (fresh) it->second = rng() & 1;
        return it->second;
      });
}

}  // namespace dartcheck::querymodify::test
