#include "querymodify/modify.hpp"

#include <fmt/format.h>

#include <stdexcept>

#include "rewriting/derivation.hpp"

namespace dartcheck::querymodify {
namespace {

// Flags the darts and checks they are closed under β1 and β2.
std::vector<bool> volume_flags(const Map& m, const std::vector<Dart>& darts) {
  std::vector<bool> in(m.size(), false);
  for (Dart d : darts) {
    if (d >= m.size()) throw std::invalid_argument(fmt::format("dart {} is not in the map", d));
    in[d] = true;
  }
  for (Dart d : darts)
    for (Dim i : {1, 2})
      if (const Dart e = m.link(i, d); e != no_dart && !in[e])
        throw std::invalid_argument(fmt::format("darts {} and {} are {}-linked but only {} is listed: not whole volumes", d, e, i, d));
  return in;
}

Renumbering remove(Map& m, const std::vector<bool>& gone) {
  std::vector<Dart> holes;
  for (Dart d = 0; d < m.size(); ++d)
    if (gone[d]) {
      for (Dim i : m.model().dims) m.remove_link(i, d);
      holes.push_back(d);
    }
  return compact(m, std::move(holes));
}

}  // namespace

Renumbering delete_volumes(Map& m, const std::vector<Dart>& darts) {
  const auto in = volume_flags(m, darts);
  for (Dart d : darts)
    if (const Dart e = m.link(3, d); e != no_dart && !in[e]) m.remove_link(3, e);  // the kept side becomes 3-free
  return remove(m, in);
}

Renumbering merge_volumes(Map& m, const std::vector<Dart>& darts) {
  const auto in = volume_flags(m, darts);
  // A face between two merged volumes: its darts are 3-sewn inside the set.
  auto inner = [&](Dart d) {
    const Dart e = m.link(3, d);
    return e != no_dart && in[e];
  };
  std::vector<std::pair<Dart, Dart>> new_beta2;
  for (Dart x : darts) {
    if (inner(x)) continue;
    Dart y = m.link(2, x);
    for (std::size_t guard = 0; inner(y); ++guard) {
      if (guard > darts.size()) throw std::logic_error("turning around an edge did not leave the removed faces");
      y = m.link(2, m.link(3, y));
    }
    new_beta2.emplace_back(x, y);
  }
  for (const auto& [x, y] : new_beta2) m.set_link(2, x, y);
  std::vector<bool> gone(m.size(), false);
  for (Dart d : darts) gone[d] = inner(d);
  return remove(m, gone);
}

}  // namespace dartcheck::querymodify
