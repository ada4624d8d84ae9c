#include "querymodify/map_checks.hpp"

#include <algorithm>

namespace dartcheck::querymodify {

ValidityReport check_3map(const Map& m) {
  ValidityReport r = check_map(m);
  const Model& model = m.model();
  auto free = [&](Dim j, Dart d) { return d == no_dart || m.link(j, d) == no_dart; };
  std::erase_if(r.violations, [&](const Violation& v) {
    if (v.constraint != Constraint::cycle || v.j < 0 || !has_dim(model.partial, v.j)) return false;
    const Dart d = static_cast<Dart>(v.element);
    return free(v.j, d) && free(v.j, m.link(v.i, d));
  });
  return r;
}

}  // namespace dartcheck::querymodify
