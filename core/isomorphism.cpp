#include "core/isomorphism.hpp"

#include <algorithm>

namespace dartcheck {

std::vector<std::int64_t> component_code(const Map& map, Dart start) {
  // Discovery numbers; the BFS follows every slot (links, then recorded
  // predecessors) in a fixed order, so the numbering depends only on the
  // structure seen from `start`.
  std::vector<std::int64_t> code;
  std::vector<Dart> order{start};
  std::vector<std::int64_t> number(map.size(), -1);
  number[start] = 0;
  const auto& dims = map.model().dims;
  for (std::size_t k = 0; k < order.size(); ++k) {
    const Dart d = order[k];
    for (Dim i : dims)
      for (const Dart e : {map.link(i, d), map.inverse_link(i, d)}) {
        if (e == no_dart) {
          code.push_back(-1);
          continue;
        }
        if (number[e] < 0) {
          number[e] = static_cast<std::int64_t>(order.size());
          order.push_back(e);
        }
        code.push_back(number[e]);
      }
  }
  return code;
}

namespace {

// The minimal code of every connected component (components found by the
// same BFS from their smallest dart).
std::vector<std::vector<std::int64_t>> canonical_components(const Map& m) {
  std::vector<bool> seen(m.size(), false);
  std::vector<std::vector<std::int64_t>> result;
  for (Dart d = 0; d < m.size(); ++d) {
    if (seen[d]) continue;
    // Collect the component of d (links and predecessors, both ways).
    std::vector<Dart> comp{d};
    seen[d] = true;
    for (std::size_t k = 0; k < comp.size(); ++k)
      for (Dim i : m.model().dims)
        for (const Dart e : {m.link(i, comp[k]), m.inverse_link(i, comp[k])})
          if (e != no_dart && !seen[e]) {
            seen[e] = true;
            comp.push_back(e);
          }
    std::vector<std::int64_t> best;
    for (Dart s : comp) {
      auto code = component_code(m, s);
      if (best.empty() || code < best) best = std::move(code);
    }
    result.push_back(std::move(best));
  }
  std::sort(result.begin(), result.end());
  return result;
}

}  // namespace

bool isomorphic(const Map& a, const Map& b) {
  return a.model() == b.model() && a.size() == b.size() && canonical_components(a) == canonical_components(b);
}

}  // namespace dartcheck
