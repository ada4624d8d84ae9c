#include "querymodify/cell_map.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <utility>

namespace dartcheck::querymodify {
namespace {

// A face of a cell, found again by its sorted vertex set.
struct FaceUse {
  std::vector<std::uint32_t> key;
  std::uint32_t cell;
  Dart first;  // the dart of the face's first edge
  bool operator<(const FaceUse& o) const { return key < o.key || (key == o.key && cell < o.cell); }
};

}  // namespace

CellMap build_cell_map(const std::vector<Polyhedron>& cells) {
  CellMap out;
  std::size_t darts = 0;
  for (std::size_t c = 0; c < cells.size(); ++c)
    for (const auto& f : cells[c]) {
      if (f.size() < 3) throw CellMapError(c, fmt::format("cell {} has a face of {} vertices (at least 3)", c, f.size()));
      darts += f.size();
    }
  Map& m = out.map;
  m = Map(Model::open_omap(3), darts);
  out.vertex.resize(darts);
  out.cell.resize(darts);
  std::vector<FaceUse> uses;
  Dart next = 0;
  for (std::size_t c = 0; c < cells.size(); ++c) {
    // β2: the dart u -> v of one face and v -> u of another, in this cell.
    std::map<std::pair<std::uint32_t, std::uint32_t>, Dart> edges;
    for (const auto& f : cells[c]) {
      const Dart first = next;
      for (std::size_t j = 0; j < f.size(); ++j) {
        const Dart d = next++;
        const std::uint32_t u = f[j], v = f[(j + 1) % f.size()];
        out.vertex[d] = u;
        out.cell[d] = static_cast<std::uint32_t>(c);
        m.sew(1, d, j + 1 < f.size() ? d + 1 : first);
        if (!edges.emplace(std::pair{u, v}, d).second)
          throw CellMapError(c, fmt::format("cell {} traverses the edge {} -> {} twice (faces not oriented alike)", c, u, v));
      }
      auto key = f;
      std::sort(key.begin(), key.end());
      if (std::adjacent_find(key.begin(), key.end()) != key.end()) throw CellMapError(c, fmt::format("a face of cell {} repeats a vertex", c));
      uses.push_back({std::move(key), static_cast<std::uint32_t>(c), first});
    }
    for (const auto& [uv, d] : edges) {
      const auto it = edges.find({uv.second, uv.first});
      if (it == edges.end())
        throw CellMapError(c, fmt::format("cell {} is not closed: its edge {} -> {} has no face on the other side", c, uv.first, uv.second));
      if (d < it->second) m.sew(2, d, it->second);
    }
  }
  // β3 across the faces two cells share: u -> v against v -> u.
  std::sort(uses.begin(), uses.end());
  for (std::size_t i = 0; i < uses.size();) {
    std::size_t j = i;
    while (j < uses.size() && uses[j].key == uses[i].key) ++j;
    if (j - i > 2) throw CellMapError(uses[i + 2].cell, fmt::format("a face of cell {} is shared by {} cells (at most 2)", uses[i + 2].cell, j - i));
    if (j - i == 2) {
      const FaceUse& a = uses[i];
      const FaceUse& b = uses[i + 1];
      if (a.cell == b.cell) throw CellMapError(a.cell, fmt::format("cell {} has the same face twice", a.cell));
      const std::size_t k = a.key.size();
      for (std::size_t x = 0; x < k; ++x) {
        const Dart d = a.first + static_cast<Dart>(x);
        const std::uint32_t u = out.vertex[d], v = out.vertex[m.link(1, d)];
        Dart e = no_dart;
        for (std::size_t y = 0; y < k; ++y) {
          const Dart f = b.first + static_cast<Dart>(y);
          if (out.vertex[f] == v && out.vertex[m.link(1, f)] == u) e = f;
        }
        if (e == no_dart)
          throw CellMapError(b.cell, fmt::format("cells {} and {} traverse their shared face the same way (orientations differ)", a.cell, b.cell));
        m.sew(3, d, e);
      }
    }
    i = j;
  }
  return out;
}

}  // namespace dartcheck::querymodify
