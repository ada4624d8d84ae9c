// Counts the query-modify tests derive by hand: 3-free darts and volumes.
#pragma once

#include "core/orbit.hpp"

namespace dartcheck::querymodify::test {

inline std::size_t free3(const Map& m) {
  std::size_t n = 0;
  for (Dart d = 0; d < m.size(); ++d) n += m.link(3, d) == no_dart;
  return n;
}

inline std::size_t volumes(const Map& m) {
  OrbitWalker w(m);
  return w.count_orbits(dims_generators({1, 2}));
}

}  // namespace dartcheck::querymodify::test
