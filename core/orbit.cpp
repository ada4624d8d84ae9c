#include "core/orbit.hpp"

#include <array>

namespace dartcheck {

std::vector<OrbitWord> dims_generators(const std::vector<Dim>& dims) {
  std::vector<OrbitWord> g;
  for (Dim i : dims) g.push_back({i});
  return g;
}

std::vector<OrbitWord> cell_generators(const Model& model, int k) {
  if (!model.is_generalized() && k == 0) {
    std::vector<OrbitWord> g;
    for (Dim j : model.dims)
      if (j >= 2) g.push_back({j, 1});
    return g;
  }
  std::vector<Dim> others;
  for (Dim i : model.dims)
    if (i != k) others.push_back(i);
  return dims_generators(others);
}

OrbitWalker::OrbitWalker(const Map& map) : map_(map), marks_((map.size() + 63) / 64, 0) {}

void OrbitWalker::traverse(Dart d, std::span<const OrbitWord> generators) {
  fit();
  const std::size_t first = visited_.size();
  visited_.push_back(d);
  mark(d);
  // G-map orbits (one letter per generator, at most 4) read the links
  // directly: the common case of every embedding and cell orbit.
  std::array<Dim, 4> dims{};
  bool letters = generators.size() <= dims.size();
  for (std::size_t k = 0; letters && k < generators.size(); ++k) {
    letters = generators[k].size() == 1;
    if (letters) dims[k] = generators[k][0];
  }
  if (letters) {
    const std::size_t n = generators.size();
    for (std::size_t k = first; k < visited_.size(); ++k) {
      const Dart x = visited_[k];
      for (std::size_t j = 0; j < n; ++j) {
        const Dart y = map_.link(dims[j], x);
        if (y != no_dart && !marked(y)) {
          mark(y);
          visited_.push_back(y);
        }
      }
    }
    return;
  }
  for (std::size_t k = first; k < visited_.size(); ++k) {
    const Dart x = visited_[k];
    for (const OrbitWord& w : generators) {
      const Dart y = follow(map_, x, w);
      if (y != no_dart && !marked(y)) {
        mark(y);
        visited_.push_back(y);
      }
    }
  }
}

const std::vector<Dart>& OrbitWalker::orbit(Dart d, std::span<const OrbitWord> generators) {
  visited_.clear();
  traverse(d, generators);
  for (Dart x : visited_) unmark(x);
  return visited_;
}

std::size_t OrbitWalker::count_orbits(std::span<const OrbitWord> generators) {
  std::size_t count = 0;
  fit();
  visited_.clear();
  for (Dart d = 0; d < map_.size(); ++d)
    if (!marked(d)) {
      ++count;
      traverse(d, generators);
    }
  for (Dart x : visited_) unmark(x);
  visited_.clear();
  return count;
}

OrbitPartition partition_orbits(const Map& map, std::span<const OrbitWord> generators) {
  constexpr std::uint32_t unset = 0xffffffffU;
  OrbitPartition p{std::vector<std::uint32_t>(map.size(), unset), {}};
  OrbitWalker walker(map);
  for (Dart d = 0; d < map.size(); ++d) {
    if (p.of[d] != unset) continue;
    const auto k = static_cast<std::uint32_t>(p.first.size());
    for (Dart e : walker.orbit(d, generators)) p.of[e] = k;
    p.first.push_back(d);
  }
  return p;
}

long long CellCounts::euler() const {
  long long chi = 0;
  for (std::size_t k = 0; k < cells.size(); ++k) chi += (k % 2 == 0 ? 1 : -1) * static_cast<long long>(cells[k]);
  return chi;
}

std::vector<LinkCount> count_links(const Map& map) {
  std::vector<LinkCount> out;
  for (Dim i : map.model().dims) {
    LinkCount c{i, 0, 0};
    for (Dart d = 0; d < map.size(); ++d) {
      const Dart e = map.link(i, d);
      if (e == no_dart) continue;
      ++c.arcs;
      c.loops += e == d;
    }
    out.push_back(c);
  }
  return out;
}

CellCounts count_cells(const Map& map) {
  CellCounts c;
  OrbitWalker walker(map);
  for (int k = 0; k <= map.model().dimension(); ++k) c.cells.push_back(walker.count_orbits(cell_generators(map.model(), k)));
  c.components = walker.count_orbits(dims_generators(map.model().dims));
  return c;
}

}  // namespace dartcheck
