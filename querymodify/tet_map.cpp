#include "querymodify/tet_map.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

namespace dartcheck::querymodify {
namespace {

// The faces of a positively oriented tetrahedron (a, b, c, d), each with
// its outward orientation.
constexpr int face_vertices[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};

double orientation(const std::array<std::uint32_t, 4>& t, const std::vector<std::array<double, 3>>& p) {
  const auto& a = p[t[0]];
  double u[3], v[3], w[3];
  for (int i = 0; i < 3; ++i) {
    u[i] = p[t[1]][i] - a[i];
    v[i] = p[t[2]][i] - a[i];
    w[i] = p[t[3]][i] - a[i];
  }
  return u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) + u[2] * (v[0] * w[1] - v[1] * w[0]);
}

using Key = std::array<std::uint32_t, 3>;
Key sorted(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
  Key k{a, b, c};
  std::sort(k.begin(), k.end());
  return k;
}

Key face_key(const std::array<std::uint32_t, 4>& t, int f) {
  return sorted(t[static_cast<std::size_t>(face_vertices[f][0])], t[static_cast<std::size_t>(face_vertices[f][1])],
                t[static_cast<std::size_t>(face_vertices[f][2])]);
}

// Face f2 and position j2 of the other face of a tetrahedron along the
// edge that face f traverses at position j (in the opposite direction).
struct Across {
  int f, j;
};
constexpr auto across_table = [] {
  std::array<std::array<Across, 3>, 4> out{};
  for (int f = 0; f < 4; ++f)
    for (int j = 0; j < 3; ++j) {
      const int a = face_vertices[f][j], b = face_vertices[f][(j + 1) % 3];
      for (int g = 0; g < 4; ++g)
        for (int k = 0; k < 3; ++k)
          if (g != f && face_vertices[g][k] == b && face_vertices[g][(k + 1) % 3] == a)
            out[static_cast<std::size_t>(f)][static_cast<std::size_t>(j)] = {g, k};
    }
  return out;
}();

std::uint32_t corner(const std::array<std::uint32_t, 4>& t, int f, int j) { return t[static_cast<std::size_t>(face_vertices[f][j % 3])]; }

// The position at which face f of t traverses u -> v, -1 if it does not.
int traversal(const std::array<std::uint32_t, 4>& t, int f, std::uint32_t u, std::uint32_t v) {
  for (int j = 0; j < 3; ++j)
    if (corner(t, f, j) == u && corner(t, f, j + 1) == v) return j;
  return -1;
}

struct FaceUse {
  Key key;
  std::uint32_t tet;
  int face;
  bool operator<(const FaceUse& o) const { return key < o.key || (key == o.key && tet < o.tet); }
};

}  // namespace

TetMap build_tet_map(const std::vector<std::array<std::uint32_t, 4>>& input, const std::vector<std::array<double, 3>>* points) {
  TetMap out;
  out.tets = input;
  const auto n = static_cast<std::uint32_t>(out.tets.size());
  // Faces by vertex set (sorted, so each shared face is two neighbours):
  // the pairs of tetrahedra that share a face.
  std::vector<FaceUse> uses;
  uses.reserve(4 * std::size_t{n});
  for (std::uint32_t t = 0; t < n; ++t)
    for (int f = 0; f < 4; ++f) uses.push_back({face_key(out.tets[t], f), t, f});
  std::sort(uses.begin(), uses.end());
  std::vector<std::pair<std::size_t, std::size_t>> shared;  // indices into uses
  for (std::size_t i = 0; i < uses.size();) {
    std::size_t j = i;
    while (j < uses.size() && uses[j].key == uses[i].key) ++j;
    if (j - i > 2) {
      const Key& k = uses[i].key;
      throw TetMapError(uses[i + 2].tet, fmt::format("the face {} {} {} is shared by {} tetrahedra (at most 2)", k[0], k[1], k[2], j - i));
    }
    if (j - i == 2) shared.emplace_back(i, i + 1);
    i = j;
  }
  // Faces are found again by vertex set: reflecting a tetrahedron (swapping
  // its last two vertices) permutes its faces.
  auto face_with = [&](std::uint32_t t, const Key& k) {
    for (int f = 0; f < 4; ++f)
      if (face_key(out.tets[t], f) == k) return f;
    return -1;
  };
  // Two tetrahedra sharing a face must traverse it in opposite directions.
  auto opposite = [&](const FaceUse& a, const FaceUse& b) {
    const auto& x = out.tets[a.tet];
    const int fa = face_with(a.tet, a.key);
    return traversal(out.tets[b.tet], face_with(b.tet, b.key), corner(x, fa, 1), corner(x, fa, 0)) >= 0;
  };
  if (points) {
    for (std::uint32_t t = 0; t < n; ++t) {
      const double o = orientation(out.tets[t], *points);
      if (o == 0) throw TetMapError(t, fmt::format("tetrahedron {} is flat", t));
      if (o < 0) std::swap(out.tets[t][2], out.tets[t][3]);
    }
    for (const auto& [a, b] : shared)
      if (!opposite(uses[a], uses[b]))
        throw TetMapError(uses[b].tet, fmt::format("tetrahedra {} and {} lie on the same side of their shared face (the mesh folds over)",
                                                   uses[a].tet, uses[b].tet));
  } else {
    // Propagate an orientation from each component's first tetrahedron.
    std::vector<std::vector<std::pair<std::size_t, std::size_t>>> around(n);  // (my use, the other's use)
    for (const auto& [a, b] : shared) {
      around[uses[a].tet].emplace_back(a, b);
      around[uses[b].tet].emplace_back(b, a);
    }
    std::vector<bool> fixed(n, false);
    for (std::uint32_t root = 0; root < n; ++root) {
      if (fixed[root]) continue;
      fixed[root] = true;
      std::vector<std::uint32_t> stack{root};
      while (!stack.empty()) {
        const std::uint32_t t = stack.back();
        stack.pop_back();
        for (const auto& [mine, theirs] : around[t]) {
          const std::uint32_t s2 = uses[theirs].tet;
          if (opposite(uses[mine], uses[theirs])) {
            if (!fixed[s2]) fixed[s2] = true, stack.push_back(s2);
            continue;
          }
          if (fixed[s2]) throw TetMapError(s2, fmt::format("the mesh is not orientable (tetrahedra {} and {})", t, s2));
          std::swap(out.tets[s2][2], out.tets[s2][3]);
          fixed[s2] = true;
          stack.push_back(s2);
        }
      }
    }
  }
  Map& m = out.map;
  m = Map(Model::open_omap(3), 12 * std::size_t{n});
  out.vertex.resize(m.size());
  auto dart = [](std::uint32_t t, int f, int j) {
    return static_cast<Dart>(12 * t + 3 * static_cast<std::uint32_t>(f) + static_cast<std::uint32_t>(j));
  };
  for (std::uint32_t t = 0; t < n; ++t)
    for (int f = 0; f < 4; ++f)
      for (int j = 0; j < 3; ++j) {
        out.vertex[dart(t, f, j)] = corner(out.tets[t], f, j);
        m.sew(1, dart(t, f, j), dart(t, f, (j + 1) % 3));
        const Across a = across_table[static_cast<std::size_t>(f)][static_cast<std::size_t>(j)];
        if (dart(t, f, j) < dart(t, a.f, a.j)) m.sew(2, dart(t, f, j), dart(t, a.f, a.j));
      }
  // β3: the dart u -> v of one tetrahedron and v -> u of the other, on the
  // face they share.
  for (const auto& [a, b] : shared) {
    const Key& k = uses[a].key;
    const std::uint32_t t0 = uses[a].tet, t1 = uses[b].tet;
    const int f0 = face_with(t0, k), f1 = face_with(t1, k);
    for (int j = 0; j < 3; ++j) {
      const int j1 = traversal(out.tets[t1], f1, corner(out.tets[t0], f0, j + 1), corner(out.tets[t0], f0, j));
      m.sew(3, dart(t0, f0, j), dart(t1, f1, j1));
    }
  }
  return out;
}

}  // namespace dartcheck::querymodify
