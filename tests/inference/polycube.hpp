// Polycubes for the volume inference tests and benchmark: unit cubes on a
// lattice, built by build_volumes (which 3-sews shared squares), their
// Menger-like refinements and the κ from a polycube to its refinement.
#pragma once

#include <algorithm>
#include <array>
#include <functional>
#include <stdexcept>
#include <vector>

#include "generators/polygon_soup.hpp"
#include "inference/kappa_graph.hpp"
#include "soup_subdivision.hpp"

namespace dartcheck::inference::test {

inline const Model gmap3 = Model::gmap(3);

// The unit cube at grid position p of a lattice with `side` points per
// axis; its six faces in a fixed order (bottom, top, y-, y+, x-, x+), each
// starting at the cube's lowest corner where it contains it.
inline Polyhedron unit_cube(std::array<std::uint32_t, 3> p, std::uint32_t side) {
  auto v = [&](std::uint32_t i, std::uint32_t j, std::uint32_t k) { return (p[0] + i) + side * ((p[1] + j) + side * (p[2] + k)); };
  return {{v(0, 0, 0), v(1, 0, 0), v(1, 1, 0), v(0, 1, 0)}, {v(0, 0, 1), v(0, 1, 1), v(1, 1, 1), v(1, 0, 1)},
          {v(0, 0, 0), v(0, 0, 1), v(1, 0, 1), v(1, 0, 0)}, {v(0, 1, 0), v(1, 1, 0), v(1, 1, 1), v(0, 1, 1)},
          {v(0, 0, 0), v(0, 1, 0), v(0, 1, 1), v(0, 0, 1)}, {v(1, 0, 0), v(1, 0, 1), v(1, 1, 1), v(1, 1, 0)}};
}

// The cubes of an n x n x n grid that `keep` keeps, (0,0,0) first.
inline std::vector<std::array<std::uint32_t, 3>> kept_cubes(std::uint32_t n, const std::function<bool(std::array<std::uint32_t, 3>)>& keep) {
  std::vector<std::array<std::uint32_t, 3>> out;
  for (std::uint32_t z = 0; z < n; ++z)
    for (std::uint32_t y = 0; y < n; ++y)
      for (std::uint32_t x = 0; x < n; ++x)
        if (keep({x, y, z})) out.push_back({x, y, z});
  return out;
}

inline Map polycube(const std::vector<std::array<std::uint32_t, 3>>& cubes, std::uint32_t n) {
  std::vector<Polyhedron> volumes;
  for (const auto& c : cubes) volumes.push_back(unit_cube(c, n + 1));
  return build_volumes(gmap3, volumes);
}

// Dart `(face, at, to)` of cube number `cube` in a polycube: each cube is
// 48 darts, numbered as build_surface numbers one surface.
inline Dart cube_dart(std::size_t cube, const Polyhedron& faces, const SoupDart& s) { return static_cast<Dart>(48 * cube) + soup_dart(faces, s); }

// κ from a polycube to its refinement by an n-grid per cube whose corner
// cubes are kept: a dart of coarse cube P at its corner c, looking along
// its side to corner c', goes to the fine corner cube at c, at the same
// corner, looking one step towards c'. `coarse` lists the coarse cubes of
// a grid of `coarse_n` per axis, `fine` the kept cubes of the refined grid
// (n * coarse_n per axis).
inline KappaSpec corner_kappa(const std::vector<std::array<std::uint32_t, 3>>& coarse, std::uint32_t coarse_n,
                              const std::vector<std::array<std::uint32_t, 3>>& fine, std::uint32_t n) {
  const std::uint32_t side = coarse_n + 1, fine_side = n * coarse_n + 1;
  auto coords = [](std::uint32_t v, std::uint32_t s) { return std::array<std::uint32_t, 3>{v % s, (v / s) % s, v / (s * s)}; };
  auto id = [](const std::array<std::uint32_t, 3>& q, std::uint32_t s) { return q[0] + s * (q[1] + s * q[2]); };
  KappaSpec k;
  for (std::size_t ci = 0; ci < coarse.size(); ++ci) {
    const auto& P = coarse[ci];
    const Polyhedron big = unit_cube(P, side);
    for (std::uint32_t f = 0; f < 6; ++f)
      for (std::size_t e = 0; e < 4; ++e)
        for (int dir = 0; dir < 2; ++dir) {
          const std::uint32_t at = big[f][dir ? (e + 1) % 4 : e], to = big[f][dir ? e : (e + 1) % 4];
          const auto c = coords(at, side), d = coords(to, side);
          std::array<std::uint32_t, 3> cube{}, corner{}, step{};
          for (int i = 0; i < 3; ++i) {
            const bool high = c[i] > P[i];
            cube[i] = n * P[i] + (high ? n - 1 : 0);
            corner[i] = n * c[i];
            step[i] = d[i] == c[i] ? corner[i] : (d[i] > c[i] ? corner[i] + 1 : corner[i] - 1);
          }
          const auto it = std::find(fine.begin(), fine.end(), cube);
          if (it == fine.end()) throw std::logic_error("a corner cube is not kept");
          const auto index = static_cast<std::size_t>(it - fine.begin());
          k.pairs.emplace_back(cube_dart(ci, big, {f, at, to}),
                               cube_dart(index, unit_cube(cube, fine_side), {f, id(corner, fine_side), id(step, fine_side)}));
        }
  }
  return k;
}

// A menger-like refinement: keep the fine cube at local position q of an
// n-grid iff `keep_local(q)`.
using Keep = std::function<bool(std::array<std::uint32_t, 3>)>;

inline std::vector<std::array<std::uint32_t, 3>> refine(const std::vector<std::array<std::uint32_t, 3>>& coarse, std::uint32_t coarse_n,
                                                        std::uint32_t n, const Keep& keep_local) {
  return kept_cubes(n * coarse_n, [&](std::array<std::uint32_t, 3> p) {
    const std::array<std::uint32_t, 3> P{p[0] / n, p[1] / n, p[2] / n};
    return std::find(coarse.begin(), coarse.end(), P) != coarse.end() && keep_local({p[0] % n, p[1] % n, p[2] % n});
  });
}

inline bool menger_local(std::array<std::uint32_t, 3> q) { return (q[0] == 1) + (q[1] == 1) + (q[2] == 1) < 2; }
inline bool menger222_local(std::array<std::uint32_t, 3> q) {
  return (q[0] == 1 || q[0] == 3) + (q[1] == 1 || q[1] == 3) + (q[2] == 1 || q[2] == 3) < 2;
}

}  // namespace dartcheck::inference::test
