// Shared by the inference tests: maps, κ by orbit association, and one
// call that folds, builds, checks and verifies.
#pragma once

#include <string>
#include <vector>

#include "analysis/map_sources.hpp"
#include "core/orbit.hpp"
#include "generators/shapes.hpp"
#include "inference/infer.hpp"
#include "io/catalog.hpp"
#include "rewriting/application.hpp"

namespace dartcheck::inference::test {

inline const Catalog& seed_catalog() {
  static const Catalog c = read_catalog(std::string(DARTCHECK_SOURCE_DIR) + "/catalogs/seed-operations.yaml");
  return c;
}

inline Map shape(const std::string& spec, int n = 2) { return build_shape(Model::gmap(n), parse_shape(spec)); }

/// The connected component of `start`, renumbered in BFS order.
inline Map component(const Map& g, Dart start, Dart* new_start = nullptr) {
  std::vector<Dart> order{start}, number(g.size(), no_dart);
  number[start] = 0;
  for (std::size_t k = 0; k < order.size(); ++k)
    for (Dim i : g.model().dims)
      if (const Dart y = g.link(i, order[k]); y != no_dart && number[y] == no_dart) {
        number[y] = static_cast<Dart>(order.size());
        order.push_back(y);
      }
  Map out(g.model(), order.size());
  for (Dart x : order)
    for (Dim i : g.model().dims)
      if (const Dart y = g.link(i, x); y != no_dart) out.set_link(i, number[x], number[y]);
  if (new_start) *new_start = 0;
  return out;
}

/// The catalog scheme `rule` applied to g at `hook` (it must apply).
inline Map applied(const Operation& op, Map g, Dart hook) {
  const Dart hooks[] = {hook};
  auto r = Applier(op).apply(g, hooks);
  if (!r.ok()) throw std::runtime_error(r.why);
  return g;
}

/// Darts of the vertex walk (α1α0)^k(0) of a polygon: the k-th corner dart.
inline Dart corner(const Map& g, int k) {
  Dart d = 0;
  for (int s = 0; s < k; ++s) d = g.link(1, g.link(0, d));
  return d;
}

}  // namespace dartcheck::inference::test
