#include "core/cell_gluing.hpp"

#include <algorithm>
#include <numeric>
#include <tuple>

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace dartcheck {

CellComplex CellComplex::of(const std::vector<Polyhedron>& cells) {
  CellComplex out;
  for (const Polyhedron& c : cells) {
    for (const Polygon& f : c) out.add_face(f);
    out.end_cell();
  }
  return out;
}

std::vector<std::uint32_t> CellComplex::face_cells() const {
  std::vector<std::uint32_t> out(faces());
  for (std::size_t c = 0; c < cells(); ++c)
    for (std::size_t f = cell_begin[c]; f < cell_begin[c + 1]; ++f) out[f] = static_cast<std::uint32_t>(c);
  return out;
}

std::vector<std::pair<std::size_t, std::size_t>> shared_faces(const CellComplex& cx) {
  // Each face's vertex set, sorted in place in a copy with the same offsets.
  std::vector<std::uint32_t> keys = cx.vertices;
  for (std::size_t f = 0; f < cx.faces(); ++f)
    std::sort(keys.begin() + static_cast<std::ptrdiff_t>(cx.face_begin[f]), keys.begin() + static_cast<std::ptrdiff_t>(cx.face_begin[f + 1]));
  auto key = [&](std::size_t f) { return std::span<const std::uint32_t>(keys.data() + cx.face_begin[f], cx.face_begin[f + 1] - cx.face_begin[f]); };
  // By size, then vertex set, then face index: equal sets are neighbours.
  auto less = [&](std::size_t a, std::size_t b) {
    const auto ka = key(a), kb = key(b);
    if (ka.size() != kb.size()) return ka.size() < kb.size();
    if (std::ranges::lexicographical_compare(ka, kb)) return true;
    if (std::ranges::lexicographical_compare(kb, ka)) return false;
    return a < b;
  };
  std::vector<std::size_t> order(cx.faces());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), less);
  auto same = [&](std::size_t a, std::size_t b) { return std::ranges::equal(key(a), key(b)); };
  std::vector<std::pair<std::size_t, std::size_t>> out;
  std::vector<std::uint32_t> cell_of;
  for (std::size_t i = 0; i < order.size();) {
    std::size_t j = i + 1;
    while (j < order.size() && same(order[i], order[j])) ++j;
    if (j - i > 2) {
      if (cell_of.empty()) cell_of = cx.face_cells();
      throw BuildError(fmt::format("the face {} is shared by {} cells (at most 2)", fmt::join(key(order[i]), " "), j - i), BuildError::Culprit::cell,
                       cell_of[order[i + 2]]);
    }
    if (j - i == 2) out.emplace_back(order[i], order[i + 1]);
    i = j;
  }
  std::sort(out.begin(), out.end());
  return out;
}

namespace {

constexpr auto in_cell = BuildError::Culprit::cell;

void check_faces(const CellComplex& cx, const std::vector<std::uint32_t>& cell_of) {
  std::vector<std::uint32_t> sorted;
  for (std::size_t f = 0; f < cx.faces(); ++f) {
    const auto face = cx.face(f);
    const std::uint32_t c = cell_of[f];
    if (face.size() < 3) throw BuildError(fmt::format("cell {} has a face of {} vertices (at least 3)", c, face.size()), in_cell, c);
    sorted.assign(face.begin(), face.end());
    std::sort(sorted.begin(), sorted.end());
    if (auto it = std::adjacent_find(sorted.begin(), sorted.end()); it != sorted.end())
      throw BuildError(fmt::format("a face of cell {} visits vertex {} twice", c, *it), in_cell, c);
  }
}

// β2 in cell c: the dart u -> v of one face and v -> u of another.
using HalfEdges = std::vector<std::tuple<std::uint32_t, std::uint32_t, Dart>>;  // (u, v, dart)

void sew_cell_edges(Map& m, const CellComplex& cx, const std::vector<std::uint32_t>& vertex, std::size_t c, HalfEdges& edges) {
  const Dart first = static_cast<Dart>(cx.face_begin[cx.cell_begin[c]]), end = static_cast<Dart>(cx.face_begin[cx.cell_begin[c + 1]]);
  edges.clear();
  for (Dart d = first; d < end; ++d) edges.emplace_back(vertex[d], vertex[m.link(1, d)], d);
  std::sort(edges.begin(), edges.end());
  for (std::size_t k = 0; k + 1 < edges.size(); ++k)
    if (std::get<0>(edges[k]) == std::get<0>(edges[k + 1]) && std::get<1>(edges[k]) == std::get<1>(edges[k + 1]))
      throw BuildError(
          fmt::format("cell {} traverses the edge {} -> {} twice (faces not oriented alike)", c, std::get<0>(edges[k]), std::get<1>(edges[k])),
          in_cell, c);
  for (const auto& [u, v, d] : edges) {
    const auto it = std::lower_bound(edges.begin(), edges.end(), std::tuple{v, u, Dart{0}});
    if (it == edges.end() || std::get<0>(*it) != v || std::get<1>(*it) != u)
      throw BuildError(fmt::format("cell {} is not closed: its edge {} -> {} has no face on the other side", c, u, v), in_cell, c);
    if (d < std::get<2>(*it)) m.sew(2, d, std::get<2>(*it));
  }
}

}  // namespace

GluedCells glue_cells(const CellComplex& cx) {
  const std::vector<std::uint32_t> cell_of = cx.face_cells();
  check_faces(cx, cell_of);
  GluedCells out;
  Map& m = out.map;
  m = Map(Model::open_omap(3), cx.vertices.size());
  out.vertex = cx.vertices;
  out.cell.resize(m.size());
  for (std::size_t f = 0; f < cx.faces(); ++f) {
    const Dart b = static_cast<Dart>(cx.face_begin[f]), e = static_cast<Dart>(cx.face_begin[f + 1]);
    for (Dart d = b; d < e; ++d) {
      m.sew(1, d, d + 1 < e ? d + 1 : b);
      out.cell[d] = cell_of[f];
    }
  }
  HalfEdges scratch;
  for (std::size_t c = 0; c < cx.cells(); ++c) sew_cell_edges(m, cx, out.vertex, c, scratch);
  // β3 across the faces two cells share: u -> v against v -> u.
  for (const auto& [a, b] : shared_faces(cx)) {
    const std::uint32_t ca = cell_of[a], cb = cell_of[b];
    if (ca == cb) throw BuildError(fmt::format("cell {} has the same face twice", ca), in_cell, ca);
    const Dart fa = static_cast<Dart>(cx.face_begin[a]), fb = static_cast<Dart>(cx.face_begin[b]);
    const std::size_t k = cx.face_begin[a + 1] - cx.face_begin[a];
    // Face b's dart from a's second vertex back to its first, then backwards.
    std::size_t y0 = 0;
    while (out.vertex[fb + y0] != out.vertex[fa + 1]) ++y0;
    for (std::size_t x = 0; x < k; ++x) {
      const Dart d = fa + static_cast<Dart>(x), e = fb + static_cast<Dart>((y0 + k - x) % k);
      if (out.vertex[m.link(1, e)] != out.vertex[d])
        throw BuildError(fmt::format("cells {} and {} traverse their shared face the same way (orientations differ)", ca, cb), in_cell, cb);
      m.sew(3, d, e);
    }
  }
  return out;
}

}  // namespace dartcheck
