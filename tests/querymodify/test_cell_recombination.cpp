// Prisms and pyramids (cell_subdivisions, cell_quality, cell_search and
// recombine's --cells). Expectations: the subdivision counts derived by
// hand (a pyramid splits its base by either diagonal; a prism takes any
// diagonals but the two cyclic ones, Schönhardt's twisted prism), each
// subdivision checked as a triangulation of a real cell by its volumes,
// the symmetry groups' orders (D3h: 12, C4v: 8), and meshes built from
// known prisms and pyramids whose every cell must come back.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <random>
#include <set>

#include "grid_tets.hpp"
#include "querymodify/cell_contacts.hpp"
#include "querymodify/cell_quality.hpp"
#include "querymodify/cell_search.hpp"
#include "querymodify/cell_subdivisions.hpp"
#include "querymodify/map_checks.hpp"
#include "querymodify/recombination.hpp"

namespace dartcheck::querymodify::test {
namespace {

using Point = std::array<double, 3>;

double volume(const Point& a, const Point& b, const Point& c, const Point& d) {
  const Point u{b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v{c[0] - a[0], c[1] - a[1], c[2] - a[2]}, w{d[0] - a[0], d[1] - a[1], d[2] - a[2]};
  return (u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) + u[2] * (v[0] * w[1] - v[1] * w[0])) / 6;
}

// A set of tetrahedra as a bit set of their masks (all below 64): compared
// as one word (GCC 12 warns on memcmp over vectors of bytes).
std::uint64_t key(const std::vector<CellTet>& tets) {
  std::uint64_t k = 0;
  for (CellTet t : tets) k |= std::uint64_t{1} << t;
  return k;
}

std::vector<int> corners_of(CellTet t) {
  std::vector<int> out;
  for (int c = 0; c < 8; ++c)
    if (t & (1u << c)) out.push_back(c);
  return out;
}

// Each subdivision triangulates the real cell: its tetrahedra are not
// flat, and their volumes (taken positive) sum to the cell's volume, so
// they fill it without overlap (the tetrahedra lie inside the convex cell).
void triangulates_each(const std::vector<std::vector<CellTet>>& subdivisions, const std::vector<Point>& p, double cell_volume) {
  for (const auto& s : subdivisions) {
    double sum = 0;
    for (CellTet t : s) {
      const auto c = corners_of(t);
      const double v = volume(p[static_cast<std::size_t>(c[0])], p[static_cast<std::size_t>(c[1])], p[static_cast<std::size_t>(c[2])],
                              p[static_cast<std::size_t>(c[3])]);
      EXPECT_NE(v, 0.0);
      sum += std::abs(v);
    }
    EXPECT_NEAR(sum, cell_volume, 1e-12);
  }
}

TEST(CellSubdivisions, PyramidSplitsItsBaseByEitherDiagonal) {
  const auto all = enumerate_cell_subdivisions(pyramid_shape());
  ASSERT_EQ(all.size(), 2u);
  std::set<unsigned> diagonals;
  for (const auto& s : all) {
    EXPECT_EQ(s.size(), 2u);
    diagonals.insert(cell_subdivision_diagonals(pyramid_shape(), s));
  }
  EXPECT_EQ(diagonals, (std::set<unsigned>{0, 1}));
  EXPECT_EQ(pyramid_shape().symmetries.size(), 8u);
  // Unit square base, apex above its centre at height 1: volume 1/3.
  triangulates_each(all, {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, 0.5, 1}}, 1.0 / 3);
}

// By hand. Euler's formula on a ball whose 6 vertices and 8 triangles
// (with 3 quad diagonals, 12 edges) are on its boundary gives 3 + e
// tetrahedra for e inner edges, and an inner edge can only be a quad's
// other diagonal (every other pair of corners is a boundary edge).
// - e = 0: 3 tetrahedra. Each quad's diagonal leaves one bottom corner;
//   when the three leave three different ones (they turn the same way
//   round) the prism cannot be cut (Schönhardt's twisted prism), otherwise
//   exactly one way: the 6 acyclic choices.
// - e = 1: none. With b-d of quad (a b c d) inner (a-c on the boundary),
//   the tetrahedra around b-d link a, c and the far edge e f: as the cycle
//   a e c f they are all 4 tetrahedra and miss the boundary triangle a c
//   d; as a e f or c e f, the triangles a b c and a c d need a fourth
//   tetrahedron a b c d, which is a face.
// - e = 2: checked triangle by triangle for the cyclic choice 1-3, 2-4,
//   0-5: {0123, 0234, 1234, 0245, 0345} (inner edges 2-3 and 0-4, each
//   boundary triangle once, 023 123 024 034 234 045 twice). Its images
//   under the 12 symmetries are 6 subdivisions, 3 for each cyclic choice.
// They exist only where two quads fold in (their other diagonals inside):
// on the right prism their tetrahedra overlap.
TEST(CellSubdivisions, PrismHasSixOfThreeTetrahedraAndSixTwistedOfFive) {
  const auto& prism = prism_shape();
  EXPECT_EQ(prism.symmetries.size(), 12u);
  const auto all = enumerate_cell_subdivisions(prism);
  std::vector<std::vector<CellTet>> three, five;
  for (const auto& s : all) (s.size() == 3 ? three : five).push_back(s);
  // The 3-tetrahedron ones: one per acyclic choice of diagonals.
  std::map<unsigned, int> by_diagonals;
  for (const auto& s : three) ++by_diagonals[cell_subdivision_diagonals(prism, s)];
  for (unsigned d = 0; d < 8; ++d) {
    std::set<int> bottom;
    unsigned q = 0;
    for (const auto& f : prism.faces) {
      if (f.size() != 4) continue;
      // Split by corners 0-2 or 1-3 of the face's cycle (bit q set: 1-3).
      const int a = (d >> q) & 1 ? f[1] : f[0], b = (d >> q) & 1 ? f[3] : f[2];
      bottom.insert(std::min(a, b));  // the bottom corner (0, 1 or 2) of the diagonal
      ++q;
    }
    const bool cyclic = bottom.size() == 3;
    EXPECT_EQ(by_diagonals.count(d) ? by_diagonals[d] : 0, cyclic ? 0 : 1) << "diagonals " << d;
  }
  EXPECT_EQ(three.size(), 6u);
  // The 5-tetrahedron ones: the orbit of the one checked by hand.
  const std::vector<std::vector<int>> hand{{0, 1, 2, 3}, {0, 2, 3, 4}, {1, 2, 3, 4}, {0, 2, 4, 5}, {0, 3, 4, 5}};
  std::set<std::uint64_t> orbit, five_keys;
  for (const auto& s : five) five_keys.insert(key(s));
  for (const auto& sigma : prism.symmetries) {
    std::vector<CellTet> image;
    for (const auto& t : hand) {
      unsigned m = 0;
      for (int c : t) m |= 1u << sigma[static_cast<std::size_t>(c)];
      image.push_back(static_cast<CellTet>(m));
    }
    orbit.insert(key(image));
  }
  EXPECT_EQ(orbit.size(), 6u);
  EXPECT_EQ(five_keys, orbit);
  EXPECT_EQ(all.size(), 12u);
  // The right prism on the unit right triangle (volume 1/2): the 3-
  // tetrahedron ones triangulate it, the twisted ones overlap on it.
  const std::vector<Point> p{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}};
  for (const auto& s : five) {
    double sum = 0;
    for (CellTet t : s) {
      const auto c = corners_of(t);
      sum += std::abs(volume(p[static_cast<std::size_t>(c[0])], p[static_cast<std::size_t>(c[1])], p[static_cast<std::size_t>(c[2])],
                             p[static_cast<std::size_t>(c[3])]));
    }
    EXPECT_GT(sum, 0.5 + 1e-9);  // they overlap
  }
  triangulates_each(three, p, 0.5);
}

// Two tetrahedra sharing a triangle read as a pyramid in exactly three
// ways: the apex is one of the three shared vertices, the base the other
// two with the two unshared ones.
TEST(CellReadings, TwoTetrahedraOnATriangleAreThreePyramids) {
  // Local vertices 0..4; shared triangle {1, 2, 3}, unshared 0 and 4.
  const std::array<CellTet, 2> tets{0b01111, 0b11110};
  const auto readings = pyramid_readings().of(tets);
  ASSERT_EQ(readings.size(), 3u);
  std::set<int> apexes;
  for (const auto& r : readings) {
    apexes.insert(r[4]);
    // The base cycle alternates shared and unshared vertices.
    for (int k = 0; k < 4; ++k) {
      const bool shared = r[static_cast<std::size_t>(k)] >= 1 && r[static_cast<std::size_t>(k)] <= 3;
      const bool next_shared = r[static_cast<std::size_t>((k + 1) % 4)] >= 1 && r[static_cast<std::size_t>((k + 1) % 4)] <= 3;
      EXPECT_NE(shared, next_shared);
    }
  }
  EXPECT_EQ(apexes, (std::set<int>{1, 2, 3}));
  // Two tetrahedra on 5 vertices sharing only an edge are no pyramid.
  const std::array<CellTet, 2> apart{0b01111, 0b11001};
  EXPECT_TRUE(pyramid_readings().of(apart).empty());
}

// Every labeled subdivision, relabeled at random, is read back: some
// reading maps it onto the relabeled set, and every reading given does.
TEST(CellReadings, EveryRelabeledSubdivisionIsRead) {
  std::mt19937 rng(7);
  for (const CellShape* cell : {&prism_shape(), &pyramid_shape()}) {
    const auto& readings = cell == &prism_shape() ? prism_readings() : pyramid_readings();
    const auto k = static_cast<std::size_t>(cell->corners);
    const auto all = enumerate_cell_subdivisions(*cell);
    std::set<std::uint64_t> labeled;
    for (const auto& s : all) labeled.insert(key(s));
    for (const auto& s : all)
      for (int trial = 0; trial < 50; ++trial) {
        std::vector<int> perm(k);
        std::iota(perm.begin(), perm.end(), 0);
        std::shuffle(perm.begin(), perm.end(), rng);
        auto image = [&](CellTet t, const auto& p) {
          unsigned m = 0;
          for (std::size_t c = 0; c < k; ++c)
            if (t & (1u << c)) m |= 1u << p[c];
          return static_cast<CellTet>(m);
        };
        std::vector<CellTet> set;
        for (CellTet t : s) set.push_back(image(t, perm));
        const auto found = readings.of(set);
        ASSERT_FALSE(found.empty());
        for (const auto& r : found) {
          // The reading's preimage of the set is a labeled subdivision.
          std::vector<CellTet> back;
          for (CellTet t : set) {
            unsigned m = 0;
            for (std::size_t c = 0; c < k; ++c)
              if (t & (1u << r[c])) m |= 1u << c;
            back.push_back(static_cast<CellTet>(m));
          }
          EXPECT_TRUE(labeled.count(key(back)));
        }
      }
  }
}

TEST(CellQuality, RegularCellsScoreOneInEitherHand) {
  const double h = std::sqrt(3.0) / 2;
  const std::array<Point, 6> prism{{{0, 0, 0}, {1, 0, 0}, {0.5, h, 0}, {0, 0, 1}, {1, 0, 1}, {0.5, h, 1}}};
  EXPECT_NEAR(prism_quality(prism), 1.0, 1e-15);
  const std::array<Point, 6> mirrored{prism[0], prism[2], prism[1], prism[3], prism[5], prism[4]};
  EXPECT_NEAR(prism_quality(mirrored), 1.0, 1e-15);
  // All 8 edges 1: the apex at height 1/sqrt(2).
  const std::array<Point, 5> pyramid{{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, 0.5, std::sqrt(0.5)}}};
  EXPECT_NEAR(pyramid_quality(pyramid), 1.0, 1e-15);
  const std::array<Point, 5> pyramid_mirrored{pyramid[0], pyramid[3], pyramid[2], pyramid[1], pyramid[4]};
  EXPECT_NEAR(pyramid_quality(pyramid_mirrored), 1.0, 1e-15);
  // Folded: the apex below the base, seen from the base's orientation,
  // with one base corner pulled through: not positive.
  std::array<Point, 5> folded = pyramid;
  folded[2] = {0.2, 0.2, 0};
  EXPECT_LE(pyramid_quality(folded), 0.0);
  // The right-handed order medit wants, from either hand.
  const std::vector<Point> points(prism.begin(), prism.end());
  EXPECT_EQ(right_handed_prism({0, 2, 1, 3, 5, 4}, points), (std::array<std::uint32_t, 6>{0, 1, 2, 3, 4, 5}));
  EXPECT_EQ(right_handed_prism({0, 1, 2, 3, 4, 5}, points), (std::array<std::uint32_t, 6>{0, 1, 2, 3, 4, 5}));
}

// A layer stack of prisms on a triangular lattice (equilateral triangles),
// each quad split by the diagonal through its smallest vertex (so that
// neighbours agree, and never cyclically), each prism into the labeled
// subdivision with those diagonals.
struct PrismMesh {
  std::vector<Point> points;
  std::vector<std::array<std::uint32_t, 4>> tets;
  std::vector<std::vector<std::uint32_t>> prism_tets;
};

PrismMesh prism_mesh(std::uint32_t n, std::uint32_t layers) {
  PrismMesh m;
  const double h = std::sqrt(3.0) / 2;
  auto at = [&](std::uint32_t i, std::uint32_t j, std::uint32_t z) { return i + (n + 1) * (j + (n + 1) * z); };
  for (std::uint32_t z = 0; z <= layers; ++z)
    for (std::uint32_t j = 0; j <= n; ++j)
      for (std::uint32_t i = 0; i <= n; ++i) m.points.push_back({i + 0.5 * j, h * j, double(z)});
  const auto& prism = prism_shape();
  const auto all = enumerate_cell_subdivisions(prism);
  for (std::uint32_t z = 0; z < layers; ++z)
    for (std::uint32_t j = 0; j < n; ++j)
      for (std::uint32_t i = 0; i < n; ++i)
        for (int upper = 0; upper < 2; ++upper) {
          const std::array<std::array<std::uint32_t, 2>, 3> tri =
              upper ? std::array<std::array<std::uint32_t, 2>, 3>{{{i + 1, j}, {i + 1, j + 1}, {i, j + 1}}}
                    : std::array<std::array<std::uint32_t, 2>, 3>{{{i, j}, {i + 1, j}, {i, j + 1}}};
          std::array<std::uint32_t, 6> v{};
          for (std::size_t c = 0; c < 3; ++c) v[c] = at(tri[c][0], tri[c][1], z), v[c + 3] = at(tri[c][0], tri[c][1], z + 1);
          unsigned diagonals = 0, q = 0;
          for (const auto& f : prism.faces) {
            if (f.size() != 4) continue;
            const auto lowest = std::min_element(f.begin(), f.end(), [&](int a, int b) { return v[static_cast<std::size_t>(a)] < v[static_cast<std::size_t>(b)]; }) - f.begin();
            if (lowest % 2) diagonals |= 1u << q;  // through corner 1 or 3 of the cycle
            ++q;
          }
          const auto s = std::find_if(all.begin(), all.end(), [&](const auto& x) { return cell_subdivision_diagonals(prism, x) == diagonals; });
          EXPECT_NE(s, all.end());
          std::vector<std::uint32_t> mine;
          for (CellTet t : *s) {
            const auto c = corners_of(t);
            mine.push_back(static_cast<std::uint32_t>(m.tets.size()));
            m.tets.push_back({v[static_cast<std::size_t>(c[0])], v[static_cast<std::size_t>(c[1])], v[static_cast<std::size_t>(c[2])],
                              v[static_cast<std::size_t>(c[3])]});
          }
          m.prism_tets.push_back(mine);
        }
  return m;
}

std::set<std::vector<std::uint32_t>> sets_of(const std::vector<CellCandidate>& cells) {
  std::set<std::vector<std::uint32_t>> out;
  for (const auto& c : cells) {
    std::vector<std::uint32_t> t(c.tets_of().begin(), c.tets_of().end());
    std::sort(t.begin(), t.end());
    out.insert(t);
  }
  return out;
}

// Every prism of the stack comes back, right-handed, and the merged map is
// valid with 24 darts (8 boundary triangles) per prism. Two prisms of a
// rhombus also make a hex of scaled Jacobian sin 60 = 0.866: a threshold
// of 0.9 leaves the prisms (quality 1) to the prism pass.
TEST(CellRecombination, EveryPrismOfALayerStackIsFound) {
  PrismMesh g = prism_mesh(3, 2);
  TetMap t = build_tet_map(g.tets, &g.points);
  const Recombination r = recombine(t, {}, Strategy::global, &g.points, 0.9, Search::vertices, Contacts::any, Cells{true, true});
  EXPECT_EQ(r.hexes, 0u);
  std::set<std::vector<std::uint32_t>> want;
  for (auto p : g.prism_tets) {
    std::sort(p.begin(), p.end());
    want.insert(p);
  }
  EXPECT_EQ(sets_of(r.prisms.cells), want);
  for (const auto& c : r.prisms.cells) {
    EXPECT_NEAR(c.quality, 1.0, 1e-12);
    std::array<Point, 6> p{};
    for (std::size_t k = 0; k < 6; ++k) p[k] = g.points[c.corners[k]];
    EXPECT_GT(volume(p[0], p[1], p[2], p[3]), 0);  // right-handed, as medit wants it
  }
  // Every prism quad faces another prism's quad or the boundary: no
  // pyramid is wanted.
  EXPECT_EQ(r.quads_facing_triangles, 0u);
  EXPECT_TRUE(r.pyramids.cells.empty());
  EXPECT_TRUE(r.remaining_tets.empty());
  EXPECT_TRUE(check_3map(t.map).valid());
  EXPECT_EQ(t.map.size(), 24u * want.size());
}

// A 3^3 grid of Kuhn hexes whose centre cube is cut instead into 6
// pyramids around its centre (2 tetrahedra each, the base split like the
// neighbour's face): the 26 hexes come back, each of their 6 quads towards
// the centre faces two tetrahedra, and the pyramid pass puts a pyramid on
// each, which leaves no quad against triangles.
TEST(CellRecombination, PyramidsCloseTheQuadsOfHexesAroundACavity) {
  const std::uint32_t n = 3;
  HexGrid g;  // lattice points in grid_tets' order
  for (std::uint32_t k = 0; k <= n; ++k)
    for (std::uint32_t j = 0; j <= n; ++j)
      for (std::uint32_t i = 0; i <= n; ++i) g.points.push_back({double(i), double(j), double(k)});
  const auto& kuhn = [] {
    std::vector<std::array<int, 4>> out;
    std::array<int, 3> axes{0, 1, 2};
    do {
      const int a = 1 << axes[0], ab = a | (1 << axes[1]);
      out.push_back({0, a, ab, 7});
    } while (std::next_permutation(axes.begin(), axes.end()));
    return out;
  }();
  const auto centre = static_cast<std::uint32_t>(g.points.size());
  g.points.push_back({1.5, 1.5, 1.5});
  std::size_t hexes = 0;
  for (std::uint32_t k = 0; k < n; ++k)
    for (std::uint32_t j = 0; j < n; ++j)
      for (std::uint32_t i = 0; i < n; ++i) {
        if (i == 1 && j == 1 && k == 1) {
          // Each face's Kuhn diagonal runs through its lowest corner.
          for (const auto& f : hex_faces()) {
            const int lo = *std::min_element(f.begin(), f.end());
            const auto at = std::find(f.begin(), f.end(), lo) - f.begin();
            auto c = [&](long s) { return lattice(n, i, j, k, f[static_cast<std::size_t>((at + s) % 4)]); };
            g.tets.push_back({c(0), c(1), c(2), centre});
            g.tets.push_back({c(0), c(2), c(3), centre});
          }
          continue;
        }
        ++hexes;
        for (const auto& t : kuhn)
          g.tets.push_back({lattice(n, i, j, k, t[0]), lattice(n, i, j, k, t[1]), lattice(n, i, j, k, t[2]), lattice(n, i, j, k, t[3])});
      }
  ASSERT_EQ(hexes, 26u);
  TetMap t = build_tet_map(g.tets, &g.points);
  const Recombination r = recombine(t, {}, Strategy::global, &g.points, 0.0, Search::vertices, Contacts::any, Cells{false, true});
  EXPECT_EQ(r.hexes, 26u);
  EXPECT_EQ(r.quads_facing_triangles_before_pyramids, 6u);
  ASSERT_EQ(r.pyramids.cells.size(), 6u);
  for (const auto& c : r.pyramids.cells) {
    EXPECT_EQ(c.corners[4], centre);
    // A half-cube pyramid: apex at height 1/2 over a unit square; at each
    // base corner the edges (1,0,0), (0,1,0), (1/2,1/2,1/2)/(sqrt(3)/2):
    // 1/sqrt(3), times sqrt(2).
    EXPECT_NEAR(c.quality, std::sqrt(2.0 / 3), 1e-12);
  }
  EXPECT_EQ(r.quads_facing_triangles, 0u);
  EXPECT_TRUE(r.remaining_tets.empty());
  EXPECT_TRUE(check_3map(t.map).valid());
  EXPECT_EQ(t.map.size(), 36u * 26 + 18u * 6);
}

// Without --cells the pass does not run, and the conformity count is the
// hexes' own.
TEST(CellRecombination, HexesOnlyByDefault) {
  PrismMesh g = prism_mesh(2, 1);
  TetMap t = build_tet_map(g.tets, &g.points);
  const Recombination r = recombine(t, {}, Strategy::global, &g.points, 0.9);
  EXPECT_EQ(r.hexes, 0u);
  EXPECT_TRUE(r.prisms.cells.empty());
  EXPECT_EQ(r.prisms.candidates, 0u);
  EXPECT_EQ(r.remaining_tets.size(), g.tets.size());
}

// How cells meet, by hand: a hex of the unit cube (vertex = corner v = x +
// 2y + 4z), a prism on its top face's triangle 4 5 6 and its quads, a
// pyramid on its top face.
TEST(CellContacts, FacesOfBothConformHalfQuadsDoNot) {
  const std::array<std::uint32_t, 8> hex{0, 1, 2, 3, 4, 5, 6, 7};
  const auto& h = hex_shape();
  const auto& prism = prism_shape();
  const auto& pyramid = pyramid_shape();
  auto meets = [](std::span<const std::uint32_t> a, const CellShape& as, std::span<const std::uint32_t> b, const CellShape& bs) {
    const bool one = conforming_contact(a, as, b, bs), other = conforming_contact(b, bs, a, as);
    EXPECT_EQ(one, other);  // symmetric
    return one;
  };
  // A prism whose quad (0 1 4 3 of the prism) is the hex's side x = 1 (1 3
  // 7 5): it shares a face of both.
  const std::array<std::uint32_t, 6> on_side{1, 3, 8, 5, 7, 9};
  EXPECT_TRUE(meets(hex, h, on_side, prism));
  // A prism standing on the triangle 4 5 6 of the top face: half a quad of
  // the hex against a triangle of the prism.
  const std::array<std::uint32_t, 6> on_half{4, 5, 6, 10, 11, 12};
  EXPECT_FALSE(meets(hex, h, on_half, prism));
  // A pyramid on the top face (base cycle 4 5 7 6): a face of both.
  const std::array<std::uint32_t, 5> on_top{4, 5, 7, 6, 13};
  EXPECT_TRUE(meets(hex, h, on_top, pyramid));
  // The same pyramid with its base cycle crossed (4 5 6 7): the hex's top
  // face's vertices, but 5-6 is a diagonal of the hex, an edge of the
  // pyramid's base; still the 4 vertices of a face of both as sets.
  // Contacts are vertex sets, as the written mesh shows them.
  const std::array<std::uint32_t, 5> crossed{4, 5, 6, 7, 13};
  EXPECT_TRUE(meets(hex, h, crossed, pyramid));
  // An edge of both, a vertex, nothing.
  const std::array<std::uint32_t, 5> on_edge{6, 7, 14, 15, 16};  // base edge 6-7 = the hex's edge 6-7
  EXPECT_TRUE(meets(hex, h, on_edge, pyramid));
  const std::array<std::uint32_t, 5> on_diagonal{4, 7, 14, 15, 16};  // 4-7: a diagonal of the hex's top face
  EXPECT_FALSE(meets(hex, h, on_diagonal, pyramid));
  const std::array<std::uint32_t, 5> at_vertex{7, 14, 15, 16, 17};
  EXPECT_TRUE(meets(hex, h, at_vertex, pyramid));
  // Two prisms on one triangle (a face of both); on one quad diagonal (an
  // edge of one only: the prism's quad 0 1 4 3 has diagonal 0-4).
  const std::array<std::uint32_t, 6> a{20, 21, 22, 23, 24, 25};
  EXPECT_TRUE(meets(a, prism, std::array<std::uint32_t, 6>{20, 21, 22, 26, 27, 28}, prism));
  EXPECT_FALSE(meets(a, prism, std::array<std::uint32_t, 6>{20, 24, 29, 30, 31, 32}, prism));
}

// With Contacts::conforming the prisms of the layer stack, which meet
// face to face, are all kept; a jittered stack keeps only cells that pass
// the test's own check of shared vertex sets (built from the face cycles
// written here, not cell_contacts).
TEST(CellRecombination, ConformingCellsMeetInFacesOfBoth) {
  PrismMesh g = prism_mesh(3, 2);
  {
    TetMap t = build_tet_map(g.tets, &g.points);
    const Recombination r = recombine(t, {}, Strategy::global, &g.points, 0.9, Search::vertices, Contacts::conforming, Cells{true, true});
    EXPECT_EQ(r.prisms.cells.size(), g.prism_tets.size());
    EXPECT_EQ(r.prisms.nonconforming, 0u);
  }
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> jitter(-0.2, 0.2);
  std::size_t passed_over = 0;
  for (int trial = 0; trial < 4; ++trial) {
    PrismMesh j = prism_mesh(4, 3);
    for (auto& p : j.points)
      for (auto& x : p) x += jitter(rng);
    TetMap t = build_tet_map(j.tets, &j.points);
    const Recombination r = recombine(t, {}, Strategy::global, &j.points, 0.0, Search::vertices, Contacts::conforming, Cells{true, true});
    passed_over += r.prisms.nonconforming + r.pyramids.nonconforming;
    // Every selected cell's allowed contacts: nothing, a vertex, an edge or
    // a face of its own (as vertex sets).
    std::vector<std::vector<std::uint32_t>> cells;
    std::vector<std::vector<std::vector<int>>> faces;
    const std::vector<std::vector<int>> hex_f{{0, 1, 3, 2}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 3, 7, 5}};
    const std::vector<std::vector<int>> prism_f{{0, 1, 2}, {3, 4, 5}, {0, 1, 4, 3}, {1, 2, 5, 4}, {2, 0, 3, 5}};
    const std::vector<std::vector<int>> pyramid_f{{0, 1, 2, 3}, {0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}};
    for (const auto& h : r.hex_corners) cells.emplace_back(h.begin(), h.end()), faces.push_back(hex_f);
    for (const auto& c : r.prisms.cells) cells.emplace_back(c.corners.begin(), c.corners.end()), faces.push_back(prism_f);
    for (const auto& c : r.pyramids.cells) cells.emplace_back(c.corners.begin(), c.corners.begin() + 5), faces.push_back(pyramid_f);
    auto allowed = [&](std::size_t k, const std::set<std::uint32_t>& shared) {
      if (shared.size() <= 1) return true;
      for (const auto& f : faces[k]) {
        std::set<std::uint32_t> face;
        for (std::size_t i = 0; i < f.size(); ++i) {
          face.insert(cells[k][static_cast<std::size_t>(f[i])]);
          if (shared == std::set<std::uint32_t>{cells[k][static_cast<std::size_t>(f[i])], cells[k][static_cast<std::size_t>(f[(i + 1) % f.size()])]}) return true;
        }
        if (shared == face) return true;
      }
      return false;
    };
    for (std::size_t a = 0; a < cells.size(); ++a)
      for (std::size_t b = a + 1; b < cells.size(); ++b) {
        std::set<std::uint32_t> shared;
        for (auto v : cells[a])
          if (std::find(cells[b].begin(), cells[b].end(), v) != cells[b].end()) shared.insert(v);
        EXPECT_TRUE(allowed(a, shared) && allowed(b, shared)) << "cells " << a << " and " << b;
      }
    EXPECT_TRUE(check_3map(t.map).valid());
  }
  EXPECT_GT(passed_over, 0u);  // not vacuous: some candidates did not conform
}

}  // namespace
}  // namespace dartcheck::querymodify::test
