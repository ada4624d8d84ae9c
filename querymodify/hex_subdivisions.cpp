#include "querymodify/hex_subdivisions.hpp"

#include <algorithm>
#include <bit>
#include <cstdlib>
#include <set>
#include <thread>

#include "core/disjoint_sets.hpp"

namespace dartcheck::querymodify {
namespace {

constexpr int bits(unsigned m) { return std::popcount(m); }

// Index of each tetrahedron mask among the candidates, -1 if none.
const std::array<int, 256>& tet_index() {
  static const std::array<int, 256> index = [] {
    std::array<int, 256> out{};
    out.fill(-1);
    const auto& c = candidate_tets();
    for (std::size_t k = 0; k < c.size(); ++k) out[c[k]] = static_cast<int>(k);
    return out;
  }();
  return index;
}

TetMask face_mask(int f) {
  TetMask m = 0;
  for (int v : hex_faces()[static_cast<std::size_t>(f)]) m = static_cast<TetMask>(m | (1u << v));
  return m;
}

// The face whose 4 vertices hold triangle t, -1 if none.
int face_of_triangle(unsigned t) {
  for (int f = 0; f < 6; ++f)
    if ((t & face_mask(f)) == t) return f;
  return -1;
}

// Backtracking over sets of tetrahedra: every boundary triangle (the two
// of each face's chosen diagonal) in exactly one, every other triangle in
// none or two; an open triangle (the one with the fewest choices) is
// closed by each admissible tetrahedron in turn.
class Enumerator {
 public:
  explicit Enumerator(int diagonals) {
    required_.fill(2);
    for (unsigned t = 0; t < 256; ++t) {
      if (bits(t) != 3) continue;
      const int f = face_of_triangle(t);
      if (f < 0) continue;
      // Diagonal 0 of face (a, b, c, d) is a-c: triangles without b or d.
      // Face (a, b, c, d) split by a-c has triangles abc and acd (both
      // hold a and c), split by b-d abd and bcd. Bit f of `diagonals`: b-d.
      const auto& q = hex_faces()[static_cast<std::size_t>(f)];
      const bool diagonal_ac = !((diagonals >> f) & 1);
      const bool has_ac = (t & (1u << q[0])) && (t & (1u << q[2]));
      // The other diagonal's triangles are not on the boundary; they may
      // still be interior triangles (a non-planar face lets the other
      // diagonal pass inside the hex), in two tetrahedra or none.
      required_[t] = has_ac == diagonal_ac ? 1 : 2;
    }
    count_.fill(0);
    // An edge is on the boundary iff it is in a boundary triangle.
    boundary_edge_.fill(false);
    for (unsigned t = 0; t < 256; ++t)
      if (bits(t) == 3 && required_[t] == 1)
        for (int v = 0; v < 8; ++v)
          if (t & (1u << v)) boundary_edge_[t & ~(1u << v)] = true;
  }

  void run(std::set<std::uint64_t>& out) { search(0, out); }

 private:
  bool admissible(TetMask tet) const {
    for (int v = 0; v < 8; ++v)
      if (tet & (1u << v)) {
        const unsigned t = tet & ~(1u << v);
        if (count_[t] + 1 > required_[t]) return false;
      }
    return true;
  }
  void add(TetMask tet, int d) {
    for (int v = 0; v < 8; ++v)
      if (tet & (1u << v)) count_[tet & ~(1u << v)] = static_cast<std::uint8_t>(count_[tet & ~(1u << v)] + d);
  }

  // Branches at the open triangle with the fewest admissible closing
  // tetrahedra, and stops where one has none. Each open triangle needs
  // exactly one more tetrahedron, so the branches are disjoint and every
  // subdivision is reached once.
  void search(std::uint64_t chosen, std::set<std::uint64_t>& out) {
    const auto& c = candidate_tets();
    int open = -1, fewest = 99;
    for (const Triangle& tri : triangles()) {
      const unsigned t = tri.mask;
      if (count_[t] + 1 != required_[t]) continue;  // not open
      int n = 0;
      for (int k : tri.closers) n += !((chosen >> k) & 1) && admissible(c[static_cast<std::size_t>(k)]);
      if (n == 0) return;
      if (n < fewest) fewest = n, open = static_cast<int>(&tri - triangles().data());
    }
    if (open < 0) {
      if (is_ball(chosen)) out.insert(chosen);
      return;
    }
    for (int k : triangles()[static_cast<std::size_t>(open)].closers) {
      const TetMask tet = c[static_cast<std::size_t>(k)];
      if ((chosen >> k) & 1 || !admissible(tet)) continue;
      add(tet, +1);
      if (edge_links_ok(chosen | (std::uint64_t{1} << k), tet)) search(chosen | (std::uint64_t{1} << k), out);
      add(tet, -1);
    }
  }

  // In a ball, the tetrahedra around an interior edge form one cycle, those
  // around a boundary edge one path. The link of edge ab is the graph on
  // the other vertices with an edge xy per tetrahedron abxy (degrees are
  // at most 2, by the triangle counts): a closed cycle on a boundary edge,
  // or next to another component, can never be repaired by adding
  // tetrahedra. Checked on the edges of the tetrahedron just added; cuts
  // the closed non-ball complexes (most leaves without it).
  bool edge_links_ok(std::uint64_t chosen, TetMask added) const {
    const auto& c = candidate_tets();
    for (int a = 0; a < 8; ++a)
      for (int b = a + 1; b < 8; ++b) {
        const unsigned ab = (1u << a) | (1u << b);
        if ((added & ab) != ab) continue;
        std::array<int, 8> parent{0, 1, 2, 3, 4, 5, 6, 7};
        auto find = [&](int x) { return find_representative(parent, x); };
        std::array<int, 8> edges{}, vertices{};
        unsigned touched = 0;
        for (std::uint64_t rest = chosen; rest; rest &= rest - 1) {
          const unsigned t = c[static_cast<std::size_t>(std::countr_zero(rest))];
          if ((t & ab) != ab) continue;
          const unsigned xy = t & ~ab;
          const int x = std::countr_zero(xy), y = 31 - std::countl_zero(xy);
          touched |= xy;
          attach_set(parent, x, y);
        }
        for (std::uint64_t rest = chosen; rest; rest &= rest - 1) {
          const unsigned t = c[static_cast<std::size_t>(std::countr_zero(rest))];
          if ((t & ab) == ab) ++edges[static_cast<std::size_t>(find(std::countr_zero(t & ~ab)))];
        }
        int components = 0;
        bool cycle = false;
        for (int x = 0; x < 8; ++x)
          if (touched & (1u << x)) ++vertices[static_cast<std::size_t>(find(x))];
        for (int r = 0; r < 8; ++r)
          if (vertices[static_cast<std::size_t>(r)] > 0) {
            ++components;
            cycle |= edges[static_cast<std::size_t>(r)] == vertices[static_cast<std::size_t>(r)];
          }
        if (cycle && (boundary_edge_[ab] || components > 1)) return false;
      }
    return true;
  }

  // The 56 triangles on the 8 vertices, each with the candidate
  // tetrahedra that contain it.
  struct Triangle {
    unsigned mask = 0;
    std::vector<int> closers;
  };
  static const std::vector<Triangle>& triangles() {
    static const std::vector<Triangle> all = [] {
      std::vector<Triangle> out;
      for (unsigned t = 0; t < 256; ++t) {
        if (bits(t) != 3) continue;
        Triangle tri{t, {}};
        for (int v = 0; v < 8; ++v)
          if (!(t & (1u << v)) && tet_index()[t | (1u << v)] >= 0) tri.closers.push_back(tet_index()[t | (1u << v)]);
        out.push_back(std::move(tri));
      }
      return out;
    }();
    return all;
  }

  // Every vertex link is a disk: connected, edges in one or two of its
  // triangles, Euler characteristic 1 (all 8 vertices are on the
  // boundary). With the boundary the hex surface, the complex is a ball.
  static bool is_ball(std::uint64_t chosen) {
    const auto tets = tets_of(chosen);
    for (int v = 0; v < 8; ++v) {
      std::vector<unsigned> triangles;
      for (TetMask t : tets)
        if (t & (1u << v)) triangles.push_back(t & ~(1u << v));
      if (triangles.empty()) return false;
      std::array<int, 256> edge_uses{};
      unsigned vertices = 0;
      for (unsigned t : triangles) {
        vertices |= t;
        for (int w = 0; w < 8; ++w)
          if (t & (1u << w)) ++edge_uses[t & ~(1u << w)];
      }
      int edges = 0;
      for (unsigned e = 0; e < 256; ++e) {
        if (edge_uses[e] > 2) return false;
        edges += edge_uses[e] > 0;
      }
      if (bits(vertices) - edges + static_cast<int>(triangles.size()) != 1) return false;
      // Connected through shared edges.
      std::vector<bool> seen(triangles.size(), false);
      std::vector<std::size_t> stack{0};
      seen[0] = true;
      std::size_t reached = 1;
      while (!stack.empty()) {
        const unsigned t = triangles[stack.back()];
        stack.pop_back();
        for (std::size_t j = 0; j < triangles.size(); ++j)
          if (!seen[j] && bits(t & triangles[j]) == 2) {
            seen[j] = true;
            ++reached;
            stack.push_back(j);
          }
      }
      if (reached != triangles.size()) return false;
    }
    return true;
  }

  std::array<int, 256> required_{};
  std::array<std::uint8_t, 256> count_{};
  std::array<bool, 256> boundary_edge_{};
};

}  // namespace

const std::array<std::array<int, 4>, 6>& hex_faces() {
  // x = 0, x = 1, y = 0, y = 1, z = 0, z = 1, each a cycle.
  static const std::array<std::array<int, 4>, 6> faces{{{0, 2, 6, 4}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 5, 7, 6}}};
  return faces;
}

const std::vector<TetMask>& candidate_tets() {
  static const std::vector<TetMask> tets = [] {
    std::vector<TetMask> out;
    for (unsigned m = 0; m < 256; ++m) {
      if (bits(m) != 4) continue;
      bool face = false;
      for (int f = 0; f < 6; ++f) face |= m == face_mask(f);
      if (!face) out.push_back(static_cast<TetMask>(m));
    }
    return out;
  }();
  return tets;
}

const std::vector<std::array<int, 8>>& cube_symmetries() {
  static const std::vector<std::array<int, 8>> group = [] {
    std::vector<std::array<int, 8>> rotations, reflections;
    std::array<int, 3> axes{0, 1, 2};
    do {
      // The parity of the axis permutation and of the flips gives the
      // determinant's sign.
      const int swaps = (axes[0] != 0) + (axes[1] != 1) + (axes[2] != 2);
      const bool odd_permutation = swaps == 2;
      for (int flips = 0; flips < 8; ++flips) {
        std::array<int, 8> p{};
        for (int v = 0; v < 8; ++v) {
          int w = 0;
          for (int i = 0; i < 3; ++i) w |= ((v >> axes[static_cast<std::size_t>(i)]) & 1) << i;
          p[static_cast<std::size_t>(v)] = w ^ flips;
        }
        const bool odd = odd_permutation != (std::popcount(static_cast<unsigned>(flips)) % 2 == 1);
        (odd ? reflections : rotations).push_back(p);
      }
    } while (std::next_permutation(axes.begin(), axes.end()));
    rotations.insert(rotations.end(), reflections.begin(), reflections.end());
    return rotations;
  }();
  return group;
}

std::vector<TetMask> tets_of(std::uint64_t subdivision) {
  std::vector<TetMask> out;
  const auto& c = candidate_tets();
  for (std::size_t k = 0; k < c.size(); ++k)
    if ((subdivision >> k) & 1) out.push_back(c[k]);
  return out;
}

const std::vector<std::uint64_t>& enumerate_hex_subdivisions() {
  static const std::vector<std::uint64_t> all = [] {
    // The 64 choices of face diagonals are independent searches: split
    // between the cores (the result is a sorted set either way).
    const unsigned threads = std::clamp(std::thread::hardware_concurrency(), 1u, 8u);
    std::vector<std::set<std::uint64_t>> found(threads);
    auto work = [&](unsigned t) {
      for (int diagonals = static_cast<int>(t); diagonals < 64; diagonals += static_cast<int>(threads)) Enumerator(diagonals).run(found[t]);
    };
    std::vector<std::thread> pool;
    for (unsigned t = 1; t < threads; ++t) pool.emplace_back(work, t);
    work(0);
    for (auto& th : pool) th.join();
    std::set<std::uint64_t> merged;
    for (const auto& f : found) merged.insert(f.begin(), f.end());
    return std::vector<std::uint64_t>(merged.begin(), merged.end());
  }();
  return all;
}

std::uint64_t canonical_subdivision(std::uint64_t subdivision, int group_size) {
  std::uint64_t best = ~std::uint64_t{0};
  const auto& group = cube_symmetries();
  const auto tets = tets_of(subdivision);
  for (int g = 0; g < group_size; ++g) {
    std::uint64_t image = 0;
    for (TetMask t : tets) {
      unsigned m = 0;
      for (int v = 0; v < 8; ++v)
        if (t & (1u << v)) m |= 1u << group[static_cast<std::size_t>(g)][static_cast<std::size_t>(v)];
      image |= std::uint64_t{1} << tet_index()[m];
    }
    best = std::min(best, image);
  }
  return best;
}

bool triangulates_unit_cube(std::uint64_t subdivision) {
  const auto tets = tets_of(subdivision);
  auto point = [](int v) { return std::array<long, 3>{v & 1, (v >> 1) & 1, (v >> 2) & 1}; };
  // Six times the signed volume of (a, b, c, d).
  auto det = [&](int a, int b, int c, int d) {
    const auto pa = point(a), pb = point(b), pc = point(c), pd = point(d);
    const long u[3] = {pb[0] - pa[0], pb[1] - pa[1], pb[2] - pa[2]}, v[3] = {pc[0] - pa[0], pc[1] - pa[1], pc[2] - pa[2]},
               w[3] = {pd[0] - pa[0], pd[1] - pa[1], pd[2] - pa[2]};
    return u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) + u[2] * (v[0] * w[1] - v[1] * w[0]);
  };
  auto vertices = [](unsigned m) {
    std::vector<int> out;
    for (int v = 0; v < 8; ++v)
      if (m & (1u << v)) out.push_back(v);
    return out;
  };
  long volume6 = 0;
  for (TetMask t : tets) {
    const auto v = vertices(t);
    const long d = std::labs(det(v[0], v[1], v[2], v[3]));
    if (d == 0) return false;
    volume6 += d;
  }
  if (volume6 != 6) return false;
  // Interior triangles: the opposite vertices on opposite sides.
  for (std::size_t i = 0; i < tets.size(); ++i)
    for (std::size_t j = i + 1; j < tets.size(); ++j) {
      const unsigned shared = tets[i] & tets[j];
      if (bits(shared) != 3) continue;
      const auto tri = vertices(shared);
      const int a = vertices(tets[i] & ~shared)[0], b = vertices(tets[j] & ~shared)[0];
      if (det(tri[0], tri[1], tri[2], a) * det(tri[0], tri[1], tri[2], b) >= 0) return false;
    }
  return true;
}

}  // namespace dartcheck::querymodify
