#include "querymodify/tet_map.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <map>
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
  return sorted(t[static_cast<std::size_t>(face_vertices[f][0])], t[static_cast<std::size_t>(face_vertices[f][1])], t[static_cast<std::size_t>(face_vertices[f][2])]);
}

// True if tetrahedron t, as oriented, traverses u -> v on one of its faces
// with vertex set k.
bool traverses(const std::array<std::uint32_t, 4>& t, const Key& k, std::uint32_t u, std::uint32_t v) {
  for (int f = 0; f < 4; ++f)
    if (face_key(t, f) == k)
      for (int j = 0; j < 3; ++j)
        if (t[static_cast<std::size_t>(face_vertices[f][j])] == u && t[static_cast<std::size_t>(face_vertices[f][(j + 1) % 3])] == v) return true;
  return false;
}

}  // namespace

TetMap build_tet_map(const std::vector<std::array<std::uint32_t, 4>>& input, const std::vector<std::array<double, 3>>* points) {
  TetMap out;
  out.tets = input;
  // Faces by vertex set: the tetrahedra that have them.
  std::map<Key, std::vector<std::uint32_t>> faces;
  for (std::uint32_t t = 0; t < out.tets.size(); ++t)
    for (int f = 0; f < 4; ++f) faces[face_key(out.tets[t], f)].push_back(t);
  for (const auto& [k, uses] : faces)
    if (uses.size() > 2) throw std::invalid_argument(fmt::format("the face {} {} {} is shared by {} tetrahedra (at most 2)", k[0], k[1], k[2], uses.size()));
  if (points) {
    for (std::uint32_t t = 0; t < out.tets.size(); ++t) {
      const double o = orientation(out.tets[t], *points);
      if (o == 0) throw std::invalid_argument(fmt::format("tetrahedron {} is flat", t));
      if (o < 0) std::swap(out.tets[t][2], out.tets[t][3]);
    }
  } else {
    // Propagate: two tetrahedra sharing a face traverse it in opposite
    // directions.
    std::vector<bool> fixed(out.tets.size(), false);
    for (std::uint32_t root = 0; root < out.tets.size(); ++root) {
      if (fixed[root]) continue;
      fixed[root] = true;
      std::vector<std::uint32_t> stack{root};
      while (!stack.empty()) {
        const std::uint32_t t = stack.back();
        stack.pop_back();
        for (int f = 0; f < 4; ++f) {
          const auto& x = out.tets[t];
          const Key k = face_key(x, f);
          const std::uint32_t u = x[static_cast<std::size_t>(face_vertices[f][0])], v = x[static_cast<std::size_t>(face_vertices[f][1])];
          for (std::uint32_t s : faces.at(k)) {
            if (s == t) continue;
            const bool opposite = traverses(out.tets[s], k, v, u);
            if (fixed[s] && !opposite) throw std::invalid_argument(fmt::format("the mesh is not orientable (tetrahedra {} and {})", t, s));
            if (!fixed[s]) {
              if (!opposite) std::swap(out.tets[s][2], out.tets[s][3]);
              fixed[s] = true;
              stack.push_back(s);
            }
          }
        }
      }
    }
  }
  Map& m = out.map;
  m = Map(Model::open_omap(3), 12 * out.tets.size());
  out.vertex.resize(m.size());
  auto dart = [](std::uint32_t t, int f, int j) { return static_cast<Dart>(12 * t + 3 * static_cast<std::uint32_t>(f) + static_cast<std::uint32_t>(j)); };
  // Directed edge of a tetrahedron -> its dart.
  std::map<std::tuple<std::uint32_t, std::uint32_t, std::uint32_t>, Dart> in_tet;
  for (std::uint32_t t = 0; t < out.tets.size(); ++t)
    for (int f = 0; f < 4; ++f)
      for (int j = 0; j < 3; ++j) {
        const auto& x = out.tets[t];
        const std::uint32_t u = x[static_cast<std::size_t>(face_vertices[f][j])], v = x[static_cast<std::size_t>(face_vertices[f][(j + 1) % 3])];
        out.vertex[dart(t, f, j)] = u;
        m.sew(1, dart(t, f, j), dart(t, f, (j + 1) % 3));
        in_tet[{t, u, v}] = dart(t, f, j);
      }
  for (std::uint32_t t = 0; t < out.tets.size(); ++t)
    for (int f = 0; f < 4; ++f)
      for (int j = 0; j < 3; ++j) {
        const Dart d = dart(t, f, j);
        const std::uint32_t u = out.vertex[d], v = out.vertex[m.link(1, d)];
        m.sew(2, d, in_tet.at({t, v, u}));  // the other face of t along u-v
      }
  // β3: the dart u -> v of one tetrahedron and v -> u of the other, on the
  // face they share.
  for (const auto& [k, uses] : faces) {
    if (uses.size() != 2) continue;
    for (int f = 0; f < 4; ++f) {
      if (face_key(out.tets[uses[0]], f) != k) continue;
      for (int j = 0; j < 3; ++j) {
        const Dart d = dart(uses[0], f, j);
        const std::uint32_t u = out.vertex[d], v = out.vertex[m.link(1, d)];
        m.sew(3, d, in_tet.at({uses[1], v, u}));
      }
    }
  }
  return out;
}

}  // namespace dartcheck::querymodify
