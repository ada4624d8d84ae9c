#include "querymodify/tet_map.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <functional>

namespace dartcheck::querymodify {
namespace {

BuildError tet_error(std::size_t t, const std::string& message) { return BuildError(message, BuildError::Culprit::cell, t); }

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

using Tets = std::vector<std::array<std::uint32_t, 4>>;
using Named = std::function<std::uint64_t(std::uint64_t)>;  // an index as the file numbers it

// The faces by vertex set (sorted, so each shared face is two neighbours),
// and the pairs of uses that are one face of two tetrahedra.
struct SharedFaces {
  std::vector<FaceUse> uses;
  std::vector<std::pair<std::size_t, std::size_t>> shared;  // indices into uses
};

SharedFaces shared_faces(const Tets& tets, const Named& named) {
  SharedFaces out;
  const auto n = static_cast<std::uint32_t>(tets.size());
  out.uses.reserve(4 * std::size_t{n});
  for (std::uint32_t t = 0; t < n; ++t)
    for (int f = 0; f < 4; ++f) out.uses.push_back({face_key(tets[t], f), t, f});
  std::sort(out.uses.begin(), out.uses.end());
  const auto& uses = out.uses;
  for (std::size_t i = 0; i < uses.size();) {
    std::size_t j = i;
    while (j < uses.size() && uses[j].key == uses[i].key) ++j;
    if (j - i > 2) {
      const Key& k = uses[i].key;
      throw tet_error(uses[i + 2].tet, fmt::format("the face {} {} {} is shared by {} tetrahedra (at most 2)", named(k[0]), named(k[1]), named(k[2]), j - i));
    }
    if (j - i == 2) out.shared.emplace_back(i, i + 1);
    i = j;
  }
  return out;
}

// Two tetrahedra sharing a face must traverse it in opposite directions.
// Faces are found again by vertex set: reflecting a tetrahedron (swapping
// its last two vertices) permutes its faces.
bool opposite(const Tets& tets, const FaceUse& a, const FaceUse& b) {
  const auto face_with = [&](std::uint32_t t, const Key& k) {
    for (int f = 0; f < 4; ++f)
      if (face_key(tets[t], f) == k) return f;
    return -1;
  };
  const auto& x = tets[a.tet];
  const int fa = face_with(a.tet, a.key);
  return traversal(tets[b.tet], face_with(b.tet, b.key), corner(x, fa, 1), corner(x, fa, 0)) >= 0;
}

// With points: each tetrahedron positively oriented, and the mesh must not
// fold over a shared face.
void orient_by_points(Tets& tets, const SharedFaces& faces, const std::vector<std::array<double, 3>>& points, const Named& named) {
  for (std::uint32_t t = 0; t < tets.size(); ++t) {
    const double o = orientation(tets[t], points);
    if (o == 0) throw tet_error(t, fmt::format("tetrahedron {} is flat", named(t)));
    if (o < 0) std::swap(tets[t][2], tets[t][3]);
  }
  for (const auto& [a, b] : faces.shared)
    if (!opposite(tets, faces.uses[a], faces.uses[b]))
      throw tet_error(faces.uses[b].tet, fmt::format("tetrahedra {} and {} lie on the same side of their shared face (the mesh folds over)",
                                                     named(faces.uses[a].tet), named(faces.uses[b].tet)));
}

// Without points: an orientation propagated from each component's first
// tetrahedron.
void orient_by_propagation(Tets& tets, const SharedFaces& faces, const Named& named) {
  const auto n = static_cast<std::uint32_t>(tets.size());
  const auto& uses = faces.uses;
  std::vector<std::vector<std::pair<std::size_t, std::size_t>>> around(n);  // (my use, the other's use)
  for (const auto& [a, b] : faces.shared) {
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
        if (opposite(tets, uses[mine], uses[theirs])) {
          if (!fixed[s2]) fixed[s2] = true, stack.push_back(s2);
          continue;
        }
        if (fixed[s2]) throw tet_error(s2, fmt::format("the mesh is not orientable (tetrahedra {} and {})", named(t), named(s2)));
        std::swap(tets[s2][2], tets[s2][3]);
        fixed[s2] = true;
        stack.push_back(s2);
      }
    }
  }
}

}  // namespace

TetMap build_tet_map(const std::vector<std::array<std::uint32_t, 4>>& input, const std::vector<std::array<double, 3>>* points,
                     std::uint32_t numbered_from) {
  const Named named = [numbered_from](std::uint64_t index) { return index + numbered_from; };
  TetMap out;
  out.tets = input;
  const auto n = static_cast<std::uint32_t>(out.tets.size());
  const SharedFaces faces = shared_faces(out.tets, named);
  if (points)
    orient_by_points(out.tets, faces, *points, named);
  else
    orient_by_propagation(out.tets, faces, named);
  // Dart 12t + 3f + j: the j-th vertex of face f of tetrahedron t.
  CellComplex cells;
  cells.vertices.reserve(12 * std::size_t{n});
  cells.face_begin.reserve(4 * std::size_t{n} + 1);
  cells.cell_begin.reserve(std::size_t{n} + 1);
  for (std::uint32_t t = 0; t < n; ++t) {
    for (int f = 0; f < 4; ++f) {
      const std::array<std::uint32_t, 3> face{corner(out.tets[t], f, 0), corner(out.tets[t], f, 1), corner(out.tets[t], f, 2)};
      cells.add_face(face);
    }
    cells.end_cell();
  }
  GluedCells glued = glue_cells(cells);
  out.map = std::move(glued.map);
  out.vertex = std::move(glued.vertex);
  return out;
}

}  // namespace dartcheck::querymodify
