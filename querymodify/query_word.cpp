#include "querymodify/query_word.hpp"

#include "core/error.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace dartcheck::querymodify {

bool is_free(const Map& m, Dim i, Dart d) {
  const Dart e = m.link(i, d);
  return e == no_dart || (e == d && !m.model().is_oriented(i));
}

Labeling bfs_labeling(const Map& m, Dart start) {
  Labeling l;
  l.label.assign(m.size(), 0);
  l.darts.push_back(start);
  l.label[start] = 1;
  for (std::size_t k = 0; k < l.darts.size(); ++k)
    for (Dim i : m.model().dims) {
      if (is_free(m, i, l.darts[k])) continue;
      const Dart e = m.link(i, l.darts[k]);
      if (l.label[e] == 0) {
        l.darts.push_back(e);
        l.label[e] = static_cast<std::uint32_t>(l.darts.size());
      }
    }
  return l;
}

std::vector<std::uint32_t> word(const Map& m, const Labeling& l) {
  std::vector<std::uint32_t> w;
  w.reserve(l.darts.size() * m.model().dims.size());
  for (Dart d : l.darts)
    for (Dim i : m.model().dims) w.push_back(is_free(m, i, d) ? 0 : l.label[m.link(i, d)]);
  return w;
}

const char* boundary_symbol(BoundaryCondition c) {
  switch (c) {
    case BoundaryCondition::any:
      return "*";
    case BoundaryCondition::boundary:
      return "ε";
    case BoundaryCondition::interior:
      return "ε̄";
    case BoundaryCondition::no_connection:
      return "↔";
  }
  return "?";
}

QueryWord query_word(const Map& query, Dart start, BoundaryCondition free_links, const std::vector<BoundaryOverride>& overrides) {
  const Labeling l = bfs_labeling(query, start);
  if (l.darts.size() != query.size())
    throw ValueError(fmt::format("the query is not connected: {} of its {} darts are reached from dart {}", l.darts.size(), query.size(), start));
  QueryWord w;
  w.dims = query.model().dims;
  w.darts = l.darts.size();
  w.letters = word(query, l);
  for (std::size_t k = 0; k < w.darts; ++k)
    for (std::size_t i = 0; i < w.dims.size(); ++i)
      if (is_free(query, w.dims[i], l.darts[k])) w.letters[k * w.dims.size() + i] = static_cast<std::uint32_t>(free_links);
  for (const auto& o : overrides) {
    std::size_t i = 0;
    while (i < w.dims.size() && w.dims[i] != o.dim) ++i;
    if (o.dart >= query.size() || i == w.dims.size() || !is_free(query, o.dim, o.dart))
      throw ValueError(fmt::format("boundary condition on dart {} dimension {}: not a free link of the query", o.dart, o.dim));
    w.letters[(l.label[o.dart] - 1) * w.dims.size() + i] = static_cast<std::uint32_t>(o.condition);
  }
  return w;
}

std::string word_text(const QueryWord& w) {
  std::string s;
  for (std::size_t k = 0; k < w.darts; ++k) {
    if (k) s += " | ";
    for (std::size_t i = 0; i < w.dims.size(); ++i) {
      const auto x = w.letters[k * w.dims.size() + i];
      s += fmt::format("{}{}", i ? " " : "", is_boundary_condition(x) ? boundary_symbol(static_cast<BoundaryCondition>(x)) : std::to_string(x));
    }
  }
  return s;
}

}  // namespace dartcheck::querymodify
