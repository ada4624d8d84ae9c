#include "generators/polygon_soup.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <map>
#include <utility>
#include <unordered_map>

namespace dartcheck {
namespace {

using Key = std::uint64_t;
Key edge_key(std::uint32_t u, std::uint32_t w) { return (Key{u} << 32) | w; }

void check_face(const Polygon& f, std::size_t index) {
  constexpr auto face = BuildError::Culprit::face;
  if (f.size() < 3) throw BuildError(fmt::format("face {} has {} vertices (at least 3 expected)", index, f.size()), face, index);
  Polygon sorted = f;
  std::sort(sorted.begin(), sorted.end());
  if (auto it = std::adjacent_find(sorted.begin(), sorted.end()); it != sorted.end())
    throw BuildError(fmt::format("face {} visits vertex {} twice", index, *it), face, index);
}

void loop_dims_above(Map& m, Dim above, Dart first, Dart end) {
  for (Dim i : m.model().dims)
    if (i > above)
      for (Dart d = first; d < end; ++d) m.sew(i, d, d);
}

// G-map darts of one surface: face f side e has darts 2e (at vertex f[e])
// and 2e+1 (at vertex f[e+1]), offset by the face's first dart.
struct GSurface {
  std::vector<Dart> first;  // first dart of each face
};

GSurface sew_gmap_surface(Map& m, const std::vector<Polygon>& faces, std::size_t face_base) {
  GSurface s;
  for (const Polygon& f : faces) s.first.push_back(m.add_darts(2 * f.size()));
  // Undirected edge -> the (face, side) pairs that use it.
  std::unordered_map<Key, std::vector<std::pair<std::size_t, std::size_t>>> edges;
  for (std::size_t fi = 0; fi < faces.size(); ++fi) {
    const Polygon& f = faces[fi];
    check_face(f, face_base + fi);
    const std::size_t k = f.size();
    const Dart b = s.first[fi];
    for (std::size_t e = 0; e < k; ++e) {
      m.sew(0, b + 2 * e, b + 2 * e + 1);
      m.sew(1, b + 2 * e + 1, b + 2 * ((e + 1) % k));
      const auto u = f[e], w = f[(e + 1) % k];
      edges[edge_key(std::min(u, w), std::max(u, w))].emplace_back(fi, e);
    }
  }
  for (auto& [key, uses] : edges) {
    if (uses.size() > 2)
      throw BuildError(
          fmt::format("edge ({}, {}) is shared by {} faces (a non-manifold edge; at most 2 expected)", key >> 32, key & 0xffffffffU, uses.size()),
          BuildError::Culprit::face, face_base + uses[2].first);
    auto dart_at = [&](std::size_t fi, std::size_t e, std::uint32_t vertex) { return s.first[fi] + 2 * e + (faces[fi][e] == vertex ? 0 : 1); };
    const auto u = static_cast<std::uint32_t>(key >> 32), w = static_cast<std::uint32_t>(key & 0xffffffffU);
    if (uses.size() == 1) {
      auto [fi, e] = uses[0];
      m.sew(2, dart_at(fi, e, u), dart_at(fi, e, u));
      m.sew(2, dart_at(fi, e, w), dart_at(fi, e, w));
    } else {
      auto [f1, e1] = uses[0];
      auto [f2, e2] = uses[1];
      m.sew(2, dart_at(f1, e1, u), dart_at(f2, e2, u));
      m.sew(2, dart_at(f1, e1, w), dart_at(f2, e2, w));
    }
  }
  return s;
}

Map build_omap_surface(const Model& model, const std::vector<Polygon>& faces) {
  if (model.dimension() != 2)
    throw BuildError(fmt::format("surfaces are built for 2-O-maps only, not {}: a {}-O-map needs every face {}-sewn", model.name, model.dimension(),
                                 model.dimension()));
  Map m(model);
  std::unordered_map<Key, Dart> half_edges;  // directed edge -> dart
  std::unordered_map<Key, std::size_t> face_of;
  for (std::size_t fi = 0; fi < faces.size(); ++fi) {
    const Polygon& f = faces[fi];
    check_face(f, fi);
    const Dart b = m.add_darts(f.size());
    for (std::size_t e = 0; e < f.size(); ++e) {
      const auto u = f[e], w = f[(e + 1) % f.size()];
      m.sew(1, b + e, b + (e + 1) % f.size());
      auto [it, fresh] = half_edges.emplace(edge_key(u, w), b + e);
      if (!fresh) {
        const bool three = half_edges.count(edge_key(w, u)) > 0;
        throw BuildError(three ? fmt::format("edge ({}, {}) is shared by more than two faces (a non-manifold edge)", u, w)
                               : fmt::format("faces {} and {} both traverse edge ({}, {}) from {} to {}: inconsistent orientation",
                                             face_of[edge_key(u, w)], fi, u, w, u, w),
                         BuildError::Culprit::face, fi);
      }
      face_of[edge_key(u, w)] = fi;
    }
  }
  // Pair opposite half-edges; a half-edge without an opposite gets one in an
  // outer face, whose darts are then chained around the boundary.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> outer;  // (u, w) of each outer dart, from u to w
  std::vector<Dart> outer_dart;
  for (const auto& [key, d] : half_edges) {
    const auto u = static_cast<std::uint32_t>(key >> 32), w = static_cast<std::uint32_t>(key & 0xffffffffU);
    auto opp = half_edges.find(edge_key(w, u));
    if (opp != half_edges.end()) {
      m.sew(2, d, opp->second);
    } else {
      outer.emplace_back(w, u);
    }
  }
  std::sort(outer.begin(), outer.end());
  const Dart ob = m.add_darts(outer.size());
  // Outer dart from u to w follows the outer dart that starts at w; several
  // boundary fans at one vertex are chained in sorted order.
  std::multimap<std::uint32_t, Dart> starting_at;
  for (std::size_t k = 0; k < outer.size(); ++k) {
    starting_at.emplace(outer[k].first, ob + static_cast<Dart>(k));
    m.sew(2, ob + static_cast<Dart>(k), half_edges.at(edge_key(outer[k].second, outer[k].first)));
  }
  for (std::size_t k = 0; k < outer.size(); ++k) {
    auto it = starting_at.find(outer[k].second);
    if (it == starting_at.end()) throw BuildError(fmt::format("the boundary does not close at vertex {}", outer[k].second));
    m.sew(1, ob + static_cast<Dart>(k), it->second);
    starting_at.erase(it);
  }
  return m;
}

}  // namespace

Map build_surface(const Model& model, const std::vector<Polygon>& faces) {
  if (!model.is_generalized()) return build_omap_surface(model, faces);
  if (model.dimension() < 2) throw BuildError(fmt::format("surfaces need a model of dimension 2 at least, not {}", model.name));
  Map m(model);
  sew_gmap_surface(m, faces, 0);
  loop_dims_above(m, 2, 0, static_cast<Dart>(m.size()));
  return m;
}

Map build_volumes(const Model& model, const std::vector<Polyhedron>& volumes) {
  if (!model.is_generalized() || model.dimension() < 3)
    throw BuildError(fmt::format("volumes are built for n-G-maps with n >= 3, not {}", model.name));
  Map m(model);
  std::vector<GSurface> surfaces;
  std::size_t face_base = 0;
  for (const Polyhedron& v : volumes) {
    surfaces.push_back(sew_gmap_surface(m, v, face_base));
    face_base += v.size();
  }
  for (Dart d = 0; d < m.size(); ++d) m.sew(3, d, d);
  const CellComplex complex = CellComplex::of(volumes);
  const std::vector<std::uint32_t> volume_of = complex.face_cells();
  for (const auto& [ga, gb] : shared_faces(complex)) {
    // Named, not structured bindings: clang 14 cannot capture those.
    const std::size_t v1 = volume_of[ga], f1 = ga - complex.cell_begin[v1];
    const std::size_t v2 = volume_of[gb], f2 = gb - complex.cell_begin[v2];
    const Polygon& a = volumes[v1][f1];
    const Polygon& b = volumes[v2][f2];
    const std::size_t k = a.size();
    // The dart of face b at vertex `at` on the side towards `to`.
    auto find_dart = [&](std::uint32_t at, std::uint32_t to) -> Dart {
      for (std::size_t e = 0; e < k; ++e) {
        if (b[e] == at && b[(e + 1) % k] == to) return surfaces[v2].first[f2] + 2 * e;
        if (b[(e + 1) % k] == at && b[e] == to) return surfaces[v2].first[f2] + 2 * e + 1;
      }
      throw BuildError(fmt::format("faces {} of volume {} and {} of volume {} have the same vertices but not the same edges", f1, v1, f2, v2),
                       BuildError::Culprit::cell, v2);
    };
    for (std::size_t e = 0; e < k; ++e) {
      const auto u = a[e], w = a[(e + 1) % k];
      const Dart da = surfaces[v1].first[f1] + 2 * e;
      m.sew(3, da, find_dart(u, w));
      m.sew(3, da + 1, find_dart(w, u));
    }
  }
  loop_dims_above(m, 3, 0, static_cast<Dart>(m.size()));
  return m;
}

}  // namespace dartcheck
