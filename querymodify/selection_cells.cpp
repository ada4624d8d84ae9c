#include "querymodify/selection_cells.hpp"

#include "core/error.hpp"

#include <stdexcept>

#include <fmt/format.h>

namespace dartcheck::querymodify {

std::vector<CellField> selection_fields(std::size_t tetrahedra, const std::vector<QueryMatch>& matches) {
  CellField match{"match", std::vector<double>(tetrahedra, -1), true};
  CellField query{"query", std::vector<double>(tetrahedra, -1), true};
  CellField count{"matches", std::vector<double>(tetrahedra, 0), true};
  std::vector<std::size_t> last(tetrahedra, matches.size());  // the match that counted a tetrahedron last
  for (std::size_t k = 0; k < matches.size(); ++k)
    for (Dart d : matches[k].darts) {
      const std::size_t t = d / 12;
      if (t >= tetrahedra) throw InternalError(fmt::format("dart {} of match {} is outside a map of {} tetrahedra", d, k, tetrahedra));
      if (last[t] == k) continue;  // one count per match
      last[t] = k;
      ++count.values[t];
      if (match.values[t] < 0) {
        match.values[t] = static_cast<double>(k);
        query.values[t] = matches[k].query;
      }
    }
  return {std::move(match), std::move(query), std::move(count)};
}

}  // namespace dartcheck::querymodify
