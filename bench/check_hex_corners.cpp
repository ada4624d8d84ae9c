// An independent check of recombined hexahedra (and of prisms and pyramids,
// `recombine --cells`, below): for each hex of a medit
// mesh written by `dartcheck recombine -o` (bottom quad, then the top quad
// vertex above vertex), the orientation of its 8
// corners by CGAL's exact predicates (Epick), corner v = x + 2y + 4z with
// its edges towards +x, +y, +z (reversed on the high side), as 001's
// scaled Jacobian reads them. dartcheck writes hexes right-handed, so every
// corner must be POSITIVE; a hex with a corner that is not is counted.
// With --conforming, also the pairs of hexes (and of all cells, with
// prisms and pyramids) whose shared vertices are not none, one, an edge or
// a face of both (as `recombine --conforming` promises), read from medit's
// face cycles.
//
//   build/bench/check_hex_corners [--conforming] OUT.mesh...
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <fmt/format.h>

#include <array>
#include <cstring>
#include <exception>

#include "hex_contacts_check.hpp"
#include "io/tet_mesh_io.hpp"

using K = CGAL::Exact_predicates_inexact_constructions_kernel;

int main(int argc, char** argv) {
  const bool conforming = argc > 1 && !std::strcmp(argv[1], "--conforming");
  if (argc < 2 + conforming) {
    fmt::print(stderr, "usage: check_hex_corners [--conforming] OUT.mesh...\n");
    return 2;
  }
  int status = 0;
  for (int a = 1 + conforming; a < argc; ++a) {
    try {
      const auto mesh = dartcheck::read_medit(argv[a]);
      std::size_t bad = 0, flat = 0;
      for (const auto& ring : mesh.hexes) {
        // medit's order (two quads, vertex above vertex) to corners x + 2y + 4z.
        const std::array<std::uint32_t, 8> h{ring[0], ring[1], ring[3], ring[2], ring[4], ring[5], ring[7], ring[6]};
        bool ok = true, any_flat = false;
        for (int v = 0; v < 8; ++v) {
          auto point = [&](int c) {
            const auto& p = mesh.points[h[static_cast<std::size_t>(c)]];
            return K::Point_3(p[0], p[1], p[2]);
          };
          int sign = 1;
          for (int axis = 0; axis < 3; ++axis) sign *= (v >> axis) & 1 ? -1 : 1;
          const int o = static_cast<int>(CGAL::orientation(point(v), point(v ^ 1), point(v ^ 2), point(v ^ 4))) * sign;
          ok &= o > 0;
          any_flat |= o == 0;
        }
        bad += !ok;
        flat += any_flat;
      }
      fmt::print("{}: {} hexes, {} with a corner not positive by exact predicate ({} with a flat corner)\n", argv[a], mesh.hexes.size(), bad, flat);
      if (bad) status = 1;
      // Prisms and pyramids (recombine --cells): every corner with its
      // two edges along its triangle or base and its third edge, medit's
      // right-handed order (a prism's triangle 0 1 2 turns
      // counterclockwise seen from the other; a pyramid's base seen from
      // its apex).
      auto check = [&](const char* name, const auto& cells, const auto& corners) {
        if (cells.empty()) return;
        std::size_t not_positive = 0;
        for (const auto& c : cells) {
          auto point = [&](int k) {
            const auto& p = mesh.points[c[static_cast<std::size_t>(k)]];
            return K::Point_3(p[0], p[1], p[2]);
          };
          bool ok = true;
          for (const auto& [v, x, y, z] : corners) ok &= CGAL::orientation(point(v), point(x), point(y), point(z)) == CGAL::POSITIVE;
          not_positive += !ok;
        }
        fmt::print("{}: {} {}, {} with a corner not positive by exact predicate\n", argv[a], cells.size(), name, not_positive);
        if (not_positive) status = 1;
      };
      check("prisms", mesh.prisms, std::array<std::array<int, 4>, 6>{{{0, 1, 2, 3}, {1, 2, 0, 4}, {2, 0, 1, 5}, {3, 5, 4, 0}, {4, 3, 5, 1}, {5, 4, 3, 2}}});
      check("pyramids", mesh.pyramids, std::array<std::array<int, 4>, 4>{{{0, 1, 3, 4}, {1, 2, 0, 4}, {2, 3, 1, 4}, {3, 0, 2, 4}}});
      if (conforming) {
        const std::size_t pairs = nonconforming_pairs(std::vector<MeditHex>(mesh.hexes.begin(), mesh.hexes.end()), mesh.points.size());
        fmt::print("{}: {} pairs of hexes meeting in more than a vertex, an edge or a face of both\n", argv[a], pairs);
        if (!mesh.prisms.empty() || !mesh.pyramids.empty()) {
          std::vector<MeditCell> cells;
          for (const auto& c : mesh.hexes) cells.emplace_back(c.begin(), c.end());
          for (const auto& c : mesh.prisms) cells.emplace_back(c.begin(), c.end());
          for (const auto& c : mesh.pyramids) cells.emplace_back(c.begin(), c.end());
          const std::size_t all = nonconforming_pairs(cells, mesh.points.size());
          fmt::print("{}: {} pairs of cells (hexes, prisms, pyramids) meeting in more than a vertex, an edge or a face of both\n", argv[a], all);
          if (all) status = 1;
        }
        if (pairs) status = 1;
      }
    } catch (const std::exception& e) {
      fmt::print(stderr, "{}: {}\n", argv[a], e.what());
      status = 2;
    }
  }
  return status;
}
